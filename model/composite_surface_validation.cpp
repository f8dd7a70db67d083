#include "composite_surface.h"
#include "geometry_checks.h"
#include "sampled_mesh.h"

#include <algorithm>
#include <cmath>

#include <set>

// CompositeSurface::validate(): every invariant of a design, checked at once (a damaged file,
// a bug in an edit), apart from the structure and edits in composite_surface.cpp.
namespace devsurf::model {

std::vector<Problem> CompositeSurface::validate() const {
    std::vector<Problem> problems;
    if (m_faces.empty()) {
        problems.push_back(problemOf(ProblemCode::NoFaces));
    }
    std::set<VertexId> usedVertices;
    std::set<EdgeId> usedEdges;
    for (const auto& [faceId, loop] : m_faces) {
        usedVertices.insert(loop.begin(), loop.end());
        for (EdgeId e : faceEdges(faceId)) {
            usedEdges.insert(e);
        }
    }
    for (const auto& [id, p] : m_vertices) {
        if (usedVertices.count(id) == 0) {
            problems.push_back(elementProblem(ProblemCode::Unused, Element::Vertex, id));
        }
        if (id >= m_nextVertexId) {
            problems.push_back(elementProblem(ProblemCode::BeyondIdCounter, Element::Vertex, id));
        }
    }
    for (const auto& [id, record] : m_edges) {
        if (usedEdges.count(id) == 0) {
            problems.push_back(elementProblem(ProblemCode::Unused, Element::Edge, id));
        }
        if (id >= m_nextEdgeId) {
            problems.push_back(elementProblem(ProblemCode::BeyondIdCounter, Element::Edge, id));
        }
        if (record.label != EdgeLabel::Spline) {
            if (!record.controlPoints.empty() || record.condition != CreaseCondition::None) {
                problems.push_back(edgeProblem(ProblemCode::RulingWithSplineData, id));
            }
            if (record.smooth && facesOfEdge(id).size() != 2) {
                problems.push_back(edgeProblem(ProblemCode::SmoothNotShared, id));
            }
            continue;
        }
        if (record.smooth) {
            problems.push_back(edgeProblem(ProblemCode::CurveMarkedSmooth, id));
        }
        if (!record.space.isValid()) {
            Problem problem = edgeProblem(ProblemCode::InvalidSplineSpace, id);
            problem.space = record.space;
            problems.push_back(problem);
            continue;
        }
        const auto expected = static_cast<std::size_t>(record.space.controlPointCount(false));
        if (record.controlPoints.size() != expected) {
            Problem problem = edgeProblem(ProblemCode::ControlPointCount, id);
            problem.count = static_cast<long long>(record.controlPoints.size());
            problem.expected = static_cast<long long>(expected);
            problem.space = record.space;
            problems.push_back(problem);
            continue;
        }
        bool finite = true;
        for (const Vec3& p : record.controlPoints) {
            finite = finite && p.isFinite();
        }
        if (!finite) {
            problems.push_back(edgeProblem(ProblemCode::ControlPointNotFinite, id));
        }
        auto from = m_vertices.find(record.from);
        auto to = m_vertices.find(record.to);
        if (from != m_vertices.end() && record.controlPoints.front() != from->second) {
            Problem problem = edgeProblem(ProblemCode::CurveNotAtVertex, id);
            problem.vertex = record.from;
            problems.push_back(problem);
        }
        if (to != m_vertices.end() && record.controlPoints.back() != to->second) {
            Problem problem = edgeProblem(ProblemCode::CurveNotAtVertex, id);
            problem.vertex = record.to;
            problem.count = 1;
            problems.push_back(problem);
        }
        const auto faces = facesOfEdge(id);
        if (record.condition != CreaseCondition::None && faces.size() != 2) {
            problems.push_back(edgeProblem(ProblemCode::ConditionNotShared, id));
        }
    }
    for (const auto& [faceId, loop] : m_faces) {
        if (faceType(faceId) == FaceType::Invalid) {
            Problem problem = faceProblem(ProblemCode::InvalidFaceLabel, faceId);
            problem.name = labelString(faceId);
            problems.push_back(problem);
        }
        if (faceId >= m_nextFaceId) {
            problems.push_back(elementProblem(ProblemCode::BeyondIdCounter, Element::Face, faceId));
        }
    }
    for (const auto& cls : splineClasses()) {
        const SplineSpace& space = m_edges.at(cls.front()).space;
        for (EdgeId e : cls) {
            const SplineSpace& other = m_edges.at(e).space;
            if (other != space) {
                Problem problem = edgeProblem(ProblemCode::SplineSpacesDiffer, cls.front());
                problem.otherEdge = e;
                problem.space = space;
                problem.otherSpace = other;
                problems.push_back(problem);
                break;
            }
        }
    }
    if (!m_development.empty()) {
        const std::size_t expected = sampledVertexCount(*this, kDevelopmentSamplesPerInterval);
        if (m_development.size() != expected) {
            Problem problem = problemOf(ProblemCode::DevelopmentSize);
            problem.count = static_cast<long long>(m_development.size());
            problem.expected = static_cast<long long>(expected);
            problems.push_back(problem);
        } else if (!std::all_of(m_development.begin(), m_development.end(), [](const Vec2& p) {
                       return std::isfinite(p.x) && std::isfinite(p.y);
                   })) {
            problems.push_back(problemOf(ProblemCode::DevelopmentNotFinite));
        }
    }
    if (std::optional<Problem> problem = domainProblem(m_sheetDomain)) {
        problems.push_back(std::move(*problem));
    }
    // Positions (finite, not absurdly large) and degenerate curves, rulings and faces.
    for (Problem& problem : degenerateGeometryProblems(*this)) {
        problems.push_back(std::move(problem));
    }
    return problems;
}

} // namespace devsurf::model
