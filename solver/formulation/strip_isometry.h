#pragma once

#include "model/strip.h"
#include "solver/core/squared_distance_term.h"

#include <map>
#include <vector>

namespace devsurf::solver {

// Rows that keep the control net of every strip (cones have none) close to an isometric copy
// of itself at the state `x`: for the control polygons a₀ … aₙ and b₀ … bₙ of its two curves,
// in the strip's parameter order, the lengths |aᵢ − aᵢ₊₁|, |bᵢ − bᵢ₊₁|, |aᵢ − bᵢ| and the
// diagonal |aᵢ − bᵢ₊₁|, each row ‖p − q‖² − d² with d the length at x (lengths of zero, such
// as a pointed end, get no row). `edgeOffsets` are the state offsets of every S-edge's control
// points in its stored orientation. Used as an energy (FormulationOptions::isometryWeight)
// whose lengths SolveSession re-bases before every step (SquaredDistanceTerm::
// setSquaredDistance): it damps stretching of the net in each step, such as a curved crease
// pulled straight, while the net can still bend about its diagonals.
void addStripIsometry(const std::vector<model::Strip>& strips,
                      const std::map<model::EdgeId, std::vector<int>>& edgeOffsets,
                      const std::vector<double>& x, SquaredDistanceTerm& term);

} // namespace devsurf::solver
