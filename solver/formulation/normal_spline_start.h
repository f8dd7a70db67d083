#pragma once

#include "model/bspline_curve.h"
#include "model/spline_space.h"
#include "model/strip.h"

#include <vector>

namespace devsurf::solver {

// An initial unit normal of a strip at u: a′ × (b − a), which points to the side the face
// loop orients (stripOfFace runs a along the loop and b against it), so neighbouring strips
// start consistently oriented (docs/math.md §2, §5). A collapsed ruling (SRS end) uses a′ × b′.
model::Vec3 initialStripNormal(const model::Strip& strip, double u);

// The largest normalised det(a − b, a′, b′) at which isDevelopableStart holds by default.
inline constexpr double kDevelopableStartLimit = 1e-9;

// True if the strip's normalised det(a − b, a′, b′) is at most `limit` at 50 values per knot
// interval (cones: always).
bool isDevelopableStart(const model::Strip& strip, double limit = kDevelopableStartLimit);

// The space of a strip's normal spline, for curves in `curves` = S(m, k, n). Exact: N = a′ × (b −
// a) of curves in S(m, k, n) lies in S(2m − 1, k − 1, n), so every developable strip of the design
// space (with N ≠ 0) has a representable normal and a valid design satisfies (4) exactly as it
// is. The cubic C² space of the paper cannot represent, e.g., the normal of a generalised
// cylinder over a C² cubic, so the solver had to move such designs. A strip that is not
// developable at the start gets the cubic C² space (`exact` false): from rough starts it
// converges better (docs/tuning.md).
model::SplineSpace normalSplineSpace(const model::SplineSpace& curves, bool exact);

// A strip that is not developable at the start gets the least-squares fit of its unit normals
// N/|N| at the samples in its normal spline's space, unless they are noisy (and the caller asks
// for it: sessions do, FormulationOptions::linearNoisyStartNormals): where that fit misses
// them by kNoisyStartNormals or more (root mean square of the difference, about an angle in rad),
// the best linear field p + u q to them is fitted instead (linear fields lie in every spline
// space). The noise of a rough start grows in the curves' derivatives, and a first step that
// has to turn normals zig-zagging along the strip overshoots; a strip that really bends has
// normals the spline fits closely. The limit and the alternatives tried: docs/tuning.md.
inline constexpr double kNoisyStartNormals = 0.04;
// The linear field is used only where it stays this far from zero on [0, 1] (where the sampled
// normals spread by more than about 150°; docs/tuning.md).
inline constexpr double kLinearStartNormalMinimum = 0.25;

// Initial control normals of a strip's normal spline `normalCurve` (its space; its control
// points are ignored), fitted by least squares to N(u) = a′ × (b − a) at `samples`, whose
// last two values must be u = 0 and u = 1 (an exact fit of N is scaled to |n(0)| = 1, only
// if the strip is `developable`: isDevelopableStart(strip), which the caller has at hand).
// `linearIfNoisy`: noisy unit normals get their best linear field (kNoisyStartNormals).
std::vector<model::Vec3> fitStartNormals(const model::Strip& strip,
                                         const model::BSplineCurve& normalCurve,
                                         const std::vector<double>& samples, bool developable,
                                         bool linearIfNoisy);

} // namespace devsurf::solver
