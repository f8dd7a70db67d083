#include "geometry_checks.h"

#include "bspline_curve.h"
#include "composite_surface.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <set>

namespace devsurf::model {

namespace {

bool isHuge(const Vec3& p) {
    return std::abs(p.x) > kMaxCoordinate || std::abs(p.y) > kMaxCoordinate ||
           std::abs(p.z) > kMaxCoordinate;
}

// An S-edge whose control data validate() accepts structurally.
bool usableSpline(const EdgeRecord& record) {
    return record.isSpline() && record.space.isValid() &&
           record.controlPoints.size() ==
               static_cast<std::size_t>(record.space.controlPointCount(false)) &&
           record.controlPoints.size() >= 2;
}

// Whether a stretch of a curve of non-zero length has shrunk to a point: two neighbouring
// samples of the held sheet's density (kDevelopmentSamplesPerInterval) closer than `tolerance`.
// A held sheet's boundary can press a sample into the corner vertex after it (docs/tuning.md,
// "A long move is split").
bool pinched(const EdgeRecord& record, double tolerance) {
    const BSplineCurve curve = BSplineCurve::uniform(record.space, record.controlPoints);
    const int count = kDevelopmentSamplesPerInterval * std::max(1, record.space.intervals);
    Vec3 previous = curve.evaluate(0.0);
    for (int i = 1; i <= count; ++i) {
        const Vec3 next = curve.evaluate(static_cast<double>(i) / count);
        if (distance(previous, next) <= tolerance) {
            return true;
        }
        previous = next;
    }
    return false;
}

bool allUsable(const std::vector<Vec3>& points) {
    return std::all_of(points.begin(), points.end(),
                       [](const Vec3& p) { return p.isFinite() && !isHuge(p); });
}

// The face's boundary as a closed polygon: its corners, with the interior control points of
// its S-sides in between (a curve lies in the convex hull of its control points). corners[i]
// and sides[i] are the face loop's vertex i and its side to vertex i + 1.
void boundaryPolygon(const std::vector<VertexId>& loop, const std::vector<const Vec3*>& corners,
                     const std::vector<const EdgeRecord*>& sides, std::vector<Vec3>& polygon) {
    polygon.clear();
    for (std::size_t i = 0; i < loop.size(); ++i) {
        polygon.push_back(*corners[i]);
        const EdgeRecord& side = *sides[i];
        if (usableSpline(side)) {
            const std::vector<Vec3>& points = side.controlPoints;
            if (side.from == loop[i]) {
                polygon.insert(polygon.end(), points.begin() + 1, points.end() - 1);
            } else {
                polygon.insert(polygon.end(), points.rbegin() + 1, points.rend() - 1);
            }
        }
    }
}

// Triangle fan from the centroid: zero exactly when every boundary point lies on one line
// through the centroid, i.e. when the face encloses nothing.
double fanArea(const std::vector<Vec3>& polygon, double* perimeter) {
    Vec3 centroid;
    for (const Vec3& p : polygon) {
        centroid += p;
    }
    centroid = centroid / static_cast<double>(polygon.size());
    double area = 0.0;
    *perimeter = 0.0;
    for (std::size_t i = 0; i < polygon.size(); ++i) {
        const Vec3& p = polygon[i];
        const Vec3& q = polygon[(i + 1) % polygon.size()];
        area += 0.5 * cross(p - centroid, q - centroid).norm();
        *perimeter += distance(p, q);
    }
    return area;
}

} // namespace

std::vector<Problem> degenerateGeometryProblems(const CompositeSurface& surface) {
    std::vector<Problem> problems;

    // Faces around each vertex, for naming; gathered at the first problem that needs them
    // (the checks also run after every solver step, SolveSession::step, where there is none).
    std::map<VertexId, std::vector<FaceId>> facesOfVertex;
    auto facesAround = [&surface, &facesOfVertex](VertexId vertex) {
        if (facesOfVertex.empty()) {
            for (const auto& [face, loop] : surface.faces()) {
                for (VertexId v : loop) {
                    auto& list = facesOfVertex[v];
                    if (std::find(list.begin(), list.end(), face) == list.end()) {
                        list.push_back(face);
                    }
                }
            }
        }
        return facesOfVertex[vertex];
    };

    // Lengths below this count as zero: a billionth of the design's size (at least 1e-9 mm),
    // far below anything that can be cut or folded, far above rounding.
    double lo[3] = {std::numeric_limits<double>::infinity(),
                    std::numeric_limits<double>::infinity(),
                    std::numeric_limits<double>::infinity()};
    double hi[3] = {-lo[0], -lo[1], -lo[2]};
    std::set<VertexId> badVertices;
    for (const auto& [id, p] : surface.vertices()) {
        if (!p.isFinite()) {
            Problem problem = vertexProblem(ProblemCode::PositionNotFinite, id);
            problem.faces = facesAround(id);
            problems.push_back(problem);
            badVertices.insert(id);
            continue;
        }
        if (isHuge(p)) {
            Problem problem = vertexProblem(ProblemCode::PositionTooFar, id);
            problem.faces = facesAround(id);
            problem.value = p.norm();
            problem.limit = kMaxCoordinate;
            problems.push_back(problem);
            badVertices.insert(id);
            continue;
        }
        for (int k = 0; k < 3; ++k) {
            lo[k] = std::min(lo[k], p[k]);
            hi[k] = std::max(hi[k], p[k]);
        }
    }
    const double size = badVertices.size() == surface.vertices().size()
                            ? 0.0
                            : std::hypot(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]);
    const double tolerance = 1.0e-9 * std::max(size, 1.0);

    std::set<std::pair<VertexId, VertexId>> zeroEdges;
    std::set<EdgeId> badEdges;
    for (const auto& [id, record] : surface.edges()) {
        auto faces = [&surface, id = id] { return surface.facesOfEdge(id); };
        if (record.isSpline()) {
            if (!usableSpline(record)) {
                continue;
            }
            if (!allUsable(record.controlPoints)) {
                // Non-finite control points are reported by validate() itself.
                if (std::all_of(record.controlPoints.begin(), record.controlPoints.end(),
                                [](const Vec3& p) { return p.isFinite(); })) {
                    Problem problem = edgeProblem(ProblemCode::ControlPointTooFar, id);
                    problem.faces = faces();
                    problem.limit = kMaxCoordinate;
                    problems.push_back(problem);
                }
                badEdges.insert(id);
                continue;
            }
            double length = 0.0;
            for (std::size_t i = 0; i + 1 < record.controlPoints.size(); ++i) {
                length += distance(record.controlPoints[i], record.controlPoints[i + 1]);
            }
            // The curve lies in the hull of its control points: a control polygon of zero
            // length is a curve of zero length.
            if (length <= tolerance) {
                Problem problem = edgeProblem(ProblemCode::CurveZeroLength, id);
                problem.faces = faces();
                problems.push_back(problem);
                zeroEdges.insert(std::minmax(record.from, record.to));
            } else if (pinched(record, tolerance)) {
                Problem problem = edgeProblem(ProblemCode::CurvePinched, id);
                problem.faces = faces();
                problems.push_back(problem);
            }
            continue;
        }
        const auto from = surface.vertices().find(record.from);
        const auto to = surface.vertices().find(record.to);
        if (badVertices.count(record.from) != 0 || badVertices.count(record.to) != 0 ||
            from == surface.vertices().end() || to == surface.vertices().end()) {
            continue;
        }
        if (distance(from->second, to->second) <= tolerance) {
            Problem problem = edgeProblem(ProblemCode::RulingZeroLength, id);
            problem.faces = faces();
            problems.push_back(problem);
            zeroEdges.insert(std::minmax(record.from, record.to));
        }
    }

    // Each face's corners and sides are looked up once: the check runs after every solver step
    // (SolveSession::step), where the lookups cost more than the geometry.
    std::vector<const Vec3*> corners;
    std::vector<const EdgeRecord*> sides;
    std::vector<Vec3> polygon;
    for (const auto& [face, loop] : surface.faces()) {
        const std::size_t count = loop.size();
        corners.assign(count, nullptr);
        sides.assign(count, nullptr);
        bool usable = true;
        for (std::size_t i = 0; i < count && usable; ++i) {
            const VertexId a = loop[i];
            const auto vertex = surface.vertices().find(a);
            const EdgeId e = surface.edgeBetween(a, loop[(i + 1) % count]);
            usable = badVertices.count(a) == 0 && vertex != surface.vertices().end() &&
                     e != kInvalidId && badEdges.count(e) == 0;
            if (usable) {
                const EdgeRecord& side = surface.edge(e);
                usable = !side.isSpline() || usableSpline(side);
                corners[i] = &vertex->second;
                sides[i] = &side;
            }
        }
        if (!usable) {
            continue;
        }
        // Coincident corners not already reported as a zero-length side.
        for (std::size_t i = 0; i < count; ++i) {
            for (std::size_t j = i + 1; j < count; ++j) {
                const auto pair = std::minmax(loop[i], loop[j]);
                if (zeroEdges.count(pair) != 0) {
                    continue;
                }
                if (distance(*corners[i], *corners[j]) <= tolerance) {
                    Problem problem = faceProblem(ProblemCode::CoincidentVertices, face);
                    problem.vertex = loop[i];
                    problem.otherVertex = loop[j];
                    problems.push_back(problem);
                }
            }
        }
        double perimeter = 0.0;
        boundaryPolygon(loop, corners, sides, polygon);
        const double area = fanArea(polygon, &perimeter);
        if (area <= tolerance * std::max(perimeter, tolerance)) {
            problems.push_back(faceProblem(ProblemCode::ZeroArea, face));
        }
    }
    return problems;
}

bool allCoordinatesFinite(const CompositeSurface& surface) {
    auto finite = [](const Vec3& p) {
        return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
    };
    for (const auto& [id, position] : surface.vertices()) {
        if (!finite(position)) {
            return false;
        }
    }
    for (const auto& [id, edge] : surface.edges()) {
        if (!std::all_of(edge.controlPoints.begin(), edge.controlPoints.end(), finite)) {
            return false;
        }
    }
    return true;
}

} // namespace devsurf::model
