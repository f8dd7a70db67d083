#include "solver/session/job_options.h"

namespace devsurf::solver {

namespace {

// The weight of the unit length of the control normals in an approximation (see optionsFor).
constexpr double kApproximationUnitNormalWeight = 1.0;

} // namespace

bool keepsLengths(const JobRequest& request) {
    return (request.kind == JobKind::VertexDrag || request.kind == JobKind::Rotate) &&
           request.lengths != DragLengths::Stretch;
}

SessionOptions optionsFor(const JobRequest& request, int surface, bool damped) {
    SessionOptions options;
    if (keepsLengths(request)) {
        options = keepLengthsSessionOptions();
    } else if (request.kind == JobKind::CreaseDrag) {
        options = creaseDragSessionOptions();
    }
    if (request.kind == JobKind::Approximate) {
        options.formulation.approximation = entryOf(request.targets, surface);
        // No fairness of points or normals: the pull shapes the strips, and fairness held them
        // flat against it (developability residual 2e-3, docs/tuning.md). The control normals
        // are held near unit length instead (an energy that fades with the residual and with
        // the pull, SurfaceFormulation::scaleApproximationWeights): without it the normal
        // spline shrank towards zero beyond the target, where (4) then held without making
        // the strip developable (sampled det 3e-3 at solver residual 2e-9).
        options.formulation.fairnessWeight = 0.0;
        options.formulation.normalFairnessWeight = 0.0;
        options.formulation.unitControlNormalWeight = kApproximationUnitNormalWeight;
        if (damped) {
            ApproximationWeights& w = options.formulation.approximationWeights;
            w.position *= kDampedApproximationWeightScale;
            w.tangency *= kDampedApproximationWeightScale;
            w.normalDistance *= kDampedApproximationWeightScale;
            options.approximationDamping = kDampedApproximationEps2;
        }
    }
    options.formulation.curvePairs = entryOf(request.curvePairs, surface);
    options.backgroundFactorization = request.backgroundFactorization;
    if (request.kind == JobKind::Solve) {
        options.stopResidual = kSolveStopResidual;
        if (const auto it = request.fixed.find(surface); it != request.fixed.end()) {
            for (model::VertexId v : it->second) {
                options.formulation.handles.push_back({v, true, {}});
            }
        }
    }
    return options;
}

} // namespace devsurf::solver
