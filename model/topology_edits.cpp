#include "topology_edits.h"

#include "bspline_curve.h"
#include "model_error.h"
#include "strip.h"

#include <algorithm>
#include <cmath>
#include <deque>

namespace devsurf::model {

namespace {

std::string str(std::uint32_t id) {
    return std::to_string(id);
}

std::pair<VertexId, VertexId> key(VertexId a, VertexId b) {
    return a < b ? std::make_pair(a, b) : std::make_pair(b, a);
}

// The canonical data of a surface while an edit rewrites it; build() turns it back into a
// surface. CompositeSurface has no removal operations on purpose (ids must stay stable), so a
// topological edit rebuilds the surface the way loading a file does: vertices, edges, then
// faces in id order.
struct SurfaceData {
    std::string name;
    SurfaceId surfaceId = 0;
    std::map<VertexId, Vec3> vertices;
    std::map<EdgeId, EdgeRecord> edges;
    std::map<FaceId, std::vector<VertexId>> faces;
    std::set<VertexId> pinned;     // vertices keep their ids, so pins carry over
    bool keepsDevelopment = false; // the setting carries over; the new samples are unfolded anew
    SheetDomain sheetDomain;       // carries over likewise
    std::map<std::pair<VertexId, VertexId>, EdgeId> edgeByVertices;
    VertexId nextVertex = 0;
    EdgeId nextEdge = 0;
    FaceId nextFace = 0;

    explicit SurfaceData(const CompositeSurface& s)
        : name(s.name()), surfaceId(s.id()), vertices(s.vertices()), edges(s.edges()),
          faces(s.faces()), pinned(s.pinnedVertices()), keepsDevelopment(s.keepsDevelopment()),
          sheetDomain(s.sheetDomain()), nextVertex(s.nextVertexId()), nextEdge(s.nextEdgeId()),
          nextFace(s.nextFaceId()) {
        for (const auto& [id, record] : edges) {
            edgeByVertices[key(record.from, record.to)] = id;
        }
    }

    VertexId addVertex(const Vec3& p) {
        const VertexId id = nextVertex++;
        vertices.emplace(id, p);
        return id;
    }
    EdgeId find(VertexId a, VertexId b) const {
        auto it = edgeByVertices.find(key(a, b));
        return it == edgeByVertices.end() ? kInvalidId : it->second;
    }
    EdgeId addEdge(const EdgeRecord& record) {
        const EdgeId id = nextEdge++;
        edges.emplace(id, record);
        edgeByVertices[key(record.from, record.to)] = id;
        return id;
    }
    // An R-edge between a and b, or the existing edge if another face already made it.
    EdgeId ruling(VertexId a, VertexId b) {
        const EdgeId existing = find(a, b);
        if (existing != kInvalidId) {
            return existing;
        }
        EdgeRecord record;
        record.from = a;
        record.to = b;
        return addEdge(record);
    }
    void setEnds(EdgeId id, VertexId from, VertexId to) {
        EdgeRecord& record = edges.at(id);
        edgeByVertices.erase(key(record.from, record.to));
        record.from = from;
        record.to = to;
        edgeByVertices[key(from, to)] = id;
    }
    FaceId addFace(std::vector<VertexId> loop) {
        const FaceId id = nextFace++;
        faces.emplace(id, std::move(loop));
        return id;
    }

    CompositeSurface build(const std::string& what) const {
        CompositeSurface s;
        s.setName(name);
        s.setId(surfaceId);
        for (const auto& [id, p] : vertices) {
            s.addVertexWithId(id, p);
        }
        for (const auto& [id, record] : edges) {
            s.addEdgeWithId(id, record);
        }
        for (const auto& [id, loop] : faces) {
            s.addFaceWithId(id, loop);
        }
        s.setNextIds(nextVertex, nextEdge, nextFace);
        for (VertexId vertex : pinned) {
            s.setPinned(vertex, true);
        }
        s.setKeepsDevelopment(keepsDevelopment);
        s.setSheetDomain(sheetDomain);
        // A face side without a prepared edge would have been created silently; that, or any
        // other problem, is a bug in the edit, reported rather than handed to the document.
        if (s.edges().size() != edges.size()) {
            throw ModelError(internalProblem(what + ": a face side has no edge"));
        }
        if (const auto problems = s.validate(); !problems.empty()) {
            throw ModelError(internalProblem(what + ": " + technicalKey(problems.front())));
        }
        return s;
    }
};

std::size_t wrap(int i, std::size_t n) {
    const int size = static_cast<int>(n);
    return static_cast<std::size_t>(((i % size) + size) % size);
}

// Greville abscissae of the clamped uniform space: a curve with control points at
// p + ξ_i (q − p) is the segment pq with linear parametrisation.
std::vector<Vec3> straightControlPoints(const SplineSpace& space, const Vec3& p, const Vec3& q) {
    const std::vector<double> knots = space.knots(false);
    const int count = space.controlPointCount(false);
    std::vector<Vec3> points;
    points.reserve(static_cast<std::size_t>(count));
    for (int i = 0; i < count; ++i) {
        double xi = 0.0;
        for (int j = 1; j <= space.degree; ++j) {
            xi += knots[static_cast<std::size_t>(i + j)];
        }
        xi /= space.degree;
        points.push_back(p * (1.0 - xi) + q * xi);
    }
    points.front() = p;
    points.back() = q;
    return points;
}

// The S-side of an SRSR face that stripOfFace() takes as its curve a: loop side ia runs along a.
std::size_t stripASide(const CompositeSurface& s, FaceId face) {
    const std::string labels = s.labelString(face);
    const auto edges = s.faceEdges(face);
    std::size_t ia = labels[0] == 'S' ? 0 : 1;
    if (edges[ia + 2] < edges[ia]) {
        ia += 2;
    }
    return ia;
}

// Reports only what an edit broke, not problems the surface already had.
void throwIfNewProblem(const CompositeSurface& before, const CompositeSurface& after) {
    const auto problems = after.validate();
    if (problems.empty()) {
        return;
    }
    const auto old = before.validate();
    for (const Problem& problem : problems) {
        if (std::find(old.begin(), old.end(), problem) == old.end()) {
            throw ModelError(problem);
        }
    }
}

struct RowFace {
    FaceId face;
    std::size_t ia; // loop side along the face's curve a (the side the row's t counts from)
};

std::vector<RowFace> collectRow(const CompositeSurface& s, FaceId face) {
    if (!s.hasFace(face)) {
        throw ModelError(elementProblem(ProblemCode::Missing, Element::Face, face));
    }
    if (s.faceType(face) != FaceType::StripSRSR) {
        Problem problem = faceProblem(ProblemCode::CreaseNeedsStrip, face);
        problem.faceType = s.faceType(face);
        throw ModelError(problem);
    }
    std::map<FaceId, std::size_t> seen{{face, stripASide(s, face)}};
    std::vector<RowFace> row{{face, seen[face]}};
    for (std::size_t next = 0; next < row.size(); ++next) {
        const RowFace current = row[next];
        const auto& loop = s.faceLoop(current.face);
        for (std::size_t side : {wrap(static_cast<int>(current.ia) + 1, 4),
                                 wrap(static_cast<int>(current.ia) + 3, 4)}) {
            const VertexId from = loop[side];
            const VertexId to = loop[wrap(static_cast<int>(side) + 1, 4)];
            const VertexId aVertex = side == wrap(static_cast<int>(current.ia) + 1, 4) ? from : to;
            const EdgeId ruling = s.edgeBetween(from, to);
            for (FaceId other : s.facesOfEdge(ruling)) {
                if (other == current.face) {
                    continue;
                }
                const FaceType type = s.faceType(other);
                if (type == FaceType::Planar) {
                    continue;
                }
                if (type != FaceType::StripSRSR) {
                    Problem problem = edgeProblem(ProblemCode::CreaseBlocked, ruling);
                    problem.face = face;
                    problem.otherFace = other;
                    problem.faceType = type;
                    throw ModelError(problem);
                }
                const auto& otherLoop = s.faceLoop(other);
                std::size_t shared = 0;
                while (s.edgeBetween(otherLoop[shared],
                                     otherLoop[wrap(static_cast<int>(shared) + 1, 4)]) != ruling) {
                    ++shared;
                }
                const std::size_t ia = otherLoop[shared] == aVertex
                                           ? wrap(static_cast<int>(shared) - 1, 4)
                                           : wrap(static_cast<int>(shared) + 1, 4);
                auto it = seen.find(other);
                if (it != seen.end()) {
                    if (it->second != ia) {
                        throw ModelError(faceProblem(ProblemCode::RowClosesSwapped, face));
                    }
                    continue;
                }
                seen.emplace(other, ia);
                row.push_back({other, ia});
            }
        }
    }
    return row;
}

} // namespace

SplineSpace spaceForNewSplineEdge(const CompositeSurface& surface, EdgeId edge) {
    for (FaceId face : surface.facesOfEdge(edge)) {
        for (EdgeId other : surface.faceEdges(face)) {
            if (other != edge && other != kInvalidId && surface.edge(other).isSpline()) {
                return surface.edge(other).space;
            }
        }
    }
    return SplineSpace{3, 2, 2};
}

CompositeSurface relabelEdges(const CompositeSurface& surface,
                              const std::vector<std::pair<EdgeId, EdgeLabel>>& labels) {
    if (labels.empty()) {
        throw ModelError(problemOf(ProblemCode::NothingToRelabel));
    }
    CompositeSurface result = surface;
    for (const auto& [edge, label] : labels) {
        if (!result.hasEdge(edge)) {
            throw ModelError(elementProblem(ProblemCode::Missing, Element::Edge, edge));
        }
        const EdgeRecord& record = result.edge(edge);
        if (record.label == label) {
            continue;
        }
        if (label == EdgeLabel::Ruling) {
            result.setRuling(edge);
        } else {
            const SplineSpace space = spaceForNewSplineEdge(result, edge);
            const VertexId from = record.from;
            const VertexId to = record.to;
            result.setSpline(
                from, to, space,
                straightControlPoints(space, result.position(from), result.position(to)));
        }
    }
    throwIfNewProblem(surface, result);
    return result;
}

std::vector<FaceId> stripRow(const CompositeSurface& surface, FaceId face) {
    std::vector<FaceId> faces;
    for (const RowFace& f : collectRow(surface, face)) {
        faces.push_back(f.face);
    }
    return faces;
}

CompositeSurface subdivideStrip(const CompositeSurface& surface, FaceId face, double t) {
    if (!(t > 0.0 && t < 1.0)) {
        Problem problem = problemOf(ProblemCode::CreasePositionOutside);
        problem.face = face;
        problem.value = t;
        throw ModelError(problem);
    }
    const std::vector<RowFace> row = collectRow(surface, face);
    SurfaceData data(surface);

    // One new vertex per cut ruling, shared by the faces on both sides of it.
    std::map<EdgeId, VertexId> cutVertex;
    std::vector<EdgeId> cutOrder;
    auto vertexOnRuling = [&](VertexId aVertex, VertexId bVertex) {
        const EdgeId ruling = surface.edgeBetween(aVertex, bVertex);
        auto it = cutVertex.find(ruling);
        if (it != cutVertex.end()) {
            return it->second;
        }
        const Vec3 p = surface.position(aVertex) * (1.0 - t) + surface.position(bVertex) * t;
        const VertexId v = data.addVertex(p);
        cutVertex.emplace(ruling, v);
        cutOrder.push_back(ruling);
        return v;
    };

    for (const RowFace& rf : row) {
        const auto& loop = surface.faceLoop(rf.face);
        auto at = [&](int offset) { return loop[wrap(static_cast<int>(rf.ia) + offset, 4)]; };
        // a runs at(0) → at(1), b runs at(3) → at(2); both share the strip's parameter u.
        const VertexId m1 = vertexOnRuling(at(1), at(2));
        const VertexId m2 = vertexOnRuling(at(0), at(3));
        if (data.find(m2, m1) == kInvalidId) {
            const std::vector<Vec3> a = surface.controlPointsFrom(at(0), at(1));
            const std::vector<Vec3> b = surface.controlPointsFrom(at(3), at(2));
            EdgeRecord crease;
            crease.from = m2;
            crease.to = m1;
            crease.label = EdgeLabel::Spline;
            crease.space = surface.edge(surface.edgeBetween(at(0), at(1))).space;
            crease.controlPoints.resize(a.size());
            // c = (1 − t) a + t b is the strip's curve v = t: the geometry is unchanged.
            for (std::size_t i = 0; i < a.size(); ++i) {
                crease.controlPoints[i] = a[i] * (1.0 - t) + b[i] * t;
            }
            crease.controlPoints.front() = data.vertices.at(m2);
            crease.controlPoints.back() = data.vertices.at(m1);
            data.addEdge(crease);
        }
        data.faces[rf.face] = {at(0), at(1), m1, m2};
        data.addFace({m2, m1, at(2), at(3)});
    }
    for (EdgeId ruling : cutOrder) {
        const VertexId m = cutVertex.at(ruling);
        const EdgeRecord original = surface.edge(ruling);
        data.setEnds(ruling, original.from, m);
        EdgeRecord rest;
        rest.from = m;
        rest.to = original.to;
        rest.smooth = original.smooth; // both halves of a smooth ruling stay smooth
        data.addEdge(rest);
        // Planar neighbours take the new vertex into their loop and stay planar.
        for (FaceId other : surface.facesOfEdge(ruling)) {
            if (surface.faceType(other) != FaceType::Planar) {
                continue;
            }
            auto& loop = data.faces.at(other);
            for (std::size_t i = 0; i < loop.size(); ++i) {
                const VertexId p = loop[i];
                const VertexId q = loop[(i + 1) % loop.size()];
                if (key(p, q) == key(original.from, original.to)) {
                    loop.insert(loop.begin() + static_cast<std::ptrdiff_t>(i + 1), m);
                    break;
                }
            }
        }
    }
    return data.build("subdividing face " + str(face));
}

std::vector<EdgeId> splineClassOf(const CompositeSurface& surface, EdgeId edge) {
    if (!surface.hasEdge(edge) || !surface.edge(edge).isSpline()) {
        throw ModelError(edgeProblem(ProblemCode::NotACurve, edge));
    }
    for (auto& cls : surface.splineClasses()) {
        if (std::find(cls.begin(), cls.end(), edge) != cls.end()) {
            return cls;
        }
    }
    return {edge};
}

CompositeSurface splitAtRuling(const CompositeSurface& surface, FaceId face, int breakpoint) {
    if (!surface.hasFace(face)) {
        throw ModelError(elementProblem(ProblemCode::Missing, Element::Face, face));
    }
    const FaceType type = surface.faceType(face);
    if (type == FaceType::Planar || type == FaceType::Invalid) {
        Problem problem = faceProblem(ProblemCode::RulingNeedsStrip, face);
        problem.faceType = type;
        throw ModelError(problem);
    }
    const Strip start = stripOfFace(surface, face);
    const SplineSpace space = surface.edge(start.aSide.edge).space;
    const int n = space.intervals;
    if (n < 2) {
        throw ModelError(faceProblem(ProblemCode::SingleInterval, face));
    }
    if (breakpoint < 1 || breakpoint > n - 1) {
        Problem problem = faceProblem(ProblemCode::RulingPosition, face);
        problem.count = breakpoint;
        problem.expected = n;
        throw ModelError(problem);
    }

    // Breakpoint index of every S-edge of the class, in the edge's stored orientation.
    std::map<EdgeId, int> cut{
        {start.aSide.edge, start.aSide.reversed ? n - breakpoint : breakpoint}};
    std::set<FaceId> faces;
    std::deque<EdgeId> queue{start.aSide.edge};
    while (!queue.empty()) {
        const EdgeId e = queue.front();
        queue.pop_front();
        for (FaceId g : surface.facesOfEdge(e)) {
            if (!faces.insert(g).second || surface.faceType(g) == FaceType::ConeSRR) {
                continue;
            }
            const Strip strip = stripOfFace(surface, g);
            const bool fromA = strip.aSide.edge == e;
            const StripSide& known = fromA ? strip.aSide : strip.bSide;
            const StripSide& other = fromA ? strip.bSide : strip.aSide;
            const int alongU = known.reversed ? n - cut.at(e) : cut.at(e);
            const int otherCut = other.reversed ? n - alongU : alongU;
            auto it = cut.find(other.edge);
            if (it == cut.end()) {
                cut.emplace(other.edge, otherCut);
                queue.push_back(other.edge);
            } else if (it->second != otherCut) {
                throw ModelError(faceProblem(ProblemCode::CurvesMeetReversed, face));
            }
        }
    }

    SurfaceData data(surface);
    std::map<EdgeId, VertexId> splitVertex;
    for (const auto& [e, k] : cut) {
        const EdgeRecord original = surface.edge(e);
        if (original.space != space) {
            Problem problem = edgeProblem(ProblemCode::CurveSpaceDiffers, e);
            problem.face = face;
            throw ModelError(problem);
        }
        const BSplineCurve curve = BSplineCurve::uniform(space, original.controlPoints);
        auto [left, right] = curve.split(static_cast<double>(k) / n);
        std::vector<Vec3> leftPoints = left.controlPoints();
        std::vector<Vec3> rightPoints = right.controlPoints();
        SplineSpace leftSpace = space;
        leftSpace.intervals = k;
        SplineSpace rightSpace = space;
        rightSpace.intervals = n - k;
        if (leftPoints.size() != static_cast<std::size_t>(leftSpace.controlPointCount(false)) ||
            rightPoints.size() != static_cast<std::size_t>(rightSpace.controlPointCount(false))) {
            throw ModelError(
                internalProblem("splitting S-edge " + str(e) + " gave non-uniform pieces"));
        }
        const VertexId w = data.addVertex(leftPoints.back());
        rightPoints.front() = leftPoints.back();
        splitVertex.emplace(e, w);

        data.setEnds(e, original.from, w);
        EdgeRecord& first = data.edges.at(e);
        first.space = leftSpace;
        first.controlPoints = std::move(leftPoints);
        EdgeRecord second = original;
        second.from = w;
        second.space = rightSpace;
        second.controlPoints = std::move(rightPoints);
        data.addEdge(second);
    }

    for (FaceId g : faces) {
        const auto& loop = surface.faceLoop(g);
        std::vector<VertexId> extended;
        std::vector<std::size_t> chord;
        for (std::size_t i = 0; i < loop.size(); ++i) {
            extended.push_back(loop[i]);
            auto it = splitVertex.find(surface.edgeBetween(loop[i], loop[(i + 1) % loop.size()]));
            if (it != splitVertex.end()) {
                chord.push_back(extended.size());
                extended.push_back(it->second);
            }
        }
        if (chord.size() == 1) {
            // A cone: the new ruling runs from the split point to the apex.
            const VertexId apex = stripOfFace(surface, g).apexVertex;
            chord.push_back(static_cast<std::size_t>(
                std::find(extended.begin(), extended.end(), apex) - extended.begin()));
            std::sort(chord.begin(), chord.end());
        }
        if (chord.size() != 2) {
            throw ModelError(internalProblem("face " + str(g) + " cannot take the new ruling"));
        }
        const auto i1 = static_cast<std::ptrdiff_t>(chord[0]);
        const auto i2 = static_cast<std::ptrdiff_t>(chord[1]);
        std::vector<VertexId> inner(extended.begin() + i1, extended.begin() + i2 + 1);
        std::vector<VertexId> outer(extended.begin() + i2, extended.end());
        outer.insert(outer.end(), extended.begin(), extended.begin() + i1 + 1);
        data.ruling(extended[chord[0]], extended[chord[1]]);
        data.faces[g] = std::move(outer);
        data.addFace(std::move(inner));
    }
    return data.build("adding a ruling to face " + str(face));
}

CompositeSurface refineSplineClass(const CompositeSurface& surface, EdgeId edge, int factor) {
    const std::vector<EdgeId> cls = splineClassOf(surface, edge);
    const SplineSpace space = surface.edge(edge).space;
    if (factor < 2) {
        Problem problem = edgeProblem(ProblemCode::RefineFactorTooSmall, edge);
        problem.count = factor;
        throw ModelError(problem);
    }
    if (static_cast<long long>(space.intervals) * factor > SplineSpace::maxIntervals) {
        Problem problem = edgeProblem(ProblemCode::TooManyIntervals, edge);
        problem.count = space.intervals;
        problem.expected = SplineSpace::maxIntervals;
        throw ModelError(problem);
    }
    SplineSpace refined = space;
    refined.intervals = space.intervals * factor;
    const int times = space.degree - space.smoothness;
    CompositeSurface result = surface;
    for (EdgeId e : cls) {
        const EdgeRecord& record = surface.edge(e);
        BSplineCurve curve = BSplineCurve::uniform(record.space, record.controlPoints);
        // Knot insertion keeps the curve; inserting every (factor·j + r) / (factor·n) with the
        // multiplicity of a breakpoint gives exactly the knots of the refined uniform space.
        for (int j = 0; j < space.intervals; ++j) {
            for (int r = 1; r < factor; ++r) {
                curve.insertKnot(static_cast<double>(factor * j + r) / refined.intervals, times);
            }
        }
        std::vector<Vec3> points = curve.controlPoints();
        if (points.size() != static_cast<std::size_t>(refined.controlPointCount(false))) {
            throw ModelError(internalProblem("refining S-edge " + str(e) + " went wrong"));
        }
        points.front() = surface.position(record.from);
        points.back() = surface.position(record.to);
        result.setSpline(record.from, record.to, refined, std::move(points));
    }
    return result;
}

CompositeSurface moveVertices(const CompositeSurface& surface, const std::set<VertexId>& vertices,
                              const RigidMotion& motion) {
    if (vertices.empty()) {
        throw ModelError(problemOf(ProblemCode::NothingToMove));
    }
    for (VertexId v : vertices) {
        if (!surface.hasVertex(v)) {
            throw ModelError(elementProblem(ProblemCode::Missing, Element::Vertex, v));
        }
    }
    CompositeSurface result = surface;
    for (const auto& [id, record] : surface.edges()) {
        if (!record.isSpline() || record.controlPoints.size() < 3) {
            continue;
        }
        const bool fromMoves = vertices.count(record.from) != 0;
        const bool toMoves = vertices.count(record.to) != 0;
        if (!fromMoves && !toMoves) {
            continue;
        }
        std::vector<Vec3> points = record.controlPoints;
        const std::size_t last = points.size() - 1;
        if (fromMoves && toMoves) {
            // Both ends move alike: the whole curve moves rigidly with them.
            for (Vec3& p : points) {
                p = motion.apply(p);
            }
            result.setControlPoints(id, std::move(points));
            continue;
        }
        // The neighbours of the ends keep the end tangents attached to the moved vertices.
        if (fromMoves) {
            points[1] = motion.apply(record.controlPoints[1]);
        }
        if (toMoves && !(fromMoves && last - 1 == 1)) {
            points[last - 1] = motion.apply(record.controlPoints[last - 1]);
        }
        result.setControlPoints(id, std::move(points));
    }
    std::vector<std::pair<VertexId, Vec3>> moves;
    for (VertexId v : vertices) {
        moves.emplace_back(v, motion.apply(surface.position(v)));
    }
    result.moveVertices(moves);
    throwIfNewProblem(surface, result);
    return result;
}

} // namespace devsurf::model
