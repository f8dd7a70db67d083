#include "approximate_command.h"

#include "cli_output.h"
#include "io/file_error.h"
#include "io/output_file.h"
#include "io/project_file.h"
#include "io/reference/reference_import.h"
#include "model/reference/bounding_box.h"
#include "model/reference/distance_report.h"
#include "model/reference/initial_strip.h"
#include "model/reference/point_index.h"
#include "model/reference/surface_samples.h"
#include "model/reference/thinning.h"
#include "outcome_text.h"
#include "reference_commands.h"
#include "solver/quality/quality_measures.h"
#include "solver/session/solve_job.h"

#include <QString>

#include <algorithm>
#include <cstdio>
#include <iostream>
#include <memory>

namespace devsurf::app {

namespace {

// The thinning radius when none is given: 2 % of the target's bounding-box diagonal, so that a
// strip of a few spline intervals is pulled by tens to hundreds of points, or more where the
// target is so sparse that a ball of that radius holds too few points to fit a plane to
// (defaultThinningRadius).
constexpr double kDefaultRhoPercent = 2.0;

// The falloff of the pull with distance (ApproximationTarget::falloff), in thinning radii.
constexpr double kFalloffRhos = 3.0;

struct Targets {
    std::vector<std::vector<model::Vec3>> points; // per surface
    std::vector<std::vector<model::Vec3>> normals;
};

// Every thinned point to the surface nearest to it (its nearest dense sample).
Targets assignToSurfaces(const std::vector<model::CompositeSurface>& surfaces,
                         const model::reference::ThinningResult& thinned) {
    const model::reference::SurfaceSamples samples = model::reference::sampleDensely(surfaces, 8);
    const model::reference::PointIndex index(samples.positions);
    Targets targets;
    targets.points.resize(surfaces.size());
    targets.normals.resize(surfaces.size());
    for (const model::reference::ThinnedPoint& p : thinned.points) {
        const std::size_t sample = index.nearest(p.position).index;
        const std::size_t s = samples.pieces[samples.piece[sample]].surface;
        targets.points[s].push_back(p.position);
        targets.normals[s].push_back(p.normal);
    }
    return targets;
}

} // namespace

int runApproximateCommand(const SubcommandArguments& args) {
    const std::string target = args.positionals(1, "a mesh or point cloud file").front();
    const std::string output = args.required("o", "the output file is missing (use -o FILE)");
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
                             "to start from flat strips.");
        }
    }
    io::ReferenceImportResult read = io::readReferenceShape(target);
    if (read.error) {
        std::cerr << "devsurf-cli: " << referenceImportSentence(*read.error, target) << "\n";
        return 2;
    }
    const std::vector<model::Vec3>& points = read.shape.points;
    const double diagonal = model::reference::boundingBoxDiagonal(points);
    if (rho == 0.0) {
        rho = std::max(kDefaultRhoPercent / 100.0 * diagonal,
                       model::reference::defaultThinningRadius(points));
    }
    const model::reference::ThinningResult thinned = model::reference::thinReference(points, rho);
    if (thinned.points.size() < 3 * static_cast<std::size_t>(strips)) {
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

    if (!from) {
        // K clusters of the thinned points (k-means), one PCA strip each.
        std::vector<model::Vec3> positions;
        for (const model::reference::ThinnedPoint& p : thinned.points) {
            positions.push_back(p.position);
        }
        const model::SplineSpace space{3, 2, intervals};
        for (const std::vector<std::size_t>& cluster :
             model::reference::clusterPoints(positions, strips)) {
            std::vector<model::Vec3> patch;
            for (std::size_t i : cluster) {
                patch.push_back(positions[i]);
            }
            model::CompositeSurface strip;
            try {
                strip = model::reference::initialStrip(patch, space);
            } catch (const std::invalid_argument&) {
                continue; // a cluster on a line or of fewer than 3 points: no strip
            }
            strip.setName("strip " + std::to_string(project.surfaces.size() + 1));
            project.addSurface(std::move(strip));
        }
        if (project.surfaces.empty()) {
            throw InputError("the points of '" + target +
                             "' lie on a line; no strip can be fitted to them.");
        }
    }
    const Targets targets = assignToSurfaces(project.surfaces, thinned);

    solver::JobRequest request;
    request.kind = solver::JobKind::Approximate;
    request.iterations = iterations;
    request.surfaces = project.surfaces;
    for (std::size_t s = 0; s < project.surfaces.size(); ++s) {
        if (targets.points[s].size() < 3) {
            continue; // too far from the target to be pulled: stays as it is
        }
        auto t = std::make_shared<solver::ApproximationTarget>();
        t->points = targets.points[s];
        t->normals = targets.normals[s];
        t->borderReach = rho;
        t->falloff = kFalloffRhos * rho;
        request.targets[static_cast<int>(s)] = std::move(t);
    }
    int surfaceShown = -1;
    auto progress = [&](const solver::JobProgress& step) {
        if (step.surface != surfaceShown) {
            surfaceShown = step.surface;
            const std::size_t s = static_cast<std::size_t>(step.surface);
            std::cout << "Surface " << step.surface + 1 << " (" << project.surfaces[s].name()
                      << "): " << targets.points[s].size() << " target points, " << step.variables
                      << " variables, " << step.rows << " rows\n";
        }
        const solver::IterationStats& it = *step.stats;
        char line[256];
        std::snprintf(line, sizeof line,
                      "iteration %3d  residual %.3e  assembly %.3f ms  factorisation %.3f ms  "
                      "solve %.3f ms\n",
                      step.done, it.maxConstraintResidual, it.assemblyMs, it.factorizationMs,
                      it.solveMs);
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
        if (a.summary.status == solver::Status::StoppedBeforeDegenerate) {
            std::cout << "  stopped at the last valid state" << refusedText(a) << "\n";
        }
    }
    std::cout << "Time: " << static_cast<long>(outcome.elapsedMs) << " ms\n";
    project.surfaces = outcome.surfaces;
    if (std::find(project.referenceShapes.begin(), project.referenceShapes.end(), read.shape) ==
        project.referenceShapes.end()) {
        project.referenceShapes.push_back(read.shape);
    }
    const model::reference::DistanceReport report =
        model::reference::measureDistance(project.surfaces, points);
    printDistanceReport(report, points.size());
    writeProject(project, output);
    std::cout << "Wrote " << output << "\n";
    return 0;
}

} // namespace devsurf::app
