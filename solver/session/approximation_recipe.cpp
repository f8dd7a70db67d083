#include "solver/session/approximation_recipe.h"

#include "model/geometry_checks.h"
#include "model/reference/bounding_box.h"
#include "model/reference/surface_samples.h"
#include "solver/quality/quality_measures.h"
#include "solver/session/drag_lengths.h"

#include <algorithm>

namespace devsurf::solver {

bool approximationFailed(const model::CompositeSurface& result, const ApproximationTarget& target,
                         const Summary& summary) {
    if (!summary.succeeded() || !model::allCoordinatesFinite(result) ||
        (!summary.toleranceReached && worstDevelopability(result) > kDragConvergedResidual)) {
        return true;
    }
    const model::reference::BoundingBox box = model::reference::boundingBox(target.points);
    const double reach = kApproximationRunaway * box.diagonal();
    const auto samples = model::reference::sampleDensely({result}, 4).positions;
    return std::any_of(samples.begin(), samples.end(),
                       [&](const model::Vec3& p) { return box.distanceOutside(p) > reach; });
}

void continueSummary(Summary& summary, const Summary& more) {
    const int offset = summary.iterationsCompleted;
    for (IterationStats stats : more.iterations) {
        stats.iteration += offset;
        summary.iterations.push_back(stats);
    }
    summary.iterationsCompleted += more.iterationsCompleted;
    summary.status = more.status;
    summary.detail = more.detail;
    if (more.iterationsCompleted > 0) {
        summary.finalMaxConstraintResidual = more.finalMaxConstraintResidual;
        summary.finalEnergy = more.finalEnergy;
    }
    summary.toleranceReached = summary.finalMaxConstraintResidual <= summary.tolerance;
    summary.analysisMs += more.analysisMs;
    summary.totalMs += more.totalMs;
}

} // namespace devsurf::solver
