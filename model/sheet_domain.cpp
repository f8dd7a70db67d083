#include "sheet_domain.h"

#include "model/math_constants.h"
#include "pattern/pattern_geometry.h"
#include "sampled_mesh.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace devsurf::model {

namespace {

using pattern::signedArea;

// An outline vertex turning by this much or more is a corner (fixed, not slid along).
constexpr double kCornerTurn = 30.0 * kPi / 180.0;

Vec2 turned(const Vec2& p, double angle) {
    const double c = std::cos(angle);
    const double s = std::sin(angle);
    return {c * p.x - s * p.y, s * p.x + c * p.y};
}

Vec2 unit(const Vec2& v) {
    const double n = v.norm();
    return n > 0.0 ? v * (1.0 / n) : Vec2(1.0, 0.0);
}

// The area centroid of a closed polygon (its vertex mean if it has no area).
Vec2 centroidOf(const std::vector<Vec2>& polygon) {
    double area = 0.0;
    Vec2 sum;
    for (std::size_t i = 0; i < polygon.size(); ++i) {
        const Vec2& a = polygon[i];
        const Vec2& b = polygon[(i + 1) % polygon.size()];
        const double w = cross2(a, b);
        area += w;
        sum = sum + (a + b) * w;
    }
    if (std::abs(area) > 0.0) {
        return sum * (1.0 / (3.0 * area));
    }
    Vec2 mean;
    for (const Vec2& p : polygon) {
        mean = mean + p * (1.0 / static_cast<double>(polygon.size()));
    }
    return mean;
}

// The outline's loops in their own frame, the outer one first and counter-clockwise, holes
// clockwise.
std::vector<std::vector<Vec2>> orientedOutline(const std::vector<std::vector<Vec2>>& outline) {
    std::vector<std::vector<Vec2>> loops = outline;
    std::stable_sort(loops.begin(), loops.end(), [](const auto& a, const auto& b) {
        return std::abs(signedArea(a)) > std::abs(signedArea(b));
    });
    for (std::size_t l = 0; l < loops.size(); ++l) {
        const bool counterClockwise = signedArea(loops[l]) > 0.0;
        if (counterClockwise != (l == 0)) {
            std::reverse(loops[l].begin(), loops[l].end());
        }
    }
    return loops;
}

// The development's boundary loops (mesh vertex indices), the one enclosing the largest area
// first.
std::vector<std::vector<int>> developmentLoops(const SampledMesh& mesh,
                                               const std::vector<Vec2>& development) {
    std::vector<std::vector<int>> loops = pattern::boundaryLoops(mesh.faces);
    auto areaOf = [&development](const std::vector<int>& loop) {
        std::vector<Vec2> points;
        for (int v : loop) {
            points.push_back(development[static_cast<std::size_t>(v)]);
        }
        return std::abs(signedArea(points));
    };
    std::stable_sort(loops.begin(), loops.end(),
                     [&](const auto& a, const auto& b) { return areaOf(a) > areaOf(b); });
    return loops;
}

std::vector<Vec2> pointsOf(const std::vector<int>& loop, const std::vector<Vec2>& development) {
    std::vector<Vec2> points;
    for (int v : loop) {
        points.push_back(development[static_cast<std::size_t>(v)]);
    }
    return points;
}

double distanceToLoops(const std::vector<DomainLoop>& loops, const Vec2& p) {
    double best = std::numeric_limits<double>::infinity();
    for (const DomainLoop& loop : loops) {
        best = std::min(best, (footPoint(loop, p).point - p).norm());
    }
    return best;
}

} // namespace

bool SheetDomain::operator==(const SheetDomain& o) const {
    return shape == o.shape && width == o.width && height == o.height && radius == o.radius &&
           innerRadius == o.innerRadius && outline == o.outline && centre == o.centre &&
           angle == o.angle && creaseCurves == o.creaseCurves && creaseCurveOf == o.creaseCurveOf;
}

std::vector<DomainLoop> domainLoops(const SheetDomain& d) {
    std::vector<DomainLoop> loops;
    auto circle = [&](double r, bool outer) {
        DomainLoop loop;
        loop.circle = true;
        loop.centre = d.centre;
        loop.radius = r;
        loop.outer = outer;
        loops.push_back(loop);
    };
    auto polygon = [&](const std::vector<Vec2>& points, bool outer) {
        DomainLoop loop;
        loop.outer = outer;
        for (const Vec2& p : points) {
            loop.polygon.push_back(d.centre + turned(p, d.angle));
        }
        loops.push_back(std::move(loop));
    };
    switch (d.shape) {
    case SheetShape::Free:
    case SheetShape::Cylinder: // no boundary: only closed up around
        break;
    case SheetShape::Rectangle: {
        const double w = 0.5 * d.width;
        const double h = 0.5 * d.height;
        polygon({{-w, -h}, {w, -h}, {w, h}, {-w, h}}, true);
        break;
    }
    case SheetShape::Disk:
        circle(d.radius, true);
        break;
    case SheetShape::Annulus:
        circle(d.radius, true);
        circle(d.innerRadius, false);
        break;
    case SheetShape::Outline: {
        const auto loopsInFrame = orientedOutline(d.outline);
        for (std::size_t l = 0; l < loopsInFrame.size(); ++l) {
            polygon(loopsInFrame[l], l == 0);
        }
        break;
    }
    }
    return loops;
}

DomainFoot footPoint(const DomainLoop& loop, const Vec2& p) {
    if (loop.circle) {
        const Vec2 away = unit(p - loop.centre);
        // Out of the sheet: away from the centre on the outer circle, towards it on a hole.
        return {loop.centre + away * loop.radius, loop.outer ? away : away * -1.0};
    }
    DomainFoot best;
    double bestDistance = std::numeric_limits<double>::infinity();
    const std::size_t n = loop.polygon.size();
    const std::size_t sides = loop.open ? n - 1 : n;
    for (std::size_t i = 0; i < sides && n > 1; ++i) {
        const Vec2& a = loop.polygon[i];
        const Vec2& b = loop.polygon[(i + 1) % n];
        const Vec2 side = b - a;
        const double length2 = dot2(side, side);
        // An open curve goes on along its end sides (their tangent lines).
        const double low = loop.open && i == 0 ? -std::numeric_limits<double>::infinity() : 0.0;
        const double high = loop.open && i + 2 == n ? std::numeric_limits<double>::infinity() : 1.0;
        const double t = length2 > 0.0 ? std::clamp(dot2(p - a, side) / length2, low, high) : 0.0;
        const Vec2 foot = a + side * t;
        const double distance = (p - foot).norm();
        if (distance < bestDistance) {
            bestDistance = distance;
            // Counter-clockwise outer loops and clockwise holes: the sheet lies left of each
            // side, so its right-hand normal points out of the sheet.
            const Vec2 outward = unit(Vec2(side.y, -side.x));
            Vec2 normal = outward;
            if (loop.smooth) {
                // Blended from the normals at the side's ends (each the mean of the sides
                // meeting there), continuous along the curve.
                auto sideNormal = [&loop, n](std::size_t k) {
                    const Vec2 d = loop.polygon[(k + 1) % n] - loop.polygon[k % n];
                    return unit(Vec2(d.y, -d.x));
                };
                const bool first = loop.open && i == 0;
                const bool last = loop.open && i + 2 == n;
                const Vec2 atA = first ? outward : unit(sideNormal(i + n - 1) + outward);
                const Vec2 atB = last ? outward : unit(sideNormal(i + 1) + outward);
                const double s = std::clamp(t, 0.0, 1.0);
                // The Gauss–Newton row uses this normal as its Jacobian (the tangent line):
                // the exact derivative of the blend converged worse (docs/tuning.md).
                normal = unit(atA * (1.0 - s) + atB * s);
            } else if ((t == 0.0 || t == 1.0) && distance > 0.0) {
                // Beyond a vertex the nearest point is the vertex itself: the normal is the
                // direction to p, signed like the sides meeting there.
                normal = unit(p - foot);
                if (dot2(normal, outward) < 0.0) {
                    normal = normal * -1.0;
                }
            }
            best = {foot, normal};
        }
    }
    return best;
}

std::optional<Vec2> domainPeriod(const SheetDomain& domain) {
    if (domain.shape != SheetShape::Cylinder) {
        return std::nullopt;
    }
    return turned(Vec2(2.0 * kPi * domain.radius, 0.0), domain.angle);
}

int periodShift(const Vec2& near, const Vec2& p, const std::optional<Vec2>& period) {
    if (!period) {
        return 0;
    }
    const double length2 = dot2(*period, *period);
    if (!(length2 > 0.0)) {
        return 0;
    }
    const double k = std::round(dot2(near - p, *period) / length2);
    return std::isfinite(k) ? static_cast<int>(k) : 0;
}

std::vector<Vec2> domainCorners(const SheetDomain& domain) {
    std::vector<Vec2> corners;
    for (const DomainLoop& loop : domainLoops(domain)) {
        const std::size_t n = loop.polygon.size();
        for (std::size_t i = 0; i < n; ++i) {
            const Vec2 in = loop.polygon[i] - loop.polygon[(i + n - 1) % n];
            const Vec2 out = loop.polygon[(i + 1) % n] - loop.polygon[i];
            const double turn = std::abs(std::atan2(cross2(in, out), dot2(in, out)));
            if (turn >= kCornerTurn) {
                corners.push_back(loop.polygon[i]);
            }
        }
    }
    return corners;
}

double domainArea(const SheetDomain& domain) {
    double area = 0.0;
    for (const DomainLoop& loop : domainLoops(domain)) {
        const double a =
            loop.circle ? kPi * loop.radius * loop.radius : std::abs(signedArea(loop.polygon));
        area += loop.outer ? a : -a;
    }
    return area;
}

namespace {

std::optional<Problem> shapeProblem(const SheetDomain& d) {
    auto problem = [](long long what) {
        Problem p = problemOf(ProblemCode::SheetDomainInvalid);
        p.count = what;
        return p;
    };
    auto usable = [](double v) { return std::isfinite(v) && v > 0.0; };
    if (!std::isfinite(d.centre.x) || !std::isfinite(d.centre.y) || !std::isfinite(d.angle)) {
        return problem(1);
    }
    switch (d.shape) {
    case SheetShape::Free:
        return std::nullopt;
    case SheetShape::Cylinder:
        return usable(d.radius) ? std::nullopt : std::optional(problem(1));
    case SheetShape::Rectangle:
        return usable(d.width) && usable(d.height) ? std::nullopt : std::optional(problem(1));
    case SheetShape::Disk:
        return usable(d.radius) ? std::nullopt : std::optional(problem(1));
    case SheetShape::Annulus:
        if (!usable(d.radius) || !usable(d.innerRadius)) {
            return problem(1);
        }
        return d.innerRadius < d.radius ? std::nullopt : std::optional(problem(2));
    case SheetShape::Outline:
        for (const auto& loop : d.outline) {
            for (const Vec2& p : loop) {
                if (!std::isfinite(p.x) || !std::isfinite(p.y)) {
                    return problem(1);
                }
            }
        }
        if (d.outline.empty() || d.outline.front().size() < 3 ||
            !(std::abs(signedArea(orientedOutline(d.outline).front())) > 0.0)) {
            return problem(3);
        }
        return std::nullopt;
    }
    return problem(1);
}

} // namespace

std::optional<Problem> domainProblem(const SheetDomain& d) {
    if (std::optional<Problem> problem = shapeProblem(d)) {
        return problem;
    }
    // Crease curves: finite points, two or more (three for a closed one), known indices.
    for (const SheetDomain::Curve& curve : d.creaseCurves) {
        bool finite = true;
        for (const Vec2& p : curve.points) {
            finite = finite && std::isfinite(p.x) && std::isfinite(p.y);
        }
        if (!finite || curve.points.size() < (curve.closed ? 3u : 2u)) {
            Problem p = problemOf(ProblemCode::SheetDomainInvalid);
            p.count = 4;
            return p;
        }
    }
    for (const auto& [edge, curve] : d.creaseCurveOf) {
        if (curve < 0 || static_cast<std::size_t>(curve) >= d.creaseCurves.size()) {
            Problem p = problemOf(ProblemCode::SheetDomainInvalid);
            p.count = 4;
            return p;
        }
    }
    return std::nullopt;
}

DomainAssignment assignToDomain(const SheetDomain& domain, const SampledMesh& mesh,
                                const std::vector<Vec2>& development) {
    DomainAssignment result;
    const std::vector<DomainLoop> loops = domainLoops(domain);
    if (loops.empty()) {
        return result;
    }
    const std::vector<std::vector<int>> boundary = developmentLoops(mesh, development);
    std::vector<std::pair<int, int>> candidates; // (vertex, domain loop)
    for (std::size_t l = 0; l < boundary.size(); ++l) {
        int target = -1;
        if (l == 0) {
            target = 0; // the outer loop comes first
        } else {
            // A hole of the development goes to the domain's hole it is nearest to on average.
            double best = std::numeric_limits<double>::infinity();
            for (std::size_t k = 1; k < loops.size(); ++k) {
                double sum = 0.0;
                for (int v : boundary[l]) {
                    const Vec2& p = development[static_cast<std::size_t>(v)];
                    sum += (footPoint(loops[k], p).point - p).norm();
                }
                if (sum < best) {
                    best = sum;
                    target = static_cast<int>(k);
                }
            }
        }
        if (target >= 0) {
            for (int v : boundary[l]) {
                candidates.emplace_back(v, target);
            }
        }
    }
    std::vector<bool> taken(candidates.size(), false);
    for (const Vec2& corner : domainCorners(domain)) {
        std::size_t nearest = candidates.size();
        double best = std::numeric_limits<double>::infinity();
        for (std::size_t i = 0; i < candidates.size(); ++i) {
            const double d =
                (development[static_cast<std::size_t>(candidates[i].first)] - corner).norm();
            if (!taken[i] && d < best) {
                best = d;
                nearest = i;
            }
        }
        if (nearest < candidates.size()) {
            taken[nearest] = true;
            result.atCorners.push_back({candidates[nearest].first, corner});
        }
    }
    for (std::size_t i = 0; i < candidates.size(); ++i) {
        if (!taken[i]) {
            result.onLoops.push_back({candidates[i].first, candidates[i].second});
        }
    }
    return result;
}

SheetDomain placeDomain(SheetDomain domain, const SampledMesh& mesh,
                        const std::vector<Vec2>& development) {
    const std::vector<std::vector<int>> boundary = developmentLoops(mesh, development);
    if (domain.isFree() || domain.shape == SheetShape::Cylinder || boundary.empty()) {
        return domain; // a cylinder's period is the development's own, wherever it lies
    }
    const std::vector<Vec2> outer = pointsOf(boundary.front(), development);
    const Vec2 centroid = centroidOf(outer);
    domain.angle = 0.0;
    domain.centre = centroid;
    if (domain.shape == SheetShape::Disk || domain.shape == SheetShape::Annulus) {
        return domain;
    }
    // The frame's origin such that the shape's own centroid lands on the development's.
    const Vec2 own = domain.shape == SheetShape::Outline
                         ? centroidOf(orientedOutline(domain.outline).front())
                         : Vec2();
    auto placedAt = [&](double angle) {
        SheetDomain d = domain;
        d.angle = angle;
        d.centre = centroid - turned(own, angle);
        return d;
    };
    auto cost = [&](double angle) {
        const std::vector<DomainLoop> loops = domainLoops(placedAt(angle));
        double sum = 0.0;
        for (const Vec2& p : outer) {
            const double d = distanceToLoops(loops, p);
            sum += d * d;
        }
        return sum;
    };
    // A search over whole degrees, then a golden-section refinement around the best.
    double bestAngle = 0.0;
    double bestCost = std::numeric_limits<double>::infinity();
    for (int degree = 0; degree < 360; ++degree) {
        const double angle = degree * kPi / 180.0;
        const double c = cost(angle);
        if (c < bestCost) {
            bestCost = c;
            bestAngle = angle;
        }
    }
    double lo = bestAngle - kPi / 180.0;
    double hi = bestAngle + kPi / 180.0;
    const double ratio = 0.5 * (std::sqrt(5.0) - 1.0);
    for (int i = 0; i < 60; ++i) {
        const double a = hi - ratio * (hi - lo);
        const double b = lo + ratio * (hi - lo);
        if (cost(a) <= cost(b)) {
            hi = b;
        } else {
            lo = a;
        }
    }
    const double refined = 0.5 * (lo + hi);
    return placedAt(cost(refined) < bestCost ? refined : bestAngle);
}

SheetDomain fittingDomain(SheetShape shape, const SampledMesh& mesh,
                          const std::vector<Vec2>& development) {
    SheetDomain domain;
    const std::vector<std::vector<int>> boundary = developmentLoops(mesh, development);
    if (boundary.empty() || shape == SheetShape::Free || shape == SheetShape::Outline ||
        shape == SheetShape::Cylinder) {
        return domain;
    }
    domain.shape = shape;
    const std::vector<Vec2> outer = pointsOf(boundary.front(), development);
    domain.centre = centroidOf(outer);
    if (shape == SheetShape::Rectangle) {
        // The smallest-area box over the hull's edge directions (one of them is optimal).
        const std::vector<Vec2> hull = pattern::convexHull(outer);
        double bestArea = std::numeric_limits<double>::infinity();
        for (std::size_t i = 0; i < hull.size(); ++i) {
            const Vec2 side = hull[(i + 1) % hull.size()] - hull[i];
            const double angle = std::atan2(side.y, side.x);
            Vec2 low(std::numeric_limits<double>::infinity(),
                     std::numeric_limits<double>::infinity());
            Vec2 high = low * -1.0;
            for (const Vec2& p : hull) {
                const Vec2 q = turned(p, -angle);
                low = {std::min(low.x, q.x), std::min(low.y, q.y)};
                high = {std::max(high.x, q.x), std::max(high.y, q.y)};
            }
            const double area = (high.x - low.x) * (high.y - low.y);
            if (area < bestArea) {
                bestArea = area;
                domain.width = high.x - low.x;
                domain.height = high.y - low.y;
                domain.angle = angle;
                domain.centre = turned((low + high) * 0.5, angle);
            }
        }
        return domain;
    }
    // The circles go through the design's own vertices on its loops (its farthest, its
    // nearest), not through the samples between them: a spline rim through points on a circle
    // dips off it between them, and circles fitted to the dips would leave those vertices off
    // the sheet, where pins on them keep every solve short of the tolerance. The next solve
    // moves the samples onto the circles.
    auto distances = [&](const std::vector<int>& loop) {
        std::vector<double> atVertices;
        std::vector<double> all;
        for (int v : loop) {
            const double d = (development[static_cast<std::size_t>(v)] - domain.centre).norm();
            all.push_back(d);
            if (static_cast<std::size_t>(v) < mesh.coarseVertexIds.size()) {
                atVertices.push_back(d);
            }
        }
        return atVertices.empty() ? all : atVertices;
    };
    for (double d : distances(boundary.front())) {
        domain.radius = std::max(domain.radius, d);
    }
    if (shape == SheetShape::Annulus) {
        domain.innerRadius = std::numeric_limits<double>::infinity();
        for (std::size_t l = 1; l < boundary.size(); ++l) {
            for (double d : distances(boundary[l])) {
                domain.innerRadius = std::min(domain.innerRadius, d);
            }
        }
        if (!(domain.innerRadius < domain.radius) || !(domain.innerRadius > 0.0)) {
            domain.innerRadius = 0.5 * domain.radius;
        }
    }
    return domain;
}

double developedArea(const SampledMesh& mesh, const std::vector<Vec2>& development) {
    double area = 0.0;
    for (const std::vector<int>& face : mesh.faces) {
        area += std::abs(signedArea(pointsOf(face, development)));
    }
    return area;
}

double largestDomainGap(const SheetDomain& domain, const SampledMesh& mesh,
                        const std::vector<Vec2>& development) {
    const std::vector<DomainLoop> loops = domainLoops(domain);
    const DomainAssignment held = assignToDomain(domain, mesh, development);
    double gap = 0.0;
    for (const DomainAssignment::OnLoop& on : held.onLoops) {
        const Vec2& p = development[static_cast<std::size_t>(on.vertex)];
        gap = std::max(gap,
                       (footPoint(loops[static_cast<std::size_t>(on.loop)], p).point - p).norm());
    }
    for (const DomainAssignment::AtCorner& at : held.atCorners) {
        gap = std::max(gap, (development[static_cast<std::size_t>(at.vertex)] - at.corner).norm());
    }
    return gap;
}

std::vector<std::vector<Vec2>> closedLoopsFromAbove(const std::vector<ReferenceCurve>& curves) {
    std::vector<std::vector<Vec2>> loops;
    for (const ReferenceCurve& curve : curves) {
        const std::vector<Vec3>& p = curve.points;
        double length = 0.0;
        for (std::size_t i = 1; i < p.size(); ++i) {
            length += distance(p[i - 1], p[i]);
        }
        if (p.size() < 4 || !(distance(p.front(), p.back()) <= 1e-6 * length)) {
            continue;
        }
        std::vector<Vec2> loop;
        for (std::size_t i = 0; i + 1 < p.size(); ++i) {
            loop.emplace_back(p[i].x, p[i].y);
        }
        loops.push_back(std::move(loop));
    }
    return loops;
}

} // namespace devsurf::model
