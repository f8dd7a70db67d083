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

// Adds, for every star of creaseVertexStars, a flat copy (a block "vertexStars", the isometry
// rows (12) of its triangles in `term`, a guard keeping every spoke at `vertexSpokeGuard` of
// its start length in `guard`); where a crease passes a four-spoke star nearly straight
// (vertexSmoothCreaseAngle, or vertexSmoothPlainCreaseAngle for a crease without a condition),
// tangent continuity instead (block "creaseTangentRatios", family "smoothCreaseVertices").
// Both kinds of rows exist for every such star, the unused one scaled to zero, as do the rows
// of stars whose start defect exceeds vertexStartDefectLimit: the structure depends on the
// combinatorics only. `state` is resized to the variable count. Returns the number of stars.
// The formulation: docs/math.md §7.1.
int addVertexDevelopability(const model::CompositeSurface& surface,
                            const std::map<model::VertexId, int>& vertexOffsets,
                            const std::map<model::EdgeId, std::vector<int>>& edgeOffsets,
                            Problem& problem, std::vector<double>& state, SquaredDistanceTerm& term,
                            MinimumLengthTerm& guard, const FormulationOptions& options);

} // namespace devsurf::solver
