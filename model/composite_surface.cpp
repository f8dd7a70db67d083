#include "composite_surface.h"

#include "model_error.h"

#include <OpenMesh/Core/Mesh/PolyMesh_ArrayKernelT.hh>
#include <OpenMesh/Core/System/omstream.hh>

#include <algorithm>
#include <numeric>
#include <set>
#include <sstream>

namespace devsurf::model {

using Mesh = OpenMesh::PolyMesh_ArrayKernelT<>;

const char* faceTypeName(FaceType type) {
    switch (type) {
    case FaceType::StripSRSR:
        return "SRSR strip";
    case FaceType::StripSRS:
        return "SRS strip";
    case FaceType::ConeSRR:
        return "SRR cone";
    case FaceType::Planar:
        return "planar polygon";
    case FaceType::Invalid:
        break;
    }
    return "invalid face";
}

const char* creaseConditionName(CreaseCondition condition) {
    switch (condition) {
    case CreaseCondition::None:
        return "none";
    case CreaseCondition::CurvedFold:
        return "curved-fold";
    case CreaseCondition::Geodesic:
        return "geodesic";
    case CreaseCondition::Straight:
        return "straight";
    }
    return "none";
}

// The OpenMesh mirror of the canonical face loops: answers adjacency questions and refuses
// non-manifold configurations.
struct CompositeSurface::Connectivity {
    Mesh mesh;
    OpenMesh::VPropHandleT<VertexId> vertexId;
    OpenMesh::EPropHandleT<EdgeId> edgeId;
    OpenMesh::FPropHandleT<FaceId> faceId;
    std::map<VertexId, Mesh::VertexHandle> vertexHandle;

    Connectivity() {
        // Our own messages name the entity; OpenMesh's log would only add noise on stderr. Its
        // log is one global stream: switch it off once, not from every thread that builds a
        // surface (the solver worker does, beside the GUI thread).
        static const bool quiet = [] {
            omerr().disable();
            return true;
        }();
        (void)quiet;
        mesh.add_property(vertexId);
        mesh.add_property(edgeId);
        mesh.add_property(faceId);
    }
};

CompositeSurface::CompositeSurface() : m_connectivity(std::make_unique<Connectivity>()) {}
CompositeSurface::~CompositeSurface() = default;

CompositeSurface::CompositeSurface(const CompositeSurface& other)
    : m_name(other.m_name), m_id(other.m_id), m_vertices(other.m_vertices), m_edges(other.m_edges),
      m_faces(other.m_faces), m_pinned(other.m_pinned),
      m_keepsDevelopment(other.m_keepsDevelopment), m_development(other.m_development),
      m_sheetDomain(other.m_sheetDomain), m_edgeByVertices(other.m_edgeByVertices),
      m_nextVertexId(other.m_nextVertexId), m_nextEdgeId(other.m_nextEdgeId),
      m_nextFaceId(other.m_nextFaceId),
      m_connectivity(std::make_unique<Connectivity>(*other.m_connectivity)) {}

CompositeSurface& CompositeSurface::operator=(const CompositeSurface& other) {
    if (this != &other) {
        CompositeSurface copy(other);
        *this = std::move(copy);
    }
    return *this;
}

CompositeSurface::CompositeSurface(CompositeSurface&& other) noexcept = default;
CompositeSurface& CompositeSurface::operator=(CompositeSurface&& other) noexcept = default;

namespace {

std::pair<VertexId, VertexId> edgeKey(VertexId a, VertexId b) {
    return a < b ? std::make_pair(a, b) : std::make_pair(b, a);
}

Problem noEdgeBetween(VertexId a, VertexId b) {
    Problem problem = vertexProblem(ProblemCode::NoEdgeBetween, a);
    problem.otherVertex = b;
    return problem;
}

} // namespace

VertexId CompositeSurface::addVertex(const Vec3& position) {
    const VertexId id = m_nextVertexId;
    addVertexWithId(id, position);
    return id;
}

void CompositeSurface::addVertexWithId(VertexId id, const Vec3& position) {
    m_development.clear(); // the samples' indexing changes
    if (id == kInvalidId || m_vertices.count(id) != 0) {
        throw ModelError(elementProblem(ProblemCode::IdUsedTwice, Element::Vertex, id));
    }
    m_vertices.emplace(id, position);
    auto handle = m_connectivity->mesh.add_vertex(Mesh::Point(0, 0, 0));
    m_connectivity->mesh.property(m_connectivity->vertexId, handle) = id;
    m_connectivity->vertexHandle.emplace(id, handle);
    m_nextVertexId = std::max(m_nextVertexId, id + 1);
}

void CompositeSurface::addEdgeWithId(EdgeId id, const EdgeRecord& record) {
    m_development.clear(); // the samples' indexing changes
    if (id == kInvalidId || m_edges.count(id) != 0) {
        throw ModelError(elementProblem(ProblemCode::IdUsedTwice, Element::Edge, id));
    }
    if (!hasVertex(record.from) || !hasVertex(record.to) || record.from == record.to) {
        throw ModelError(edgeProblem(ProblemCode::EdgeEndsInvalid, id));
    }
    const auto key = edgeKey(record.from, record.to);
    if (m_edgeByVertices.count(key) != 0) {
        Problem problem = edgeProblem(ProblemCode::DuplicateEdge, id);
        problem.vertex = record.from;
        problem.otherVertex = record.to;
        throw ModelError(problem);
    }
    m_edges.emplace(id, record);
    m_edgeByVertices.emplace(key, id);
    m_nextEdgeId = std::max(m_nextEdgeId, id + 1);
}

FaceId CompositeSurface::addFace(const std::vector<VertexId>& loop) {
    const FaceId id = m_nextFaceId;
    addFaceWithId(id, loop);
    return id;
}

void CompositeSurface::addFaceWithId(FaceId id, const std::vector<VertexId>& loop) {
    m_development.clear(); // the samples' indexing changes
    if (id == kInvalidId || m_faces.count(id) != 0) {
        throw ModelError(elementProblem(ProblemCode::IdUsedTwice, Element::Face, id));
    }
    insertFace(id, loop);
    m_nextFaceId = std::max(m_nextFaceId, id + 1);
}

void CompositeSurface::insertFace(FaceId id, const std::vector<VertexId>& loop) {
    if (loop.size() < 3) {
        throw ModelError(faceProblem(ProblemCode::FaceTooFewVertices, id));
    }
    std::set<VertexId> distinct(loop.begin(), loop.end());
    if (distinct.size() != loop.size()) {
        throw ModelError(faceProblem(ProblemCode::FaceRepeatsVertex, id));
    }
    Connectivity& c = *m_connectivity;
    std::vector<Mesh::VertexHandle> handles;
    handles.reserve(loop.size());
    for (VertexId v : loop) {
        auto it = c.vertexHandle.find(v);
        if (it == c.vertexHandle.end()) {
            Problem problem = faceProblem(ProblemCode::FaceMissingVertex, id);
            problem.vertex = v;
            throw ModelError(problem);
        }
        handles.push_back(it->second);
    }
    for (std::size_t i = 0; i < loop.size(); ++i) {
        const auto from = handles[i];
        const auto to = handles[(i + 1) % loop.size()];
        const auto halfedge = c.mesh.find_halfedge(from, to);
        if (halfedge.is_valid() && !c.mesh.is_boundary(halfedge)) {
            Problem problem = faceProblem(ProblemCode::FaceOrientation, id);
            problem.vertex = loop[i];
            problem.otherVertex = loop[(i + 1) % loop.size()];
            throw ModelError(problem);
        }
    }
    const auto faceHandle = c.mesh.add_face(handles);
    if (!faceHandle.is_valid()) {
        throw ModelError(faceProblem(ProblemCode::FaceNonManifold, id));
    }
    c.mesh.property(c.faceId, faceHandle) = id;
    for (std::size_t i = 0; i < loop.size(); ++i) {
        const VertexId a = loop[i];
        const VertexId b = loop[(i + 1) % loop.size()];
        auto key = edgeKey(a, b);
        auto it = m_edgeByVertices.find(key);
        EdgeId edgeId;
        if (it == m_edgeByVertices.end()) {
            edgeId = m_nextEdgeId++;
            EdgeRecord record;
            record.from = a;
            record.to = b;
            m_edges.emplace(edgeId, record);
            m_edgeByVertices.emplace(key, edgeId);
        } else {
            edgeId = it->second;
        }
        const auto halfedge = c.mesh.find_halfedge(handles[i], handles[(i + 1) % loop.size()]);
        c.mesh.property(c.edgeId, c.mesh.edge_handle(halfedge)) = edgeId;
    }
    m_faces.emplace(id, loop);
}

void CompositeSurface::setNextIds(VertexId vertex, EdgeId edge, FaceId face) {
    m_nextVertexId = std::max(m_nextVertexId, vertex);
    m_nextEdgeId = std::max(m_nextEdgeId, edge);
    m_nextFaceId = std::max(m_nextFaceId, face);
}

EdgeRecord& CompositeSurface::mutableEdge(EdgeId id) {
    auto it = m_edges.find(id);
    if (it == m_edges.end()) {
        throw ModelError(elementProblem(ProblemCode::Missing, Element::Edge, id));
    }
    return it->second;
}

EdgeId CompositeSurface::setSpline(VertexId a, VertexId b, const SplineSpace& space,
                                   std::vector<Vec3> controlPoints) {
    m_development.clear(); // the samples' indexing changes
    const EdgeId id = edgeBetween(a, b);
    if (id == kInvalidId) {
        throw ModelError(noEdgeBetween(a, b));
    }
    EdgeRecord& record = mutableEdge(id);
    record.from = a;
    record.to = b;
    record.label = EdgeLabel::Spline;
    record.space = space;
    record.controlPoints = std::move(controlPoints);
    record.smooth = false;
    return id;
}

void CompositeSurface::setRuling(EdgeId edge) {
    m_development.clear(); // the samples' indexing changes
    EdgeRecord& record = mutableEdge(edge);
    record.label = EdgeLabel::Ruling;
    record.space = SplineSpace{};
    record.controlPoints.clear();
    record.condition = CreaseCondition::None;
    record.smooth = false;
}

void CompositeSurface::setCreaseCondition(EdgeId edge, CreaseCondition condition) {
    mutableEdge(edge).condition = condition;
}

void CompositeSurface::setSmooth(EdgeId edge, bool smooth) {
    EdgeRecord& record = mutableEdge(edge);
    if (record.isSpline() && smooth) {
        throw ModelError(edgeProblem(ProblemCode::CurveCannotBeSmooth, edge));
    }
    record.smooth = smooth;
}

void CompositeSurface::reverseEdge(EdgeId edge) {
    m_development.clear(); // the samples' indexing changes
    EdgeRecord& record = mutableEdge(edge);
    std::swap(record.from, record.to);
    std::reverse(record.controlPoints.begin(), record.controlPoints.end());
}

void CompositeSurface::moveVertex(VertexId vertex, const Vec3& position) {
    auto it = m_vertices.find(vertex);
    if (it == m_vertices.end()) {
        throw ModelError(elementProblem(ProblemCode::Missing, Element::Vertex, vertex));
    }
    it->second = position;
    for (auto& [id, record] : m_edges) {
        if (!record.isSpline() || record.controlPoints.empty()) {
            continue;
        }
        if (record.from == vertex) {
            record.controlPoints.front() = position;
        }
        if (record.to == vertex) {
            record.controlPoints.back() = position;
        }
    }
}

void CompositeSurface::moveVertices(const std::vector<std::pair<VertexId, Vec3>>& moves) {
    std::map<VertexId, Vec3> moved;
    for (const auto& [vertex, position] : moves) {
        if (m_vertices.find(vertex) == m_vertices.end()) {
            throw ModelError(elementProblem(ProblemCode::Missing, Element::Vertex, vertex));
        }
        moved[vertex] = position;
    }
    for (const auto& [vertex, position] : moved) {
        m_vertices.find(vertex)->second = position;
    }
    for (auto& [id, record] : m_edges) {
        if (!record.isSpline() || record.controlPoints.empty()) {
            continue;
        }
        if (const auto from = moved.find(record.from); from != moved.end()) {
            record.controlPoints.front() = from->second;
        }
        if (const auto to = moved.find(record.to); to != moved.end()) {
            record.controlPoints.back() = to->second;
        }
    }
}

void CompositeSurface::setControlPoints(EdgeId edge, std::vector<Vec3> controlPoints) {
    mutableEdge(edge).controlPoints = std::move(controlPoints);
}

void CompositeSurface::setKeepsDevelopment(bool keep) {
    m_keepsDevelopment = keep;
    if (!keep) {
        m_development.clear();
        m_sheetDomain = SheetDomain(); // no sheet: nothing to confine
    }
}

void CompositeSurface::setPinned(VertexId vertex, bool pinned) {
    if (!hasVertex(vertex)) {
        throw ModelError(elementProblem(ProblemCode::Missing, Element::Vertex, vertex));
    }
    if (pinned) {
        m_pinned.insert(vertex);
    } else {
        m_pinned.erase(vertex);
    }
}

const Vec3& CompositeSurface::position(VertexId id) const {
    auto it = m_vertices.find(id);
    if (it == m_vertices.end()) {
        throw ModelError(elementProblem(ProblemCode::Missing, Element::Vertex, id));
    }
    return it->second;
}

const EdgeRecord& CompositeSurface::edge(EdgeId id) const {
    auto it = m_edges.find(id);
    if (it == m_edges.end()) {
        throw ModelError(elementProblem(ProblemCode::Missing, Element::Edge, id));
    }
    return it->second;
}

const std::vector<VertexId>& CompositeSurface::faceLoop(FaceId id) const {
    auto it = m_faces.find(id);
    if (it == m_faces.end()) {
        throw ModelError(elementProblem(ProblemCode::Missing, Element::Face, id));
    }
    return it->second;
}

EdgeId CompositeSurface::edgeBetween(VertexId a, VertexId b) const {
    auto it = m_edgeByVertices.find(edgeKey(a, b));
    return it == m_edgeByVertices.end() ? kInvalidId : it->second;
}

std::vector<FaceId> CompositeSurface::facesOfEdge(EdgeId edgeId) const {
    const EdgeRecord& record = edge(edgeId);
    const Connectivity& c = *m_connectivity;
    std::vector<FaceId> result;
    const auto from = c.vertexHandle.find(record.from);
    const auto to = c.vertexHandle.find(record.to);
    if (from == c.vertexHandle.end() || to == c.vertexHandle.end()) {
        return result;
    }
    const auto halfedge = c.mesh.find_halfedge(from->second, to->second);
    if (!halfedge.is_valid()) {
        return result;
    }
    for (auto h : {halfedge, c.mesh.opposite_halfedge_handle(halfedge)}) {
        const auto face = c.mesh.face_handle(h);
        if (face.is_valid()) {
            result.push_back(c.mesh.property(c.faceId, face));
        }
    }
    std::sort(result.begin(), result.end());
    return result;
}

std::vector<EdgeId> CompositeSurface::faceEdges(FaceId face) const {
    const auto& loop = faceLoop(face);
    std::vector<EdgeId> result;
    result.reserve(loop.size());
    for (std::size_t i = 0; i < loop.size(); ++i) {
        result.push_back(edgeBetween(loop[i], loop[(i + 1) % loop.size()]));
    }
    return result;
}

std::vector<Vec3> CompositeSurface::controlPointsFrom(VertexId a, VertexId b) const {
    const EdgeId id = edgeBetween(a, b);
    if (id == kInvalidId) {
        throw ModelError(noEdgeBetween(a, b));
    }
    const EdgeRecord& record = edge(id);
    std::vector<Vec3> points = record.controlPoints;
    if (record.from != a) {
        std::reverse(points.begin(), points.end());
    }
    return points;
}

std::string CompositeSurface::labelString(FaceId face) const {
    std::string labels;
    for (EdgeId e : faceEdges(face)) {
        labels += (e != kInvalidId && edge(e).isSpline()) ? 'S' : 'R';
    }
    return labels;
}

FaceType CompositeSurface::faceType(FaceId face) const {
    const std::string labels = labelString(face);
    const auto spline = static_cast<std::size_t>(std::count(labels.begin(), labels.end(), 'S'));
    if (spline == 0) {
        return FaceType::Planar;
    }
    if (labels.size() == 3) {
        if (spline == 2) {
            return FaceType::StripSRS;
        }
        if (spline == 1) {
            return FaceType::ConeSRR;
        }
        return FaceType::Invalid;
    }
    if (labels.size() == 4 && spline == 2 && labels[0] == labels[2] && labels[1] == labels[3]) {
        return FaceType::StripSRSR;
    }
    return FaceType::Invalid;
}

std::vector<std::vector<EdgeId>> CompositeSurface::splineClasses() const {
    std::map<EdgeId, EdgeId> parent;
    for (const auto& [id, record] : m_edges) {
        if (record.isSpline()) {
            parent[id] = id;
        }
    }
    auto find = [&parent](EdgeId e) {
        while (parent[e] != e) {
            parent[e] = parent[parent[e]];
            e = parent[e];
        }
        return e;
    };
    for (const auto& [faceId, loop] : m_faces) {
        EdgeId first = kInvalidId;
        for (EdgeId e : faceEdges(faceId)) {
            if (e == kInvalidId || parent.count(e) == 0) {
                continue;
            }
            if (first == kInvalidId) {
                first = e;
            } else {
                const EdgeId ra = find(first);
                const EdgeId rb = find(e);
                parent[std::max(ra, rb)] = std::min(ra, rb);
            }
        }
    }
    std::map<EdgeId, std::vector<EdgeId>> byRoot;
    for (const auto& entry : parent) {
        byRoot[find(entry.first)].push_back(entry.first);
    }
    std::vector<std::vector<EdgeId>> classes;
    for (auto& entry : byRoot) {
        classes.push_back(std::move(entry.second));
    }
    return classes;
}

std::size_t CompositeSurface::controlPointCount() const {
    std::size_t count = m_vertices.size();
    for (const auto& [id, record] : m_edges) {
        if (record.isSpline() && record.controlPoints.size() >= 2) {
            count += record.controlPoints.size() - 2;
        }
    }
    return count;
}

bool CompositeSurface::operator==(const CompositeSurface& other) const {
    auto sameEdges = [](const EdgeRecord& a, const EdgeRecord& b) {
        return a.from == b.from && a.to == b.to && a.label == b.label && a.space == b.space &&
               a.controlPoints == b.controlPoints && a.condition == b.condition &&
               a.smooth == b.smooth;
    };
    return m_name == other.m_name && m_id == other.m_id && m_vertices == other.m_vertices &&
           m_faces == other.m_faces && m_nextVertexId == other.m_nextVertexId &&
           m_nextEdgeId == other.m_nextEdgeId && m_nextFaceId == other.m_nextFaceId &&
           m_pinned == other.m_pinned && m_keepsDevelopment == other.m_keepsDevelopment &&
           m_development == other.m_development && m_sheetDomain == other.m_sheetDomain &&
           std::equal(m_edges.begin(), m_edges.end(), other.m_edges.begin(), other.m_edges.end(),
                      [&](const auto& a, const auto& b) {
                          return a.first == b.first && sameEdges(a.second, b.second);
                      });
}

} // namespace devsurf::model
