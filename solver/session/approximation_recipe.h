#pragma once

// The judgements of an approximation's recipe in the solve job (§4.2): whether the pull failed,
// so that the damped pull runs instead, and the summary of a strip finished by a Solve.

#include "model/composite_surface.h"
#include "solver/core/summary.h"
#include "solver/formulation/approximation_terms.h"

namespace devsurf::solver {

// A sample farther than this times the target's bounding-box diagonal outside that box: the
// surface ran away.
inline constexpr double kApproximationRunaway = 0.5;

// Whether the pull failed: it stopped, it missed the tolerance with a patch sampled farther than
// kDragConvergedResidual from developable, or the surface ran away (also within the tolerance:
// a developable strip can leave its points). Missing the tolerance alone is no failure; the job
// finishes such a strip by a Solve.
bool approximationFailed(const model::CompositeSurface& result, const ApproximationTarget& target,
                         const Summary& summary);

// `summary` continued by `more` (an approximation finished by a Solve): its iterations
// appended, its end taken.
void continueSummary(Summary& summary, const Summary& more);

} // namespace devsurf::solver
