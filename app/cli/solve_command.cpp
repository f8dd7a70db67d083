#include "solve_command.h"

#include "cli_output.h"
#include "io/project_file.h"
#include "model/model_error.h"
#include "outcome_text.h"
#include "solver/formulation/perturbation.h"
#include "solver/quality/quality_measures.h"
#include "solver/session/solve_job.h"
#include "solver/session/verdict.h"
#include "verdict_text.h"

#include <QString>

#include <algorithm>
#include <cstdio>
#include <iostream>
#include <optional>
#include <sstream>
#include <stdexcept>

namespace devsurf::app {

namespace {

// Says whether the solve reached the tolerance and, if not, which patches are least
// developable (sampled, as the desktop application's Solver panel names them).
void reportTolerance(const solver::SurfaceAssessment& assessment) {
    const solver::Summary& summary = assessment.summary;
    char line[256];
    if (summary.toleranceReached) {
        std::snprintf(line, sizeof line, "Reached the tolerance %.1e (largest residual %.2e).\n",
                      summary.tolerance, summary.finalMaxConstraintResidual);
        std::cout << line;
        return;
    }
    std::snprintf(line, sizeof line,
                  "Did not reach the tolerance %.1e (largest residual %.2e); least developable "
                  "faces:",
                  summary.tolerance, summary.finalMaxConstraintResidual);
    std::cout << line;
    for (std::size_t i = 0; i < assessment.worstFaces.size(); ++i) {
        std::snprintf(line, sizeof line, "%s face %u (%.2e)", i == 0 ? "" : ",",
                      assessment.worstFaces[i].first, assessment.worstFaces[i].second);
        std::cout << line;
    }
    std::cout << (assessment.worstFaces.empty()
                      ? " none (the residual is in a vertex or normal condition)"
                      : "")
              << "\n";
}

} // namespace

int runSolveCommand(const SolveArguments& args) {
    const std::optional<int> iterations = args.iterations;
    const bool perturb = args.perturb.has_value();
    const double sigma = args.perturb.value_or(0.0);
    const unsigned seed = args.seed;
    const std::vector<model::VertexId>& fixed = args.fixed;
    const std::string& output = args.output;
    const std::string& path = args.input;
    model::Project project = io::loadProjectFile(QString::fromStdString(path));
    solver::JobRequest request;
    request.kind = solver::JobKind::Solve;
    request.iterations = iterations;
    for (std::size_t s = 0; s < project.surfaces.size(); ++s) {
        model::CompositeSurface& surface = project.surfaces[s];
        for (model::VertexId v : fixed) {
            if (!surface.hasVertex(v)) {
                throw InputError("'" + path + "' has no vertex " + std::to_string(v) +
                                 " in surface " + std::to_string(s + 1) + ".");
            }
        }
        if (perturb) {
            solver::perturbSurface(surface, sigma * solver::surfaceDiameter(surface),
                                   seed + static_cast<unsigned>(s), fixed);
        }
        request.fixed[static_cast<int>(s)] = fixed;
    }
    request.surfaces = project.surfaces;
    // The same job as the desktop application's Tools ▸ Solve: one line per iteration.
    int surfaceShown = -1;
    auto progress = [&](const solver::JobProgress& step) {
        if (step.surface != surfaceShown) {
            surfaceShown = step.surface;
            std::cout << "Surface " << step.surface + 1 << " ("
                      << project.surfaces[static_cast<std::size_t>(step.surface)].name()
                      << "): " << step.variables << " variables, " << step.rows << " rows\n";
        }
        const solver::IterationStats& it = *step.stats;
        const solver::QualityMeasures quality = solver::measureQuality(*step.current);
        char line[512];
        std::snprintf(line, sizeof line,
                      "iteration %3d  residual %.3e  assembly %.3f ms  factorisation %.3f ms "
                      " solve %.3f ms  %s\n",
                      it.iteration + 1, it.maxConstraintResidual, it.assemblyMs, it.factorizationMs,
                      it.solveMs, describeQuality(quality).c_str());
        std::cout << line;
    };
    solver::SolveJob job;
    const solver::JobOutcome outcome = job.run(request, nullptr, progress);
    if (!outcome.ok) {
        throw InputError("the solver stopped (" + describeFailure(outcome.failure) +
                         "); nothing was written.");
    }
    for (std::size_t s = 0; s < outcome.surfaces.size(); ++s) {
        const solver::SurfaceAssessment& a = outcome.assessments[s];
        const solver::Summary& summary = a.summary;
        if (summary.status == solver::Status::StoppedBeforeDegenerate) {
            // The session refused a degenerate iterate and stayed at the last valid one.
            std::cout << "After iteration " << summary.iterationsCompleted
                      << ": stopped at the last valid state" << refusedText(a) << "\n";
        }
        if (a.bestIteration > 0) {
            std::cout << "Ended on iteration " << a.bestIteration
                      << ", the one with the smallest residual.\n";
        }
        if (a.keptAsItWas) {
            char line[200];
            std::snprintf(line, sizeof line,
                          "Left as it was: solving made it less developable (largest "
                          "developability residual %.1e -> %.1e).\n",
                          a.keptAsItWas->before, a.keptAsItWas->after);
            std::cout << line;
        }
        reportTolerance(a);
        // The solver's residual holds at collocation values; the crease conditions sampled
        // along the whole creases (as the Solver panel gives them).
        if (a.creases.creases > 0) {
            char line[160];
            std::snprintf(line, sizeof line,
                          "Creases: %d with a condition, sampled along them: residual max %.2e "
                          "mean %.2e.\n",
                          a.creases.creases, a.creases.residualMax, a.creases.residualMean);
            std::cout << line;
        }
        std::cout << describeFoldOvers(a.foldOvers) << "\n"
                  << describeSelfOverlap(a.overlapping) << "\n";
        project.surfaces[s] = outcome.surfaces[s];
    }
    // The same verdict as the Solver panel's, decided by the job's outcome.
    const solver::Verdict verdict = solver::verdictOf(outcome);
    if (verdict.kind != solver::VerdictKind::None) {
        std::cout << "Verdict: " << VerdictText::of(verdict).toStdString() << "\n"
                  << "  " << VerdictText::details(verdict).toStdString() << "\n";
    }
    writeProject(project, output);
    std::cout << "Wrote " << output << "\n";
    return 0;
}

} // namespace devsurf::app
