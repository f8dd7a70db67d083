#include "join_command.h"

#include "cli_output.h"
#include "io/project_file.h"
#include "model/strip_joining.h"
#include "outcome_text.h"
#include "problem_text.h"
#include "solver/quality/quality_measures.h"
#include "solver/session/join_job.h"

#include <QString>

#include <cstdio>
#include <iostream>
#include <set>

namespace devsurf::app {

void printIterationLine(const solver::JobProgress& step) {
    const solver::IterationStats& it = *step.stats;
    char line[256];
    std::snprintf(line, sizeof line,
                  "iteration %3d  residual %.3e  assembly %.3f ms  factorisation %.3f ms  "
                  "solve %.3f ms\n",
                  step.done, it.maxConstraintResidual, it.assemblyMs, it.factorizationMs,
                  it.solveMs);
    std::cout << line;
}

std::optional<model::CompositeSurface>
joinSurfaces(const std::vector<model::CompositeSurface>& surfaces,
             std::shared_ptr<const model::reference::ThinningResult> target, double rho,
             std::optional<int> iterations, solver::SolveJob& job, std::vector<int>* joined) {
    solver::JobRequest request;
    request.kind = solver::JobKind::Join;
    request.surfaces = surfaces;
    request.iterations = iterations;
    request.joinTarget = std::move(target);
    request.joinRho = rho;
    // The pairing, then the last step on the joined surface: each starts its iterations at 1.
    int stage = 0;
    const auto progress = [&stage](const solver::JobProgress& step) {
        if (step.done == 1) {
            std::cout << (++stage == 1 ? "Join: pairing the facing edges, "
                                       : "Join: settling the joined surface, ")
                      << step.variables << " variables, " << step.rows << " rows\n";
        }
        printIterationLine(step);
    };
    const solver::JobOutcome outcome = job.run(request, nullptr, progress);
    if (!outcome.ok) {
        throw InputError("the solver stopped while joining the surfaces (" +
                         describeFailure(outcome.failure) + "); nothing was written.");
    }
    const solver::JoinReport& join = *outcome.join;
    if (join.separations.empty()) {
        std::cout << "Join: no two surfaces have boundary edges facing each other (within "
                  << solver::kJoinReach * 100.0 << " % of their length); left separate.\n";
        return std::nullopt;
    }
    for (std::size_t p = 0; p < join.separations.size(); ++p) {
        std::cout << "Join: pair " << p + 1 << " of facing edges " << join.separations[p]
                  << " mm apart\n";
    }
    for (const model::Problem& problem : join.refused) {
        std::cout << "Join: not welded: " << ProblemText::of(problem).toStdString() << "\n";
    }
    if (joined != nullptr) {
        *joined = join.joined;
    }
    const model::CompositeSurface& result = outcome.surfaces.front();
    const solver::SurfaceAssessment& a = outcome.assessments.front();
    char line[320];
    std::snprintf(
        line, sizeof line,
        "Join: %d of %zu pairs of facing edges welded; %zu surfaces now one of %d part(s), "
        "%zu patches; %s in %d iterations, largest residual %.2e (%s the tolerance); "
        "developability sampled: max %.2e\n",
        join.welded, join.separations.size(), join.joined.size(), join.parts, result.faces().size(),
        join.pulledToReference ? "pulled to the reference" : "solved",
        a.summary.iterationsCompleted, a.summary.finalMaxConstraintResidual,
        a.summary.toleranceReached ? "within" : "NOT within",
        solver::measureQuality(result).developabilityMax);
    std::cout << line;
    return result;
}

int runJoinCommand(const SubcommandArguments& args) {
    const std::string input = args.onePositional("one project file");
    const std::string output = args.required("o", kMissingOutput);
    std::optional<int> iterations;
    if (const auto n = args.value("iterations")) {
        iterations = static_cast<int>(parseWhole(*n, "iterations", 0, 10000));
    }
    std::vector<std::uint32_t> numbers;
    if (const auto list = args.value("surfaces")) {
        numbers = parseIds(*list, "--surfaces", "surface");
    }
    checkOutput(output, {input}, OutputKind::Project, "the project");
    model::Project project = io::loadProjectFile(QString::fromStdString(input));
    // The surfaces joined, as indices in ascending order.
    std::set<std::size_t> chosen;
    for (std::uint32_t number : numbers) {
        if (number == 0 || number > project.surfaces.size()) {
            throw UsageError{"option '--surfaces' needs surface numbers from 1 to " +
                             std::to_string(project.surfaces.size()) + ", not '" +
                             std::to_string(number) + "'"};
        }
        chosen.insert(number - 1);
    }
    if (numbers.empty()) {
        for (std::size_t s = 0; s < project.surfaces.size(); ++s) {
            chosen.insert(s);
        }
    }
    if (chosen.size() < 2) {
        throw InputError("a join needs two surfaces at least; '" + input + "' " +
                         (numbers.empty() ? "has " + std::to_string(project.surfaces.size())
                                          : std::string("was given one")) +
                         " (list them with 'devsurf-cli info FILE').");
    }
    std::vector<model::CompositeSurface> surfaces;
    for (std::size_t s : chosen) {
        surfaces.push_back(project.surfaces[s]);
    }
    // Pulled towards every reference shape of the project, thinned as `approximate` thins.
    std::shared_ptr<const model::reference::ThinningResult> target;
    double rho = 0.0;
    if (const auto thinned = solver::thinReferenceShapes(project.referenceShapes)) {
        target = std::make_shared<const model::reference::ThinningResult>(thinned->thinned);
        rho = thinned->rho;
        std::size_t points = 0;
        for (const model::ReferenceShape& shape : project.referenceShapes) {
            points += shape.points.size();
        }
        std::cout << "Reference: " << points << " points thinned with radius " << rho << " mm to "
                  << thinned->thinned.points.size() << " points\n";
    }
    solver::SolveJob job;
    std::vector<int> joinedIndices;
    const std::optional<model::CompositeSurface> joined =
        joinSurfaces(surfaces, target, rho, iterations, job, &joinedIndices);
    if (!joined) {
        std::cerr << "devsurf-cli: nothing was joined; '" << output << "' was not written.\n";
        return kExitInput;
    }
    // The joined surface takes the first one's place and id, as Tools ▸ Join Surfaces does;
    // chosen surfaces that face no other stay as they are.
    const std::vector<std::size_t> order(chosen.begin(), chosen.end());
    std::vector<int> merged;
    for (int k : joinedIndices) {
        merged.push_back(static_cast<int>(order[static_cast<std::size_t>(k)]));
    }
    project.surfaces = model::replaceByJoined(project.surfaces, merged, *joined);
    writeProject(project, output);
    std::cout << "Wrote " << output << " (" << merged.size() << " surfaces joined into '"
              << joined->name() << "'";
    if (merged.size() < chosen.size()) {
        std::cout << "; " << chosen.size() - merged.size() << " facing no other left as they were";
    }
    std::cout << ")\n";
    return kExitOk;
}

} // namespace devsurf::app
