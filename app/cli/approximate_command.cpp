#include "approximate_command.h"

#include "cli_output.h"
#include "io/file_error.h"
#include "io/output_file.h"
#include "io/project_file.h"
#include "io/reference/reference_import.h"
#include "join_command.h"
#include "model/reference/distance_report.h"
#include "model/strip_joining.h"
#include "outcome_text.h"
#include "problem_text.h"
#include "reference_commands.h"
#include "solver/quality/quality_measures.h"
#include "solver/session/approximation_setup.h"
#include "solver/session/solve_job.h"

#include <QString>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>

namespace devsurf::app {

namespace {

// --join (§4.2, "Composite"): the strips joined into one surface by the Join job, pulled
// towards the thinned target.
std::vector<model::CompositeSurface>
joinStrips(const std::vector<model::CompositeSurface>& surfaces,
           const model::reference::ThinningResult& thinned, double rho,
           std::optional<int> iterations, solver::SolveJob& job) {
    if (surfaces.size() < 2) {
        std::cout << "Join: a single surface, nothing to join.\n";
        return surfaces;
    }
    std::vector<int> merged;
    const std::optional<model::CompositeSurface> joined =
        joinSurfaces(surfaces, std::make_shared<const model::reference::ThinningResult>(thinned),
                     rho, iterations, job, &merged);
    return joined ? model::replaceByJoined(surfaces, merged, *joined) : surfaces;
}

} // namespace

int runApproximateCommand(const SubcommandArguments& args) {
    const std::string target = args.positionals(1, "a mesh or point cloud file").front();
    const std::string output = args.required("o", kMissingOutput);
    const std::optional<std::string> from = args.value("from");
    if (from && args.value("strips")) {
        throw UsageError{"give either '--from' or '--strips', not both"};
    }
    const int strips =
        static_cast<int>(parseWhole(args.value("strips").value_or("1"), "strips", 1, 1000));
    const int intervals =
        static_cast<int>(parseWhole(args.value("intervals").value_or("4"), "intervals", 1, 100));
    std::optional<int> iterations;
    if (const auto n = args.value("iterations")) {
        iterations = static_cast<int>(parseWhole(*n, "iterations", 0, 10000));
    }
    double rho = 0.0;
    if (const auto r = args.value("rho")) {
        rho = parseReal(*r, "rho", 1e-9, 1e9, "a length in mm");
    }
    checkReferenceTarget(target, output);
    checkOutput(output, from ? std::vector<std::string>{*from} : std::vector<std::string>{},
                OutputKind::Project, "the project");
    model::Project project;
    if (from) {
        project = io::loadProjectFile(QString::fromStdString(*from));
        if (project.surfaces.empty()) {
            throw InputError("'" + *from +
                             "' has no surface to start from; leave out '--from' "
                             "to start from new strips.");
        }
    }
    io::ReferenceImportResult read = io::readReferenceShape(target);
    if (read.error) {
        std::cerr << "devsurf-cli: " << referenceImportSentence(*read.error, target) << "\n";
        return 2;
    }
    const std::vector<model::Vec3>& points = read.shape.points;
    const solver::ThinnedTarget thinnedTarget = solver::thinTarget(points, rho);
    const model::reference::ThinningResult& thinned = thinnedTarget.thinned;
    const double diagonal = thinnedTarget.diagonal;
    rho = thinnedTarget.rho;
    if (!solver::enoughPointsFor(thinnedTarget, strips)) {
        throw InputError("thinning '" + target + "' with radius " +
                         QString::number(rho, 'g', 6).toStdString() + " mm kept " +
                         std::to_string(thinned.points.size()) + " points, too few for " +
                         std::to_string(strips) +
                         " strip(s); give a denser target or a smaller "
                         "'--rho'.");
    }
    std::cout << "Target: " << points.size() << " points, bounding-box diagonal " << diagonal
              << " mm; thinned with radius " << rho << " mm to " << thinned.points.size()
              << " points\n";

    bool oneSurface = false;
    if (!from && !args.isSet("separate")) {
        // A patch over its plane: the strips side by side as one surface, watertight.
        if (std::optional<model::CompositeSurface> sheet =
                solver::initialStripSheet(thinnedTarget, points, strips, intervals)) {
            std::cout << "The target is one patch: " << strips
                      << " strips laid side by side as one surface, each two sharing a "
                         "curve\n";
            project.addSurface(std::move(*sheet));
            oneSurface = true;
        } else if (std::optional<model::CompositeSurface> rings =
                       solver::initialStripRings(thinnedTarget, points, strips, intervals)) {
            // Closed around an axis: rings one after another, watertight but for the ends.
            std::cout << "The target closes around an axis: " << strips
                      << " rings laid one after another around it as one surface, each two "
                         "sharing a closed curve\n";
            project.addSurface(std::move(*rings));
            oneSurface = true;
        }
    }
    if (!from && !oneSurface) {
        // K bands of the thinned points (k-means), one flat strip each.
        for (model::CompositeSurface& strip :
             solver::initialStrips(thinnedTarget, strips, intervals)) {
            project.addSurface(std::move(strip));
        }
        if (project.surfaces.empty()) {
            throw InputError("the points of '" + target +
                             "' lie on a line; no strip can be fitted to them.");
        }
    }
    const solver::SurfaceTargets targets = solver::assignToSurfaces(project.surfaces, thinned);
    const solver::JobRequest request = solver::approximationRequest(
        project.surfaces, targets, rho, iterations, !from && !oneSurface);
    int surfaceShown = -1;
    auto progress = [&](const solver::JobProgress& step) {
        if (step.surface != surfaceShown) {
            surfaceShown = step.surface;
            const std::size_t s = static_cast<std::size_t>(step.surface);
            std::cout << "Surface " << step.surface + 1 << " (" << project.surfaces[s].name()
                      << "): " << targets.points[s].size() << " target points, " << step.variables
                      << " variables, " << step.rows << " rows\n";
        }
        printIterationLine(step);
    };
    solver::SolveJob job;
    const solver::JobOutcome outcome = job.run(request, nullptr, progress);
    if (!outcome.ok) {
        throw InputError("the solver stopped (" + describeFailure(outcome.failure) +
                         "); nothing was written.");
    }
    for (std::size_t s = 0; s < outcome.surfaces.size(); ++s) {
        const solver::SurfaceAssessment& a = outcome.assessments[s];
        if (!a.solved) {
            std::cout << "Surface " << s + 1 << ": too far from the target, left as it was.\n";
            continue;
        }
        const solver::QualityMeasures quality = solver::measureQuality(outcome.surfaces[s]);
        char line[256];
        std::snprintf(line, sizeof line,
                      "Surface %zu: %d iterations, largest residual %.2e (%s the tolerance "
                      "%.1e); developability sampled: max %.2e\n",
                      s + 1, a.summary.iterationsCompleted, a.summary.finalMaxConstraintResidual,
                      a.summary.toleranceReached ? "within" : "NOT within", a.summary.tolerance,
                      quality.developabilityMax);
        std::cout << line;
        if (a.dampedApproximation) {
            std::cout << "  pulled again, damped: the strip cannot follow this part of the "
                         "target closely and stay developable\n";
        }
        if (a.approximationKeptStart) {
            std::cout << "  kept as it was laid: pulled closer, it did not end developable\n";
        }
        if (a.approximationTrim) {
            std::cout << "  trimmed where it stood off the shape: "
                      << std::lround(100.0 * a.approximationTrim->kept())
                      << " % of its parameters kept\n";
        }
        if (a.summary.status == solver::Status::StoppedBeforeDegenerate) {
            std::cout << "  stopped at the last valid state" << refusedText(a) << "\n";
        }
    }
    std::cout << "Time: " << static_cast<long>(outcome.elapsedMs) << " ms\n";
    project.surfaces = outcome.surfaces;
    if (args.isSet("join")) {
        project.surfaces = joinStrips(project.surfaces, thinned, rho, iterations, job);
    }
    if (std::find(project.referenceShapes.begin(), project.referenceShapes.end(), read.shape) ==
        project.referenceShapes.end()) {
        project.referenceShapes.push_back(read.shape);
    }
    model::reference::DistanceOptions distanceOptions;
    distanceOptions.triangles = &read.shape.triangles; // a mesh: to its triangles
    const model::reference::DistanceReport report =
        model::reference::measureDistance(project.surfaces, points, distanceOptions);
    printDistanceReport(report, points.size());
    writeProject(project, output);
    std::cout << "Wrote " << output << "\n";
    return 0;
}

} // namespace devsurf::app
