#pragma once

// Vertex developability (docs/math.md §7): at an interior vertex where creases meet, the angles
// between consecutive edges leaving it sum to 2π.

#include "model/composite_surface.h"
#include "solver/core/minimum_length_term.h"
#include "solver/core/problem.h"
#include "solver/core/squared_distance_term.h"
#include "solver/formulation/surface_formulation.h"

#include <map>
#include <vector>

namespace devsurf::solver {

// For every star of creaseVertexStars (the vertex v and the points cᵢ that span its edges'
// tangents, in cyclic order), a flat copy: 2D points v̄, c̄ᵢ in a block "vertexStars" appended to
// `problem`, and the isometry conditions (12) of every triangle (v, cᵢ, cᵢ₊₁), cyclically closed,
// normalised by the squared reference length of the pair:
//   (‖v̄ − c̄ᵢ‖² − ‖v − cᵢ‖²) / |v − cᵢ|²_ref = 0,  (‖c̄ᵢ − c̄ᵢ₊₁‖² − ‖cᵢ − cᵢ₊₁‖²) / |cᵢ − cᵢ₊₁|²_ref
//   = 0.
// Such a copy exists iff the angles sum to 2π (or the star folds over itself). The copy starts
// with the triangles laid out around v̄ with the start's angles and lengths, so it closes exactly
// where the sum is 2π. `vertexOffsets` and `edgeOffsets` give the state offsets of the vertices
// and of every S-edge's control points (stored orientation); `state` holds their start values and
// is resized to the problem's variable count. Stars with a vanishing spoke or rim get no rows.
// `term` must have left dimension 2 and right dimension 3. A spoke that shrinks to a point
// satisfies its rows without closing the star (its angles are then undefined): `guard` gets a row
// keeping every spoke at least `spokeGuard` times its start length (inactive while it is).
//
// A star of four spokes through which a crease passes (spokes i and i + 2 both S-edges) and
// does so almost straight (they leave the vertex within `smoothCreaseAngle` radians of opposite
// directions in `state`; a crease without a condition within vertexSmoothPlainCreaseAngle, if
// that is smaller) is made developable by tangent continuity of the crease instead of its
// flat copy: its two tangent points l, r lie on one line through v on opposite sides,
//   ((r − v) + λ (l − v)) / |r − v|_ref = 0   (three rows, λ > 0 a variable of a block
//   "creaseTangentRatios", starting at |r − v| / |l − v|),
// in a family "smoothCreaseVertices" (role Constraint, weight `weight`) added to `problem`. The
// angles on either side of the crease then sum to π each: the star is developable. Every star a
// crease passes through gets both kinds of rows, the unused kind scaled to zero, so the
// structure does not depend on the coordinates. 0 disables tangent continuity. Returns the
// number of stars.
//
// `spokeGuard`, `smoothCreaseAngle`, `startDefectLimit` and `weight` are those of `options`
// (vertexSpokeGuard, vertexSmoothCreaseAngle, vertexStartDefectLimit,
// vertexDevelopabilityWeight). A star whose angle defect in `state` exceeds the limit gets its
// rows scaled to zero and guards that never act (same structure, no effect).
int addVertexDevelopability(const model::CompositeSurface& surface,
                            const std::map<model::VertexId, int>& vertexOffsets,
                            const std::map<model::EdgeId, std::vector<int>>& edgeOffsets,
                            Problem& problem, std::vector<double>& state, SquaredDistanceTerm& term,
                            MinimumLengthTerm& guard, const FormulationOptions& options);

} // namespace devsurf::solver
