#include "strip_joining.h"

#include "bspline_curve.h"
#include "model_error.h"
#include "topology_edits.h"

#include <Eigen/Dense>

#include <algorithm>
#include <set>
#include <utility>
#include <vector>

namespace devsurf::model {

namespace {

double polygonLength(const std::vector<Vec3>& points) {
    double length = 0.0;
    for (std::size_t i = 1; i < points.size(); ++i) {
        length += (points[i] - points[i - 1]).norm();
    }
    return length;
}

double largestGap(const std::vector<Vec3>& a, const std::vector<Vec3>& b) {
    double gap = 0.0;
    for (std::size_t i = 0; i < a.size(); ++i) {
        gap = std::max(gap, (a[i] - b[i]).norm());
    }
    return gap;
}

// The faces connected to `face` through shared edges.
std::set<FaceId> partOf(const CompositeSurface& surface, FaceId face) {
    std::set<FaceId> part{face};
    std::vector<FaceId> open{face};
    while (!open.empty()) {
        const FaceId f = open.back();
        open.pop_back();
        for (EdgeId e : surface.faceEdges(f)) {
            for (FaceId g : surface.facesOfEdge(e)) {
                if (part.insert(g).second) {
                    open.push_back(g);
                }
            }
        }
    }
    return part;
}

// Whether the loop of `face` runs from `a` to `b` (rather than from b to a).
bool loopRuns(const CompositeSurface& surface, FaceId face, VertexId a, VertexId b) {
    const std::vector<VertexId>& loop = surface.faceLoop(face);
    for (std::size_t i = 0; i < loop.size(); ++i) {
        if (loop[i] == a && loop[(i + 1) % loop.size()] == b) {
            return true;
        }
    }
    return false;
}

// Copies the edge data (label, curve, condition, smoothness, orientation) of `old` onto its
// image in `into`; curve ends follow the vertices of `into`.
void copyEdge(CompositeSurface& into, const EdgeRecord& old, VertexId from, VertexId to) {
    const EdgeId id = into.edgeBetween(from, to);
    if (old.isSpline()) {
        std::vector<Vec3> points = old.controlPoints;
        points.front() = into.position(from);
        points.back() = into.position(to);
        into.setSpline(from, to, old.space, std::move(points));
        into.setCreaseCondition(id, old.condition);
    } else {
        if (into.edge(id).from != from) {
            into.reverseEdge(id);
        }
        into.setSmooth(id, old.smooth);
    }
}

void throwFirstProblem(const CompositeSurface& surface) {
    const std::vector<Problem> problems = surface.validate();
    if (!problems.empty()) {
        throw ModelError(problems.front());
    }
}

// `first` (in S(n1)) and `second` (in S(n2)) joined at first.back() == second.front() in
// S(n1 + n2): ends kept, inner control points by least squares on samples of both.
std::vector<Vec3> joinedCurve(const std::vector<Vec3>& first, const SplineSpace& firstSpace,
                              const std::vector<Vec3>& second, const SplineSpace& secondSpace) {
    const SplineSpace space{firstSpace.degree, firstSpace.smoothness,
                            firstSpace.intervals + secondSpace.intervals};
    const BSplineCurve a = BSplineCurve::uniform(firstSpace, first);
    const BSplineCurve b = BSplineCurve::uniform(secondSpace, second);
    const double split = static_cast<double>(firstSpace.intervals) / space.intervals;
    const int n = space.controlPointCount(false);
    const int samples = 16 * space.intervals;
    Eigen::MatrixXd basis = Eigen::MatrixXd::Zero(samples + 1, n);
    Eigen::MatrixXd target(samples + 1, 3);
    const BSplineCurve joined =
        BSplineCurve::uniform(space, std::vector<Vec3>(static_cast<std::size_t>(n), Vec3()));
    for (int i = 0; i <= samples; ++i) {
        const double u = static_cast<double>(i) / samples;
        const Vec3 p = u <= split ? a.evaluate(u / split) : b.evaluate((u - split) / (1.0 - split));
        const DeBoorRows rows = joined.deBoorRows(u);
        for (std::size_t j = 0; j < rows.indices.size(); ++j) {
            basis(i, rows.indices[j]) += rows.point[j];
        }
        const Vec3 rest = p - first.front() * basis(i, 0) - second.back() * basis(i, n - 1);
        target.row(i) << rest.x, rest.y, rest.z;
    }
    std::vector<Vec3> points(static_cast<std::size_t>(n));
    points.front() = first.front();
    points.back() = second.back();
    const Eigen::MatrixXd inner = basis.middleCols(1, n - 2);
    const Eigen::MatrixXd x = (inner.transpose() * inner).ldlt().solve(inner.transpose() * target);
    for (int j = 1; j + 1 < n; ++j) {
        points[static_cast<std::size_t>(j)] = Vec3(x(j - 1, 0), x(j - 1, 1), x(j - 1, 2));
    }
    return points;
}

// `loop` rotated to start at `vertex`.
std::vector<VertexId> startingAt(std::vector<VertexId> loop, VertexId vertex) {
    std::rotate(loop.begin(), std::find(loop.begin(), loop.end(), vertex), loop.end());
    return loop;
}

} // namespace

std::vector<std::set<FaceId>> surfaceParts(const CompositeSurface& surface) {
    std::vector<std::set<FaceId>> parts;
    std::set<FaceId> seen;
    for (const auto& [face, loop] : surface.faces()) {
        if (seen.count(face) == 0) {
            parts.push_back(partOf(surface, face));
            seen.insert(parts.back().begin(), parts.back().end());
        }
    }
    return parts;
}

BSplineCurve edgeCurve(const CompositeSurface& surface, EdgeId edge) {
    const EdgeRecord& record = surface.edge(edge);
    if (record.isSpline()) {
        return BSplineCurve::uniform(record.space, record.controlPoints);
    }
    return BSplineCurve::uniform(SplineSpace{1, 0, 1},
                                 {surface.position(record.from), surface.position(record.to)});
}

std::optional<NearestCurves> nearestBoundaryCurves(const CompositeSurface& surface,
                                                   const std::set<FaceId>& one,
                                                   const std::set<FaceId>& other) {
    // Per boundary edge bordering `faces`: its ends and midpoint.
    struct Curve {
        EdgeId edge;
        bool spline;
        Vec3 from, middle, to;
    };
    auto boundaryCurves = [&surface](const std::set<FaceId>& faces) {
        std::vector<Curve> curves;
        for (const auto& [id, record] : surface.edges()) {
            const std::vector<FaceId> around = surface.facesOfEdge(id);
            if (around.size() == 1 && faces.count(around.front()) != 0) {
                const BSplineCurve curve = edgeCurve(surface, id);
                curves.push_back({id, record.isSpline(), curve.evaluate(0.0), curve.evaluate(0.5),
                                  curve.evaluate(1.0)});
            }
        }
        return curves;
    };
    std::optional<NearestCurves> nearest;
    for (const Curve& a : boundaryCurves(one)) {
        for (const Curve& b : boundaryCurves(other)) {
            if (a.spline != b.spline) {
                continue;
            }
            const double middle = (a.middle - b.middle).norm();
            const double along = std::max((a.from - b.from).norm(), (a.to - b.to).norm());
            const double against = std::max((a.from - b.to).norm(), (a.to - b.from).norm());
            const double separation = std::max(middle, std::min(along, against));
            if (!nearest || separation < nearest->separation) {
                nearest = NearestCurves{a.edge, b.edge, separation,
                                        0.5 * ((a.to - a.from).norm() + (b.to - b.from).norm())};
            }
        }
    }
    return nearest;
}

std::vector<CompositeSurface> replaceByJoined(const std::vector<CompositeSurface>& surfaces,
                                              const std::vector<int>& indices,
                                              CompositeSurface joined) {
    const auto first = static_cast<std::size_t>(indices.front());
    joined.setId(surfaces[first].id());
    std::vector<CompositeSurface> result;
    for (std::size_t s = 0; s < surfaces.size(); ++s) {
        if (s == first) {
            result.push_back(joined);
        } else if (!std::binary_search(indices.begin(), indices.end(), static_cast<int>(s))) {
            result.push_back(surfaces[s]);
        }
    }
    return result;
}

SurfacesSideBySide placeSideBySide(const CompositeSurface& first, const CompositeSurface& second) {
    SurfacesSideBySide result;
    CompositeSurface& s = result.surface;
    s = first;
    s.setDevelopment({});
    if (!second.name().empty()) {
        s.setName(first.name().empty() ? second.name() : first.name() + " + " + second.name());
    }
    for (const auto& [id, position] : second.vertices()) {
        result.vertexOfSecond[id] = s.addVertex(position);
    }
    for (const auto& [id, loop] : second.faces()) {
        std::vector<VertexId> mapped;
        for (VertexId v : loop) {
            mapped.push_back(result.vertexOfSecond.at(v));
        }
        result.faceOfSecond[id] = s.addFace(mapped);
    }
    for (const auto& [id, record] : second.edges()) {
        const VertexId from = result.vertexOfSecond.at(record.from);
        const VertexId to = result.vertexOfSecond.at(record.to);
        copyEdge(s, record, from, to);
        result.edgeOfSecond[id] = s.edgeBetween(from, to);
    }
    for (VertexId v : second.pinnedVertices()) {
        s.setPinned(result.vertexOfSecond.at(v), true);
    }
    throwFirstProblem(s);
    return result;
}

Weld weldEdges(const CompositeSurface& surface, EdgeId first, EdgeId second, double tolerance) {
    auto refuse = [](EdgeId edge) {
        throw ModelError(edgeProblem(ProblemCode::WeldNeedsBoundaryEdges, edge));
    };
    for (EdgeId e : {first, second}) {
        if (!surface.hasEdge(e) || surface.facesOfEdge(e).size() != 1) {
            refuse(e);
        }
    }
    if (first == second || surface.edge(first).label != surface.edge(second).label ||
        surface.facesOfEdge(first) == surface.facesOfEdge(second)) {
        refuse(second);
    }
    const FaceId firstFace = surface.facesOfEdge(first).front();
    const FaceId secondFace = surface.facesOfEdge(second).front();

    // One spline space: the coarser curve's class refined to the finer one where it can be.
    CompositeSurface source = surface;
    if (source.edge(first).isSpline() && source.edge(first).space != source.edge(second).space) {
        const SplineSpace a = source.edge(first).space;
        const SplineSpace b = source.edge(second).space;
        const bool coarserFirst = a.intervals < b.intervals;
        const int finer = std::max(a.intervals, b.intervals);
        const int coarser = std::min(a.intervals, b.intervals);
        if (a.degree != b.degree || a.smoothness != b.smoothness || finer % coarser != 0) {
            Problem problem = edgeProblem(ProblemCode::CurveSpaceDiffers, second);
            problem.face = firstFace;
            throw ModelError(problem);
        }
        source = refineSplineClass(source, coarserFirst ? first : second, finer / coarser);
    }
    const EdgeRecord& one = source.edge(first);
    const EdgeRecord& two = source.edge(second);
    const std::vector<Vec3> onePoints =
        one.isSpline() ? one.controlPoints
                       : std::vector<Vec3>{source.position(one.from), source.position(one.to)};
    std::vector<Vec3> twoPoints =
        two.isSpline() ? two.controlPoints
                       : std::vector<Vec3>{source.position(two.from), source.position(two.to)};
    std::vector<Vec3> twoReversed(twoPoints.rbegin(), twoPoints.rend());

    Weld weld;
    const double along = largestGap(onePoints, twoPoints);
    const double against = largestGap(onePoints, twoReversed);
    weld.reversed = against < along;
    weld.gap = std::min(along, against);
    if (weld.reversed) {
        twoPoints = std::move(twoReversed);
    }
    const double length = 0.5 * (polygonLength(onePoints) + polygonLength(twoPoints));
    if (!(weld.gap <= tolerance * length)) {
        Problem problem = edgeProblem(ProblemCode::EdgesTooFarApart, first);
        problem.otherEdge = second;
        problem.value = weld.gap;
        problem.limit = tolerance * length;
        throw ModelError(problem);
    }

    // The vertices of `second` that merge into those of `first`, and the merged positions.
    const VertexId twoFrom = weld.reversed ? two.to : two.from;
    const VertexId twoTo = weld.reversed ? two.from : two.to;
    std::map<VertexId, VertexId> merged;
    for (const auto& [from, into] : {std::pair{twoFrom, one.from}, std::pair{twoTo, one.to}}) {
        if (from != into) {
            merged[from] = into;
        }
    }
    std::vector<Vec3> averaged(onePoints.size());
    for (std::size_t i = 0; i < averaged.size(); ++i) {
        averaged[i] = (onePoints[i] + twoPoints[i]) * 0.5;
    }
    // Both faces running along the welded edge the same way: turn the part of `second` over.
    const bool sameWay = loopRuns(source, firstFace, one.from, one.to) ==
                         loopRuns(source, secondFace, twoFrom, twoTo);
    std::set<FaceId> turned;
    if (sameWay) {
        turned = partOf(source, secondFace);
        if (turned.count(firstFace) != 0) {
            Problem problem = faceProblem(ProblemCode::FaceOrientation, secondFace);
            problem.vertex = one.from;
            problem.otherVertex = one.to;
            throw ModelError(problem);
        }
        weld.flipped = true;
    }

    CompositeSurface& result = weld.surface;
    result.setName(source.name());
    result.setId(source.id());
    std::map<VertexId, VertexId> vertexOf;
    for (const auto& [id, position] : source.vertices()) {
        if (merged.count(id) == 0) {
            const Vec3 p = id == one.from ? averaged.front()
                           : id == one.to ? averaged.back()
                                          : position;
            vertexOf[id] = result.addVertex(p);
        }
    }
    for (const auto& [from, into] : merged) {
        vertexOf[from] = vertexOf.at(into);
    }
    for (const auto& [id, loop] : source.faces()) {
        std::vector<VertexId> mapped;
        for (VertexId v : loop) {
            mapped.push_back(vertexOf.at(v));
        }
        if (turned.count(id) != 0) {
            std::reverse(mapped.begin(), mapped.end());
        }
        result.addFace(mapped);
    }
    for (const auto& [id, record] : source.edges()) {
        if (id != second) {
            copyEdge(result, record, vertexOf.at(record.from), vertexOf.at(record.to));
            weld.edgeOf[id] = result.edgeBetween(vertexOf.at(record.from), vertexOf.at(record.to));
        }
    }
    weld.shared = result.edgeBetween(vertexOf.at(one.from), vertexOf.at(one.to));
    weld.edgeOf[second] = weld.shared;
    if (one.isSpline()) {
        // The welded curve has no crease condition yet: it was a boundary on either side.
        result.setSpline(vertexOf.at(one.from), vertexOf.at(one.to), one.space, averaged);
        result.setCreaseCondition(weld.shared, CreaseCondition::None);
    }
    for (VertexId v : source.pinnedVertices()) {
        result.setPinned(vertexOf.at(v), true);
    }
    result.setKeepsDevelopment(source.keepsDevelopment());
    result.setSheetDomain(source.sheetDomain());
    throwFirstProblem(result);
    return weld;
}

CompositeSurface mergeStrips(const CompositeSurface& surface, EdgeId ruling) {
    const auto refuse = [ruling]() {
        throw ModelError(edgeProblem(ProblemCode::MergeNeedsStrips, ruling));
    };
    if (!surface.hasEdge(ruling) || surface.edge(ruling).isSpline() ||
        surface.facesOfEdge(ruling).size() != 2) {
        refuse();
    }
    const std::vector<FaceId> faces = surface.facesOfEdge(ruling);
    const VertexId p = surface.edge(ruling).from;
    const VertexId q = surface.edge(ruling).to;
    for (FaceId f : faces) {
        if (surface.faceType(f) != FaceType::StripSRSR) {
            refuse();
        }
    }
    for (const auto& [face, loop] : surface.faces()) {
        const bool touches = std::find(loop.begin(), loop.end(), p) != loop.end() ||
                             std::find(loop.begin(), loop.end(), q) != loop.end();
        if (touches && face != faces[0] && face != faces[1]) {
            refuse();
        }
    }
    // The first face runs u → w along the ruling, the second w → u. Rotated, the first is
    // [w, r1, r2, u] and the second [u, s1, s2, w]: the merged loop is [r1, r2, s1, s2], with
    // the curves r2 → u → s1 and s2 → w → r1.
    const VertexId u = loopRuns(surface, faces[0], p, q) ? p : q;
    const VertexId w = u == p ? q : p;
    const std::vector<VertexId> first = startingAt(surface.faceLoop(faces[0]), w);
    const std::vector<VertexId> second = startingAt(surface.faceLoop(faces[1]), u);
    const VertexId r1 = first[1], r2 = first[2], s1 = second[1], s2 = second[2];
    const EdgeId curves[4] = {surface.edgeBetween(r2, u), surface.edgeBetween(u, s1),
                              surface.edgeBetween(s2, w), surface.edgeBetween(w, r1)};
    for (EdgeId e : curves) {
        if (e == kInvalidId || !surface.edge(e).isSpline() || surface.facesOfEdge(e).size() != 1) {
            refuse();
        }
    }
    const SplineSpace& firstSpace = surface.edge(curves[0]).space;
    const SplineSpace& secondSpace = surface.edge(curves[1]).space;
    if (firstSpace.degree != secondSpace.degree ||
        firstSpace.smoothness != secondSpace.smoothness) {
        refuse();
    }
    const SplineSpace joinedSpace{firstSpace.degree, firstSpace.smoothness,
                                  firstSpace.intervals + secondSpace.intervals};

    CompositeSurface result;
    result.setName(surface.name());
    result.setId(surface.id());
    std::map<VertexId, VertexId> vertexOf;
    for (const auto& [id, position] : surface.vertices()) {
        if (id != u && id != w) {
            vertexOf[id] = result.addVertex(position);
        }
    }
    for (const auto& [id, loop] : surface.faces()) {
        if (id == faces[1]) {
            continue;
        }
        const std::vector<VertexId> old =
            id == faces[0] ? std::vector<VertexId>{r1, r2, s1, s2} : loop;
        std::vector<VertexId> mapped;
        for (VertexId v : old) {
            mapped.push_back(vertexOf.at(v));
        }
        result.addFace(mapped);
    }
    for (const auto& [id, record] : surface.edges()) {
        if (id != ruling &&
            std::find(std::begin(curves), std::end(curves), id) == std::end(curves)) {
            copyEdge(result, record, vertexOf.at(record.from), vertexOf.at(record.to));
        }
    }
    result.setSpline(vertexOf.at(r2), vertexOf.at(s1), joinedSpace,
                     joinedCurve(surface.controlPointsFrom(r2, u), firstSpace,
                                 surface.controlPointsFrom(u, s1), secondSpace));
    result.setSpline(vertexOf.at(s2), vertexOf.at(r1), joinedSpace,
                     joinedCurve(surface.controlPointsFrom(s2, w), secondSpace,
                                 surface.controlPointsFrom(w, r1), firstSpace));
    for (VertexId v : surface.pinnedVertices()) {
        if (v != u && v != w) {
            result.setPinned(vertexOf.at(v), true);
        }
    }
    result.setKeepsDevelopment(surface.keepsDevelopment());
    result.setSheetDomain(surface.sheetDomain());
    throwFirstProblem(result);
    return result;
}

} // namespace devsurf::model
