#pragma once

// A strip trimmed back where it overhangs its reference shape. A strip laid over a patch of the
// shape and pulled towards it covers a rectangle of its parameters; where the patch is not a
// rectangle, or the shape ends or turns away, its corners and sides stand off the shape, and
// those make most of the largest distances surface → target. Trimming them leaves the part
// that lies on the shape (docs/tuning.md, "Strips trimmed where they overhang").

#include "model/composite_surface.h"
#include "model/reference/point_index.h"
#include "model/vec3.h"

#include <optional>
#include <vector>

namespace devsurf::model::reference {

// How far a point is off a reference shape given as points thinned at spacing ρ with a normal
// each: from the nearest point, the distance along its normal, and sideways only what exceeds
// ρ (a point over the gap between thinned points is on the shape, not ρ / 2 off it).
class OverhangMeasure {
public:
    // Throws std::invalid_argument if there are no points, the normals are not one per point
    // or ρ is not a finite number ≥ 0.
    OverhangMeasure(std::vector<Vec3> points, std::vector<Vec3> normals, double rho);

    double operator()(const Vec3& p) const;

private:
    PointIndex m_index;
    std::vector<Vec3> m_normals;
    double m_rho = 0.0;
};

// The part of a strip's parameters to keep: u along its curves from u0 to u1, and across them
// (w, the rulings' v from a to b) from a line w0 to a line w1, each given at u0 (index 0) and
// u1 (index 1). A quadrilateral rather than a rectangle, so that a corner standing off the
// shape is cut without the rest of its sides.
struct StripTrim {
    double u0 = 0.0;
    double u1 = 1.0;
    double w0[2] = {0.0, 0.0};
    double w1[2] = {1.0, 1.0};

    bool trims() const {
        return u0 > 0.0 || u1 < 1.0 || w0[0] > 0.0 || w0[1] > 0.0 || w1[0] < 1.0 || w1[1] < 1.0;
    }
    // At t in [0, 1] from u0 to u1: u, and the lines' w.
    double u(double t) const { return u0 + (u1 - u0) * t; }
    double low(double t) const { return w0[0] + (w0[1] - w0[0]) * t; }
    double high(double t) const { return w1[0] + (w1[1] - w1[0]) * t; }
    // The share of the parameter square kept.
    double kept() const { return (u1 - u0) * 0.5 * (high(0.0) - low(0.0) + high(1.0) - low(1.0)); }
};

// The trim's steps: 1 / kTrimStepsAlong of u, 1 / kTrimStepsAcross of w; its lines are judged
// at kTrimSamples points each; at least kTrimKeep of u, and of w at both ends, stays.
inline constexpr int kTrimStepsAlong = 32;
inline constexpr int kTrimStepsAcross = 16;
inline constexpr int kTrimSamples = 33;
inline constexpr double kTrimKeep = 0.25;

// The trim of a surface made of one strip (one SRSR face), cut back one step at a time: of
// the six cuts (either end along u, either line at either end across), the one whose sliver
// stands off the shape most on average, while that mean exceeds `tolerance` (mm). A side
// which overhangs at a corner only is so cut at that corner. nullopt for any other surface.
std::optional<StripTrim> overhangTrim(const CompositeSurface& surface,
                                      const OverhangMeasure& overhang, double tolerance);

// The surface of one strip cut to `trim`: its curves a and b replaced by s(u, low) and
// s(u, high) for u from u0 to u1, fitted by least squares in their spline spaces. Exact where
// only w is trimmed, evenly (the rulings stay); otherwise the fit is close but not exactly
// developable, so a Solve should follow. Throws std::invalid_argument for a surface that is
// not one strip or a trim outside [0, 1] or empty.
CompositeSurface trimmedStrip(const CompositeSurface& surface, const StripTrim& trim);

} // namespace devsurf::model::reference
