#pragma once

// An approximation's recipe in the solve job (§4.2): whether the pull failed, so that the damped
// pull runs instead, the finishing Solve of a strip short of the tolerance, and the summary of a
// strip so finished.

#include "model/composite_surface.h"
#include "solver/core/summary.h"
#include "solver/formulation/approximation_terms.h"
#include "solver/formulation/surface_formulation.h"
#include "solver/session/solve_job.h"

#include <atomic>
#include <functional>
#include <memory>
#include <vector>

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

class SolveSession;

// What the job's approximation of one surface runs with.
struct ApproximationSteps {
    const JobRequest& request;
    int key = 0;        // the surface
    int iterations = 0; // of the pull, before it fades
    int steps = 0;      // of the pull and its fading
    const std::vector<VertexHandle>& handles;
    const std::vector<ControlPointHandle>& points;
    const std::atomic<bool>* cancel = nullptr;
    const std::function<void(const IterationStats&)>& perIteration;
};

// After the pull from `snapshot` ended with `summary` in `session`: where it failed, the damped
// pull again (from target.dampedStart where set); where the result is short of the tolerance by
// the solver's rows or sampled between them (kApproximationFinishSampledFraction), a Solve of
// it; where that is still short, the damped pull's start solved. Replaces `session`, marks
// `assessment`, adds each step's iterations to `total` (the job's progress) and returns the
// summary of the result. Then, for a strip with a target.overhang that ended developable, its
// sides trimmed back where they overhang the shape (model::reference::overhangTrim) and the
// trimmed strip solved, kept where that ends developable (assessment.approximationTrim).
// Throws what SolveSession's constructor throws.
Summary continueApproximation(const ApproximationSteps& run, const ApproximationTarget& target,
                              const model::CompositeSurface& snapshot,
                              std::unique_ptr<SolveSession>& session, Summary summary,
                              SurfaceAssessment& assessment, int& total);

} // namespace devsurf::solver
