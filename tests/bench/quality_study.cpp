#include "quality_study.h"

#include "ceres_peer.h"

#include "model/pattern/cutting_pattern.h"
#include "solver/core/guided_projection.h"
#include "solver/formulation/perturbation.h"
#include "solver/quality/quality_measures.h"
#include "solver/session/solve_session.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <tuple>
#include <utility>

namespace devsurf::bench {

double noiseSigma(const model::CompositeSurface& surface, const StudyStart& start) {
    return start.fraction * (start.scale == NoiseScale::EdgeLength
                                 ? solver::meanControlSpacing(surface)
                                 : solver::surfaceDiameter(surface));
}

std::vector<StudyRun> runStudy(const model::CompositeSurface& surface, const StudyStart& start,
                               const StudyOptions& options) {
    const std::vector<model::VertexId> anchors =
        solver::spreadBoundaryVertices(surface, options.fixedVertices);
    const double sigma = noiseSigma(surface, start);
    solver::FormulationOptions formulationOptions = options.formulation;
    for (model::VertexId v : anchors) {
        formulationOptions.handles.push_back({v, true, {}});
    }
    solver::Options solverOptions = options.solver;
    solverOptions.maxIterations = options.iterations;
    std::vector<StudyRun> runs;
    for (int s = 0; s < options.seeds; ++s) {
        StudyRun run;
        run.seed = options.firstSeed + static_cast<unsigned>(s);
        model::CompositeSurface perturbed = surface;
        solver::perturbSurface(perturbed, sigma, run.seed, anchors);
        solver::Summary summary;
        model::CompositeSurface result = perturbed;
        bool written = false;
        if (options.solverKind == StudySolver::Session) {
            model::CompositeSurface pinned = perturbed;
            for (model::VertexId v : anchors) {
                pinned.setPinned(v, true);
            }
            solver::SolveSession session(pinned, {});
            summary = session.step(options.iterations);
            result = session.surface();
            written = true;
        } else {
            const solver::SurfaceFormulation formulation(perturbed, formulationOptions);
            std::vector<double> x = formulation.initialState();
            if (options.ceres) {
                const CeresResult ceres = runCeres(formulation.problem(), x, 1e-10, 60.0);
                run.ceresResidual = ceres.finalResidual;
                run.ceresIterations = ceres.iterations;
            }
            solver::GuidedProjection projection;
            projection.setExperimentalOptions(options.experimental);
            summary = projection.solve(formulation.problem(), x, solverOptions);
            written = formulation.writeBack(x, result);
        }
        run.status = solver::toString(summary.status);
        run.residual = summary.finalMaxConstraintResidual;
        run.iterations = summary.iterations;
        double iterationMs = 0.0;
        for (const solver::IterationStats& it : summary.iterations) {
            iterationMs += it.assemblyMs + it.factorizationMs + it.solveMs;
        }
        run.msPerIteration =
            summary.iterations.empty() ? 0.0 : iterationMs / summary.iterations.size();
        try {
            if (!written) {
                throw std::runtime_error("not written back");
            }
            const solver::QualityMeasures quality = solver::measureQuality(result);
            run.detMax = quality.developabilityMax;
            run.flatnessMean = quality.flatnessMean;
            run.change = solver::measureShapeChange(perturbed, result);
            run.overlapping = model::selfOverlappingPatches(result);
        } catch (const std::exception&) {
            // A result too degenerate to measure (a face of zero area) counts as the worst.
            run.status = "degenerate";
            run.detMax = 1.0;
            run.flatnessMean = 1.0;
            run.change.shortestRuling = 0.0;
            run.change.slowestSpeed = 0.0;
        }
        runs.push_back(run);
    }
    return runs;
}

namespace {

// Worst and median of a figure; `largerIsWorse` tells which end is the worst.
std::pair<double, double> worstAndMedian(std::vector<double> values, bool largerIsWorse) {
    if (values.empty()) {
        return {0.0, 0.0};
    }
    std::sort(values.begin(), values.end());
    const std::size_t n = values.size();
    const double median = n % 2 == 1 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
    return {largerIsWorse ? values.back() : values.front(), median};
}

} // namespace

StudySummary summarize(const std::vector<StudyRun>& runs) {
    std::vector<double> det, flatness, ruling, speed, fold, startAngle, ratio;
    for (const StudyRun& r : runs) {
        det.push_back(r.detMax);
        flatness.push_back(r.flatnessMean);
        ruling.push_back(r.change.shortestRuling);
        speed.push_back(r.change.slowestSpeed);
        fold.push_back(r.change.creaseFoldMean);
        startAngle.push_back(r.change.startNormalAngleMean);
        ratio.push_back(r.change.startNormalAngleMean > 0.0
                            ? r.change.creaseFoldMean / r.change.startNormalAngleMean
                            : 0.0);
    }
    StudySummary s;
    std::tie(s.detWorst, s.detMedian) = worstAndMedian(det, true);
    std::tie(s.flatnessWorst, s.flatnessMedian) = worstAndMedian(flatness, true);
    std::tie(s.rulingWorst, s.rulingMedian) = worstAndMedian(ruling, false);
    std::tie(s.speedWorst, s.speedMedian) = worstAndMedian(speed, false);
    std::tie(s.foldWorst, s.foldMedian) = worstAndMedian(fold, true);
    s.startAngleMedian = worstAndMedian(startAngle, true).second;
    std::tie(s.foldOverStartWorst, s.foldOverStartMedian) = worstAndMedian(ratio, true);
    for (const StudyRun& r : runs) {
        s.foldedOverSeeds += r.change.foldOverPlaces() > 0 ? 1 : 0;
        s.foldOverPlacesWorst = std::max(s.foldOverPlacesWorst, r.change.foldOverPlaces());
        s.overlappingSeeds += r.overlapping.empty() ? 0 : 1;
    }
    return s;
}

} // namespace devsurf::bench
