// The fig12 example: a ring folded along concentric closed creases, exactly (after the paper's
// Fig. 12, whose creases are circles: held to circles, such folds are conjectured not to exist
// exactly, §5).
//
// A cone with its apex at the origin whose generators' directions γ(t) run a closed curve of
// length 2π on the unit sphere is isometric to the plane around its apex: the point at
// distance ρ along the generator at arc length σ of γ unfolds to polar (ρ, σ). Above the
// equator γ must wave to be that long: γ(t) = (cos θ cos t, cos θ sin t, sin θ) with the
// latitude θ(t) = θ₀ + a cos(lobes·t). Folding the cone at horizontal planes z = c_j
// reflects the rest of the sheet in each plane in turn: both sides of each crease are mirror
// images (a curved fold), every band stays a piece of the cone, and the whole stays
// isometric to the flat ring. Crease j is the cone's section by z = c_j: in the sheet
// r = c_j / sin θ, every crease a scaled copy of one wavy closed curve about the centre. The
// rims are two more such copies, so that every strip is exactly a piece of the cone with
// cubic splines (a circle in the sheet, r = const, is not: its band would be developable only
// to the splines' accuracy, and Solve does not converge from there).

#include "example_shapes.h"

#include "bspline_curve.h"
#include "development.h"
#include "model/math_constants.h"
#include "sampled_mesh.h"
#include "sheet_domain.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <map>

namespace devsurf::model::example_shapes {

namespace {

constexpr int kPleatLobes = 8;
constexpr double kPleatAmplitude = 0.1; // a, radians
constexpr int kPleatSectorsPerLobe = 4;
constexpr double kPleatInnerRadius = 100.0; // the sheet's hole at its narrowest, mm
constexpr double kPleatOuterRadius = 250.0; // the sheet at its widest, mm

struct LobedCone {
    double base = 0.0; // θ₀
    double latitude(double t) const { return base + kPleatAmplitude * std::cos(kPleatLobes * t); }
    Vec3 direction(double t) const {
        const double theta = latitude(t);
        return {std::cos(theta) * std::cos(t), std::cos(theta) * std::sin(t), std::sin(theta)};
    }
    // γ / sin θ: the generator's point at height 1. Crease j is c_j times this curve.
    Vec3 atUnitHeight(double t) const { return direction(t) / std::sin(latitude(t)); }
    double speed(double t) const {
        const double theta = latitude(t);
        const double slope = -kPleatAmplitude * kPleatLobes * std::sin(kPleatLobes * t);
        return std::sqrt(std::cos(theta) * std::cos(theta) + slope * slope);
    }
    // Arc length of γ from 0 to t ≥ 0: 5-point Gauss–Legendre on pieces of a fixed width, 64
    // to a lobe, and on the last part piece (so that it is smooth in t, for Newton).
    double length(double t) const {
        static constexpr double nodes[5] = {-0.9061798459386640, -0.5384693101056831, 0.0,
                                            0.5384693101056831, 0.9061798459386640};
        static constexpr double weights[5] = {0.2369268850561891, 0.4786286704993665,
                                              0.5688888888888889, 0.4786286704993665,
                                              0.2369268850561891};
        auto piece = [&](double from, double width) {
            double sum = 0.0;
            for (int q = 0; q < 5; ++q) {
                sum += weights[q] * speed(from + 0.5 * width * (1.0 + nodes[q]));
            }
            return 0.5 * width * sum;
        };
        const double width = 2.0 * kPi / (kPleatLobes * 64);
        const int whole = static_cast<int>(std::floor(t / width));
        double sum = 0.0;
        for (int p = 0; p < whole; ++p) {
            sum += piece(p * width, width);
        }
        return sum + piece(whole * width, t - whole * width);
    }
    // The parameters cutting γ into `parts` of equal arc length (Newton on the arc length).
    std::vector<double> equalArcs(int parts) const {
        const double total = length(2.0 * kPi);
        std::vector<double> ends(static_cast<std::size_t>(parts) + 1);
        for (int i = 0; i <= parts; ++i) {
            const double sigma = total * i / parts;
            double t = 2.0 * kPi * i / parts;
            for (int k = 0; k < 50; ++k) {
                const double step = (length(t) - sigma) / speed(t);
                t -= step;
                if (std::abs(step) < 1e-15) {
                    break;
                }
            }
            ends[static_cast<std::size_t>(i)] = t;
        }
        return ends;
    }
};

// The unit tangent of `curve` at u: central differences extrapolated (Richardson), to ~1e-13,
// so that the solver's tangent continuity at the vertices holds as built (a one-sided
// difference left it at 2.9e-6, and Solve ran all its iterations).
Vec3 unitTangent(const std::function<Vec3(double)>& curve, double u) {
    const double h = 1e-3;
    const Vec3 wide = (curve(u + h) - curve(u - h)) / (2.0 * h);
    const Vec3 narrow = (curve(u + 0.5 * h) - curve(u - 0.5 * h)) / h;
    const Vec3 tangent = (narrow * 4.0 - wide) / 3.0;
    return tangent / tangent.norm();
}

// The crease curve at unit height as splines, one per sector (control points in the plane
// z = 1, so that c_j times it lies in the fold plane z = c_j), and the rays of its samples as the
// sampled mesh takes them: `samples` to a sector, around once.
struct UnitCrease {
    std::vector<std::vector<Vec3>> sectors;
    std::vector<BSplineCurve> splines;  // of `sectors`
    std::vector<Vec3> sampleDirections; // the first not repeated at the end
    std::vector<double> rayTurn;        // the angle from the first ray, along the fan
    double turn = 0.0;                  // around once, back to the first
    int samples = 0;
};

UnitCrease unitCrease(const LobedCone& cone, const SplineSpace& space, int sectors) {
    UnitCrease crease;
    const std::vector<double> ends = cone.equalArcs(sectors);
    crease.samples = space.intervals * kDevelopmentSamplesPerInterval;
    for (int i = 0; i < sectors; ++i) {
        const double t0 = ends[static_cast<std::size_t>(i)];
        const double t1 = ends[static_cast<std::size_t>(i) + 1];
        auto curve = [&](double u) { return cone.atUnitHeight(t0 + u * (t1 - t0)); };
        crease.sectors.push_back(
            alongEndTangents(controlPointsThrough(space, curve(0.0), curve(1.0), curve),
                             unitTangent(curve, 0.0), unitTangent(curve, 1.0)));
        crease.splines.push_back(BSplineCurve::uniform(space, crease.sectors.back()));
        for (int k = 0; k < crease.samples; ++k) {
            const Vec3 p = crease.splines.back().evaluate(static_cast<double>(k) / crease.samples);
            crease.sampleDirections.push_back(p / p.norm());
        }
    }
    const std::size_t n = crease.sampleDirections.size();
    for (std::size_t k = 0; k < n; ++k) {
        crease.rayTurn.push_back(crease.turn);
        crease.turn +=
            angleBetween(crease.sampleDirections[k], crease.sampleDirections[(k + 1) % n]);
    }
    return crease;
}

} // namespace

// The pleated ring: `rings` bands between rings − 1 creases and two rims, all scaled copies of
// one crease about the apex, 8 lobes, 4 sectors to a lobe. θ₀ is chosen so that the rays of
// the curves' samples turn through exactly 2π: every band, a fan of planar quads between two
// scaled copies of one spline, then unfolds into a closed ring exactly. (Sampled more finely,
// the splines turn through a little more, 0.004 rad: the cutting pattern is laid onto the kept
// sheet.) Its sheet is that ring, an annulus whose circles wave with the lobes, from
// kPleatInnerRadius to kPleatOuterRadius at their extremes, held as an outline so that the
// rulings and creases can move in it. Three vertices of the inner rim are pinned.
CompositeSurface makeFig12(int rings) {
    const int sectors = kPleatLobes * kPleatSectorsPerLobe;
    const SplineSpace space{3, 2, 3};
    LobedCone cone;
    UnitCrease unit;
    double low = kPleatAmplitude; // above the equator everywhere
    double high = 0.5 * kPi - kPleatAmplitude;
    for (int i = 0; i < 60; ++i) {
        cone.base = 0.5 * (low + high);
        unit = unitCrease(cone, space, sectors);
        (unit.turn > 2.0 * kPi ? low : high) = cone.base;
    }

    // The heights c_0 … c_rings of the rims and creases on the unfolded cone, evenly spaced:
    // the inner rim reaches in to kPleatInnerRadius, the outer out to kPleatOuterRadius.
    double nearest = std::numeric_limits<double>::infinity();
    double farthest = 0.0;
    for (const BSplineCurve& spline : unit.splines) {
        for (int k = 0; k <= 60; ++k) {
            const double rho = spline.evaluate(k / 60.0).norm();
            nearest = std::min(nearest, rho);
            farthest = std::max(farthest, rho);
        }
    }
    const double first = kPleatInnerRadius / nearest;
    const double last = kPleatOuterRadius / farthest;
    std::vector<double> heights;
    for (int j = 0; j <= rings; ++j) {
        heights.push_back(first + (last - first) * j / rings);
    }
    // The folded height of unfolded height z: slope +1, −1, +1, … between the creases.
    auto foldedHeight = [&](double z) {
        double folded = 0.0;
        double below = 0.0;
        double sign = 1.0;
        for (int j = 1; j < rings && z > heights[static_cast<std::size_t>(j)]; ++j) {
            folded += sign * (heights[static_cast<std::size_t>(j)] - below);
            below = heights[static_cast<std::size_t>(j)];
            sign = -sign;
        }
        return folded + sign * (z - below);
    };
    // Curve j of sector i: heights[j] times the unit crease, folded (the crease lies in its
    // fold plane, so both bands beside it agree on it).
    auto curvePoints = [&](int j, int i) {
        std::vector<Vec3> points;
        for (const Vec3& p : unit.sectors[static_cast<std::size_t>(i)]) {
            const Vec3 q = p * heights[static_cast<std::size_t>(j)];
            points.emplace_back(q.x, q.y, foldedHeight(q.z));
        }
        return points;
    };

    CompositeSurface s;
    s.setName("fig12");
    std::vector<std::vector<VertexId>> grid(rings + 1, std::vector<VertexId>(sectors));
    for (int j = 0; j <= rings; ++j) {
        for (int i = 0; i < sectors; ++i) {
            grid[j][i] = s.addVertex(curvePoints(j, i).front());
        }
    }
    for (int j = 0; j < rings; ++j) {
        for (int i = 0; i < sectors; ++i) {
            const int next = (i + 1) % sectors;
            s.addFace({grid[j][i], grid[j + 1][i], grid[j + 1][next], grid[j][next]});
        }
    }
    std::map<EdgeId, int> sectorOf;
    for (int j = 0; j <= rings; ++j) {
        for (int i = 0; i < sectors; ++i) {
            const int next = (i + 1) % sectors;
            std::vector<Vec3> points = curvePoints(j, i);
            points.back() = s.position(grid[j][next]); // the same point, bit for bit
            const EdgeId edge = s.setSpline(grid[j][i], grid[j][next], space, points);
            sectorOf[edge] = i;
            if (j > 0 && j < rings) {
                s.setCreaseCondition(edge, CreaseCondition::CurvedFold);
            }
        }
    }

    for (int k = 0; k < 3; ++k) {
        s.setPinned(grid[0][k * sectors / 3], true);
    }

    // The development: every sample lies on a ray of the fan (sample k of sector i's curves on
    // ray i · samples + k), at its distance from the apex on the unfolded cone, turned by the
    // angle its ray makes in the fan (scaled by what the bisection left of 2π − turn, a few
    // 1e-12, so that it closes exactly).
    const SampledMesh mesh = sampleSurface(s, kDevelopmentSamplesPerInterval);
    const std::size_t rays = unit.sampleDirections.size();
    auto place = [&](double turned, double rho) {
        const double angle = turned * (2.0 * kPi / unit.turn);
        return Vec2(rho * std::cos(angle), rho * std::sin(angle));
    };
    std::vector<Vec2> development(mesh.vertices.size());
    for (const SampledMesh::Polyline& line : mesh.splineEdges) {
        for (std::size_t k = 0; k < line.vertices.size(); ++k) {
            const std::size_t ray =
                (static_cast<std::size_t>(sectorOf.at(line.edge) * unit.samples) + k) % rays;
            const Vec3& d = unit.sampleDirections[ray];
            const Vec3& p = mesh.vertices[static_cast<std::size_t>(line.vertices[k])];
            development[static_cast<std::size_t>(line.vertices[k])] =
                place(unit.rayTurn[ray], std::hypot(p.x, p.y) / std::hypot(d.x, d.y));
        }
    }
    s.setKeepsDevelopment(true);
    s.setDevelopment(development);

    // The sheet: the rims as its outline, through their samples (so that these lie on it
    // exactly) and 7 points between each two, where the rim's ray lies between theirs.
    const int between = 8;
    SheetDomain sheet;
    sheet.shape = SheetShape::Outline;
    for (int j : {rings, 0}) {
        const double height = heights[static_cast<std::size_t>(j)];
        std::vector<Vec2> loop;
        for (std::size_t k = 0; k < rays; ++k) {
            const BSplineCurve& spline = unit.splines[k / static_cast<std::size_t>(unit.samples)];
            const Vec3& d0 = unit.sampleDirections[k];
            const Vec3& d1 = unit.sampleDirections[(k + 1) % rays];
            const double step = angleBetween(d0, d1);
            loop.push_back(place(unit.rayTurn[k], height / d0.z));
            for (int m = 1; m < between; ++m) {
                const double u = (static_cast<double>(k % static_cast<std::size_t>(unit.samples)) +
                                  static_cast<double>(m) / between) /
                                 unit.samples;
                const Vec3 p = spline.evaluate(u) * height;
                const Vec3 d = p / p.norm();
                const double before = angleBetween(d0, d);
                const double share = before / (before + angleBetween(d, d1));
                loop.push_back(place(unit.rayTurn[k] + share * step, p.norm()));
            }
        }
        sheet.outline.push_back(std::move(loop));
    }
    s.setSheetDomain(placeDomain(sheet, mesh, development));
    return s;
}

} // namespace devsurf::model::example_shapes
