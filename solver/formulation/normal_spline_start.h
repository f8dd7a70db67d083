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
// converged better (measured from 0.1 % noise on the cylinder: det 5e-15 against 2e-6 in the
// exact space).
model::SplineSpace normalSplineSpace(const model::SplineSpace& curves, bool exact);

// A strip that is not developable at the start gets the least-squares fit of its unit normals
// N/|N| at the samples in its normal spline's space, unless they are noisy (and the caller asks
// for it: sessions do, FormulationOptions::linearNoisyStartNormals): where that fit misses
// them by kNoisyStartNormals or more (root mean square of the difference, about an angle in rad),
// the best linear field p + u q to them is fitted instead (linear fields lie in every spline
// space). The noise of a rough start grows in the curves' derivatives, and the first step then
// had to turn normals that zig-zag along the strip: it overshot (the annulus from 1 % of its
// diameter: largest residual 0.8 → 3.4, most of it the normal splines' unit rows) and the next
// five iterations recovered. A strip that really bends has normals the spline fits closely
// (the curved fold of tst_crease_conditions: misfit 0.002; the annulus from 1 %: 0.08 on average,
// up to 0.25). Measured with devsurf-bench --study MODEL --session (10 seeds, 10 iterations),
// det worst without → with: the annulus from 1 % of its diameter 3.8e-4 → 9.9e-11 (every seed
// within 1e-8; rulings 0.34 → 0.38; over 40 seeds 0.81 → 1.1e-3, fold-overs in 4 → 1 seeds);
// the other examples, fig6, fig8 and Fig. 13 from 10 % edge noise and 1 % at most 2.1e-10 as
// before, their creases folding no more. Limits of 0.03 and 0.06: the annulus at 9.2e-11 and
// 8.7e-9; 0.02: Fig. 13's creases folded 1.06 times the start's noise (0.40 before); 0.01:
// fig6's 0.90 (0.28). A linear field for every strip whose sampled normals merely turned
// quickly (second differences, threshold 0.02) failed 10 of 20 seeds of that curved fold from
// 0.2 %. Smoothing splines (second differences of the control normals at weight 10 … 1e6)
// left the annulus at 7.5e-4 … 1.9e-7.
inline constexpr double kNoisyStartNormals = 0.04;
// The linear field is used only where it stays this far from zero on [0, 1] (where the sampled
// normals spread by more than about 150°). 0.5 kept the noisy fit on strips that needed the
// linear one: the annulus from 1 % at 6.4e-3.
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
