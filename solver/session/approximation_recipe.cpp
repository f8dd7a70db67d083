#include "solver/session/approximation_recipe.h"

#include "model/geometry_checks.h"
#include "model/reference/bounding_box.h"
#include "model/reference/strip_trim.h"
#include "model/reference/surface_samples.h"
#include "solver/quality/quality_measures.h"
#include "solver/session/drag_lengths.h"
#include "solver/session/job_options.h"
#include "solver/session/solve_session.h"

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

namespace {

JobRequest finishingSolve(const ApproximationSteps& run) {
    JobRequest finish;
    finish.kind = JobKind::Solve;
    finish.curvePairs = run.request.curvePairs;
    return finish;
}

bool shortOf(const model::CompositeSurface& s, const Summary& summary, double fraction) {
    return worstDevelopability(s) > fraction * summary.tolerance;
}

// The pull, its fallback and its finish (continueApproximation without the trim).
Summary finishApproximation(const ApproximationSteps& run, const ApproximationTarget& target,
                            const model::CompositeSurface& snapshot,
                            std::unique_ptr<SolveSession>& session, Summary summary,
                            SurfaceAssessment& assessment, int& total) {
    const model::CompositeSurface* start = &snapshot; // of the pull that counts
    if (summary.status != Status::Cancelled &&
        approximationFailed(session->surface(), target, summary)) {
        // The target pulled the strips where they cannot stay developable: the damped recipe
        // from the start (kDampedApproximationWeightScale).
        if (target.dampedStart) {
            start = &*target.dampedStart;
        }
        SessionOptions options = optionsFor(run.request, run.key, true);
        options.approximationFadeAfter = run.iterations;
        session = std::make_unique<SolveSession>(*start, run.handles, run.points, options);
        total += run.steps;
        summary = session->step(run.steps, run.cancel, run.perIteration);
        assessment.dampedApproximation = true;
    }
    if (!summary.succeeded() || summary.status == Status::StoppedBeforeDegenerate ||
        (summary.toleranceReached &&
         !shortOf(session->surface(), summary, kApproximationFinishSampledFraction))) {
        return summary;
    }
    // Short of the tolerance once the pull has faded: finished as a Solve of where the pull left
    // it, whose relative fairness keeps it there while the hard conditions converge (continuing
    // the pull's own session moved it farther: docs/tuning.md).
    const JobRequest finish = finishingSolve(run);
    const model::CompositeSurface pulled = session->surface();
    session = std::make_unique<SolveSession>(pulled, std::vector<VertexHandle>{},
                                             optionsFor(finish, run.key));
    total += kApproximationFinishIterations;
    continueSummary(summary,
                    session->step(kApproximationFinishIterations, run.cancel, run.perIteration));
    if (summary.succeeded() && run.request.curvePairs.count(run.key) == 0 &&
        shortOf(session->surface(), summary, 1.0) && !shortOf(*start, summary, 1.0)) {
        // Still short: the start of the damped pull (a flat strip, or the cylinder over its
        // points), solved; a developable strip a little farther from the target rather than one
        // that is not developable. Not for a pairing (the Join job), whose start has its edges
        // apart.
        session = std::make_unique<SolveSession>(*start, std::vector<VertexHandle>{},
                                                 optionsFor(finish, run.key));
        total += kApproximationFinishIterations;
        summary = session->step(kApproximationFinishIterations, run.cancel, run.perIteration);
        assessment.approximationKeptStart = true;
    }
    return summary;
}

// A developable strip trimmed back where it overhangs the shape, then solved (the refit of a
// trim along its curves or askew is not exactly developable); kept only if that ends
// developable. Where the trim askew does not, the same trim with its lines across made even
// (each at its tighter end) is tried.
void trimOverhang(const ApproximationSteps& run, const ApproximationTarget& target,
                  std::unique_ptr<SolveSession>& session, Summary& summary,
                  SurfaceAssessment& assessment, int& total) {
    if (!target.overhang || !summary.succeeded() ||
        summary.status == Status::StoppedBeforeDegenerate || !summary.toleranceReached ||
        shortOf(session->surface(), summary, 1.0) || run.request.curvePairs.count(run.key) != 0) {
        return;
    }
    const std::optional<model::reference::StripTrim> trim =
        model::reference::overhangTrim(session->surface(), *target.overhang, target.trimTolerance);
    if (!trim || !trim->trims()) {
        return;
    }
    model::reference::StripTrim even = *trim;
    even.w0[0] = even.w0[1] = std::max(trim->w0[0], trim->w0[1]);
    even.w1[0] = even.w1[1] = std::min(trim->w1[0], trim->w1[1]);
    const bool askew = trim->w0[0] != trim->w0[1] || trim->w1[0] != trim->w1[1];
    const model::reference::StripTrim tries[2] = {*trim, even};
    for (int k = 0; k < (askew ? 2 : 1); ++k) {
        const model::reference::StripTrim& t = tries[k];
        auto trimmed = std::make_unique<SolveSession>(
            model::reference::trimmedStrip(session->surface(), t), std::vector<VertexHandle>{},
            optionsFor(finishingSolve(run), run.key));
        total += kApproximationFinishIterations;
        const Summary more =
            trimmed->step(kApproximationFinishIterations, run.cancel, run.perIteration);
        if (more.succeeded() && more.toleranceReached && !shortOf(trimmed->surface(), more, 1.0)) {
            session = std::move(trimmed);
            continueSummary(summary, more);
            assessment.approximationTrim = t;
            return;
        }
        if (more.status == Status::Cancelled) {
            return;
        }
    }
}

} // namespace

Summary continueApproximation(const ApproximationSteps& run, const ApproximationTarget& target,
                              const model::CompositeSurface& snapshot,
                              std::unique_ptr<SolveSession>& session, Summary summary,
                              SurfaceAssessment& assessment, int& total) {
    summary = finishApproximation(run, target, snapshot, session, summary, assessment, total);
    trimOverhang(run, target, session, summary, assessment, total);
    return summary;
}

} // namespace devsurf::solver
