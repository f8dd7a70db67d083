#pragma once

// The crease conditions of a design (docs/math.md §5, paper §3.3) as rows of the
// guided-projection problem.

#include "model/bspline_curve.h"
#include "model/composite_surface.h"
#include "model/strip.h"
#include "solver/core/bilinear_term.h"
#include "solver/core/bisector_term.h"
#include "solver/core/problem.h"
#include "solver/core/unit_norm_term.h"

#include <map>
#include <vector>

namespace devsurf::solver {

// The normal spline of one strip as the formulation holds it: its control normals start at
// state offset `offset` (3 values each); `curve` (any control points) gives evaluation rows in
// the strip's parameter u.
struct StripNormalSpline {
    int offset = 0;
    model::BSplineCurve curve;
};

// The variables "straight when unfolded" needs: a unit normal n_o of the crease's osculating
// plane per collocation value, a block "osculatingNormals" appended to `problem` (its start values
// written into `state`, which is resized to the problem's variable count), |n_o| = 1 in
// `unitNormals`.
struct OsculatingNormals {
    Problem& problem;
    std::vector<double>& state;
    UnitNormTerm& unitNormals;
};

// The rows of the crease conditions: curved folds and geodesics in `bisector`, "straight when
// unfolded" in `straight`; the face of every row (the crease's left strip) in the matching
// vector.
struct CreaseConditionTerms {
    BisectorTerm& bisector;
    std::vector<model::FaceId>& bisectorFaces;
    BilinearTerm& straight;
    std::vector<model::FaceId>& straightFaces;
};

// Adds the rows of every crease whose condition is a curved fold (7), a geodesic (8) or
// "straight when unfolded" (docs/math.md §5):
//   curved fold: ⟨c²₀ − c²₁, n̂_L + n̂_R⟩ = ⟨c²₁ − c²₂, n̂_L + n̂_R⟩ = 0,
//   geodesic:    the same with n̂_L − n̂_R,
//   straight:    ⟨c²₀ − c²₁, n_o⟩ = ⟨c²₁ − c²₂, n_o⟩ = ⟨n_L, n_o⟩ = 0, |n_o| = 1 (n_L lies in the
//                osculating plane: the crease is a geodesic of its left strip, so it unfolds
//                to a straight line),
// with c²ₖ the second-derivative points of the crease at `valuesPerInterval` parameters per
// spline interval and n_L, n_R the two strips' normal splines there, oriented to the same side
// of the surface (model::creasesOf), n̂ their directions. A fold or geodesic row is
// ⟨d, w_L n_L ± w_R n_R⟩ (BisectorTerm) with the weights taken from the two normals' lengths
// at the reference state, or 1 during drags (FormulationOptions::weighCreaseNormals): the
// normal splines have unit length at u = 0 only. `edgePoints` gives, for every S-edge, the state
// offsets of its control points in the edge's stored orientation. Returns the number of rows added.
//
// Throws std::invalid_argument with a sentence naming the edge when a condition cannot be
// imposed: it is not on a crease between two strips (a boundary curve, a cone or a planar
// face beside it), or the curve's degree is below 2 (no second derivative).
int addCreaseConditions(const model::CompositeSurface& surface,
                        const std::vector<model::Strip>& strips,
                        const std::map<model::FaceId, StripNormalSpline>& normals,
                        const std::map<model::EdgeId, std::vector<int>>& edgePoints,
                        int valuesPerInterval, CreaseConditionTerms& terms,
                        const OsculatingNormals& osculating);

} // namespace devsurf::solver
