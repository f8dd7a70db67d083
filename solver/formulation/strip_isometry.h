#pragma once

#include "solver/core/squared_distance_term.h"

#include <vector>

namespace devsurf::solver {

// Rows that keep the control net of a strip close to an isometric copy of itself at the state
// `x`: for the control polygons a₀ … aₙ and b₀ … bₙ of its two curves (offsets of their first
// coordinates, in the strip's parameter order), the lengths |aᵢ − aᵢ₊₁|, |bᵢ − bᵢ₊₁|,
// |aᵢ − bᵢ| and the diagonal |aᵢ − bᵢ₊₁|, each row ‖(p − q) / d‖² − 1 with d the length at x
// (dimensionless: about twice the relative change of the length). Lengths below `negligible`
// get no row. Used as an energy: it resists changes of the net's shape that the constraints
// do not ask for, such as a curved crease pulled straight, while the net can still bend
// about its diagonals.
void addStripIsometry(const std::vector<int>& a, const std::vector<int>& b,
                      const std::vector<double>& x, double negligible, SquaredDistanceTerm& term);

} // namespace devsurf::solver
