#pragma once

// The guard against cusps of the curves: curve speeds that must not fall below a minimum set
// from the reference state (FormulationOptions::speedGuard, SurfaceFormulation::setReferenceState).

#include "model/composite_surface.h"
#include "solver/core/minimum_length_term.h"

#include <map>
#include <vector>

namespace devsurf::solver {

// One row |c¹₁ − c¹₀| (the speed of the curve) of every S-edge at the collocation values of
// its intervals and at its ends, with minimum 0. `edgeOffsets` are the state offsets of every
// S-edge's control points (stored orientation); `curveStart` receives the first row of every
// curve and, at the end, the row count, so that curve c owns rows curveStart[c] …
// curveStart[c + 1] − 1.
void addSpeedGuards(const model::CompositeSurface& surface,
                    const std::map<model::EdgeId, std::vector<int>>& edgeOffsets,
                    MinimumLengthTerm& speeds, std::vector<int>& curveStart);

} // namespace devsurf::solver
