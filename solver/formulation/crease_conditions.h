#pragma once

// The crease conditions of a design (docs/math.md §5, paper §3.3) as rows of the
// guided-projection problem.

#include "model/bspline_curve.h"
#include "model/composite_surface.h"
#include "model/strip.h"
#include "solver/core/bilinear_term.h"

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

// Adds the rows of every crease whose condition is a curved fold (7) or a geodesic (8):
//   curved fold: ⟨c²₀ − c²₁, n_L + n_R⟩ = ⟨c²₁ − c²₂, n_L + n_R⟩ = 0,
//   geodesic:    the same with n_L − n_R,
// with c²ₖ the second-derivative points of the crease at `valuesPerInterval` parameters per
// spline interval and n_L, n_R the two strips' normal splines there, oriented to the same side
// of the surface (model::creasesOf). `edgePoints` gives, for every S-edge, the state offsets of
// its control points in the edge's stored orientation. Every row's face (the left strip) is
// appended to `rowFaces`. Returns the number of rows added.
//
// Throws std::invalid_argument with a sentence naming the edge when a condition cannot be
// imposed: it is not on a crease between two strips (a boundary curve, a cone or a planar
// face beside it), or the curve's degree is below 2 (no second derivative), or the condition is
// "straight when unfolded", which the solver does not impose yet.
int addCreaseConditions(const model::CompositeSurface& surface,
                        const std::vector<model::Strip>& strips,
                        const std::map<model::FaceId, StripNormalSpline>& normals,
                        const std::map<model::EdgeId, std::vector<int>>& edgePoints,
                        int valuesPerInterval, BilinearTerm& term,
                        std::vector<model::FaceId>& rowFaces);

} // namespace devsurf::solver
