#include "solve_command.h"

#include "cli_output.h"
#include "io/project_file.h"
#include "model/model_error.h"
#include "model/pattern/cutting_pattern.h"
#include "solver/formulation/perturbation.h"
#include "solver/quality/crease_quality.h"
#include "solver/quality/quality_measures.h"
#include "solver/quality/shape_change.h"
#include "solver/session/solve_session.h"

#include <QString>

#include <algorithm>
#include <cstdio>
#include <iostream>
#include <sstream>
#include <stdexcept>

namespace devsurf::app {

namespace {

// Says whether the solve reached the tolerance and, if not, which faces are worst (their ids,
// as the desktop application shows them).
void reportTolerance(const solver::SolveSession& session, const solver::Summary& summary) {
    char line[256];
    if (summary.toleranceReached) {
        std::snprintf(line, sizeof line, "Reached the tolerance %.1e (largest residual %.2e).\n",
                      summary.tolerance, summary.finalMaxConstraintResidual);
        std::cout << line;
        return;
    }
    std::snprintf(line, sizeof line,
                  "Did not reach the tolerance %.1e (largest residual %.2e); worst faces:",
                  summary.tolerance, summary.finalMaxConstraintResidual);
    std::cout << line;
    const auto faces = session.worstFaces();
    const std::size_t shown = std::min<std::size_t>(faces.size(), 5);
    for (std::size_t i = 0; i < shown; ++i) {
        std::snprintf(line, sizeof line, "%s face %u (%.2e)", i == 0 ? "" : ",", faces[i].face,
                      faces[i].residual);
        std::cout << line;
    }
    std::cout << (shown == 0 ? " none (the residual is in a vertex or normal condition)" : "")
              << "\n";
}

} // namespace

int runSolveCommand(const SolveArguments& args) {
    const int iterations = args.iterations;
    const bool perturb = args.perturb.has_value();
    const double sigma = args.perturb.value_or(0.0);
    const unsigned seed = args.seed;
    const std::vector<model::VertexId>& fixed = args.fixed;
    const std::string& output = args.output;
    const std::string& path = args.input;
    model::Project project = io::loadProjectFile(QString::fromStdString(path));
    for (std::size_t s = 0; s < project.surfaces.size(); ++s) {
        model::CompositeSurface& surface = project.surfaces[s];
        for (model::VertexId v : fixed) {
            if (!surface.hasVertex(v)) {
                throw model::ModelError("'" + path + "' has no vertex " + std::to_string(v) +
                                        " in surface " + std::to_string(s + 1) + ".");
            }
        }
        if (perturb) {
            solver::perturbSurface(surface, sigma * solver::surfaceDiameter(surface),
                                   seed + static_cast<unsigned>(s), fixed);
        }
        solver::SessionOptions sessionOptions;
        for (model::VertexId v : fixed) {
            sessionOptions.formulation.handles.push_back({v, true, {}});
        }
        std::unique_ptr<solver::SolveSession> session;
        try {
            session = std::make_unique<solver::SolveSession>(
                surface, std::vector<solver::VertexHandle>{}, sessionOptions);
        } catch (const std::invalid_argument& error) {
            throw model::ModelError("surface " + std::to_string(s + 1) + " of '" + path +
                                    "' cannot be solved: " + error.what());
        }
        const solver::Problem& problem = session->formulation().problem();
        std::cout << "Surface " << s + 1 << " (" << surface.name()
                  << "): " << problem.variableCount() << " variables, " << problem.rowCount()
                  << " rows\n";
        solver::Summary last;
        for (int i = 0; i < iterations; ++i) {
            const solver::Summary summary = session->step(1);
            if (summary.status == solver::Status::StoppedBeforeDegenerate) {
                // The session refused a degenerate iterate and stays at the last valid one.
                std::cout << "After iteration " << i
                          << ": stopped at the last valid state: " << summary.message << "\n";
                break;
            }
            if (!summary.succeeded() || summary.iterations.empty()) {
                throw model::ModelError("the solver stopped at iteration " + std::to_string(i + 1) +
                                        " (" + solver::toString(summary.status) +
                                        (summary.message.empty() ? "" : ": " + summary.message) +
                                        "); nothing was written.");
            }
            last = summary;
            const solver::IterationStats& it = summary.iterations.front();
            const solver::QualityMeasures quality = solver::measureQuality(session->surface());
            char line[512];
            std::snprintf(line, sizeof line,
                          "iteration %3d  residual %.3e  assembly %.3f ms  factorisation %.3f ms "
                          " solve %.3f ms  %s\n",
                          i + 1, it.maxConstraintResidual, it.assemblyMs, it.factorizationMs,
                          it.solveMs, quality.describe().c_str());
            std::cout << line;
        }
        // Solve ends on its best iterate (SolveSession::returnToBestIterate).
        const solver::SolveSession::BestIterate best = session->returnToBestIterate(&last);
        if (best.iteration > 0) {
            std::cout << "Ended on iteration " << best.iteration
                      << ", the one with the smallest residual.\n";
        }
        reportTolerance(*session, last);
        surface = session->surface();
        // The solver's residual holds at collocation values; the crease conditions sampled
        // along the whole creases (as the Solver panel gives them).
        if (const solver::CreaseQuality creases = solver::measureCreaseQuality(surface);
            creases.creases > 0) {
            char line[160];
            std::snprintf(line, sizeof line,
                          "Creases: %d with a condition, sampled along them: residual max %.2e "
                          "mean %.2e.\n",
                          creases.creases, creases.residualMax, creases.residualMean);
            std::cout << line;
        }
        std::cout << solver::describeFoldOvers(solver::foldOvers(surface)) << "\n"
                  << model::describeSelfOverlap(model::selfOverlappingPatches(surface)) << "\n";
    }
    writeProject(project, output);
    std::cout << "Wrote " << output << "\n";
    return 0;
}

} // namespace devsurf::app
