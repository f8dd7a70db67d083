#include "approximation_bench.h"

#include "bench_json.h"

#include "io/reference/reference_import.h"
#include "model/reference/distance_report.h"
#include "model/strip_joining.h"
#include "solver/core/blas_info.h"
#include "solver/quality/quality_measures.h"
#include "solver/session/approximation_setup.h"
#include "solver/session/solve_job.h"

#include <algorithm>
#include <chrono>
#include <cstdio>

namespace devsurf::bench {

namespace {

using Clock = std::chrono::steady_clock;

double msSince(Clock::time_point start) {
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

void log(const ApproximationBenchOptions& options, const std::string& line) {
    if (options.log) {
        options.log(line);
    }
}

} // namespace

ApproximationBenchReport runApproximationBench(const ApproximationBenchOptions& options) {
    ApproximationBenchReport report;
    report.target = options.target;
    const io::ReferenceImportResult read = io::readReferenceShape(options.target);
    if (read.error) {
        report.error = "cannot read '" + options.target + "'" +
                       (read.error->detail.empty() ? "" : ": " + read.error->detail);
        return report;
    }
    const std::vector<model::Vec3>& points = read.shape.points;
    report.targetPoints = points.size();

    const Clock::time_point start = Clock::now();
    solver::ApproximationOptions setupOptions;
    setupOptions.strips = options.strips;
    setupOptions.intervals = options.intervals;
    setupOptions.rho = options.rho;
    setupOptions.iterations = options.iterations;
    const solver::ApproximationSetup setup = solver::prepareApproximation(points, {}, setupOptions);
    report.setupMs = msSince(start);
    report.diagonalMm = setup.target.diagonal;
    report.rhoMm = setup.target.rho;
    report.thinnedPoints = setup.target.thinned.points.size();
    if (setup.error != solver::ApproximationSetup::Error::None) {
        report.error = "the setup found no strips to pull (too few, collinear or far points)";
        return report;
    }
    report.surfaces = static_cast<int>(setup.surfaces.size());
    for (const model::CompositeSurface& surface : setup.surfaces) {
        report.strips += static_cast<int>(surface.faces().size());
        report.controlPoints += static_cast<int>(surface.controlPointCount());
    }
    log(options, "approximation: " + std::to_string(report.strips) + " strips on " +
                     std::to_string(report.thinnedPoints) + " thinned points");

    solver::SolveJob job;
    int lastSurface = -1;
    const solver::JobOutcome outcome =
        job.run(setup.request, nullptr, [&](const solver::JobProgress& p) {
            if (p.surface != lastSurface && p.surface % 10 == 0) {
                log(options, "approximation: strip " + std::to_string(p.surface + 1));
            }
            lastSurface = p.surface;
        });
    report.totalSeconds = msSince(start) / 1000.0;
    if (!outcome.ok) {
        report.error = "the solve job failed: " + outcome.failure.detail;
        return report;
    }
    for (const solver::SurfaceAssessment& a : outcome.assessments) {
        const solver::Summary& s = a.summary;
        report.variables += s.variables;
        report.iterations = std::max(report.iterations, s.iterationsCompleted);
        report.dampedStrips += a.dampedApproximation ? 1 : 0;
        if (s.iterations.empty()) {
            continue;
        }
        double assembly = 0.0;
        double factorize = 0.0;
        double solve = 0.0;
        for (const solver::IterationStats& it : s.iterations) {
            assembly += it.assemblyMs;
            factorize += it.factorizationMs;
            solve += it.solveMs;
        }
        const double n = static_cast<double>(s.iterations.size());
        report.assemblyMs += assembly / n;
        report.factorizeMs += factorize / n;
        report.solveMs += solve / n;
    }
    report.iterationMs = report.assemblyMs + report.factorizeMs + report.solveMs;
    for (const model::CompositeSurface& surface : outcome.surfaces) {
        const double worst = solver::worstDevelopability(surface);
        report.developabilityMax = std::max(report.developabilityMax, worst);
        report.stripsDevelopable +=
            worst <= kDevelopableResidual ? static_cast<int>(surface.faces().size()) : 0;
        report.parts += static_cast<int>(model::surfaceParts(surface).size());
    }
    log(options, "approximation: measuring the distance");
    model::reference::DistanceOptions distanceOptions;
    distanceOptions.triangles = &read.shape.triangles; // a mesh: to its triangles
    const model::reference::DistanceReport distance =
        model::reference::measureDistance(outcome.surfaces, points, distanceOptions);
    report.targetToSurface = distance.targetToSurface;
    report.surfaceToTarget = distance.surfaceToTarget;
    report.hausdorffPercent = 100.0 * distance.hausdorff() / distance.diagonal;
    report.coverage = distance.coverage;
    return report;
}

namespace {

std::string distanceJson(const model::reference::OneSidedDistance& d) {
    return "{ \"mean_mm\": " + number(d.mean) + ", \"p95_mm\": " + number(d.percentile95) +
           ", \"max_mm\": " + number(d.max) + ", \"mean_percent\": " + number(d.meanPercent) +
           ", \"p95_percent\": " + number(d.percentile95Percent) +
           ", \"max_percent\": " + number(d.maxPercent) + " }";
}

const char* verdict(bool met) {
    return met ? "met" : "MISSED";
}

} // namespace

void printApproximationBench(const ApproximationBenchReport& r, bool json, std::ostream& out) {
    const solver::BlasInfo blas = solver::detectBlas();
    const double meanPercent =
        std::max(r.targetToSurface.meanPercent, r.surfaceToTarget.meanPercent);
    const double ratio = r.iterationMs / kPaperIterationMs;
    const bool ok = r.error.empty();
    const bool stripsMet = ok && r.strips <= kPaperStrips;
    const bool developableMet = ok && r.stripsDevelopable == r.strips;
    const bool hausdorffMet = ok && r.hausdorffPercent <= kHausdorffPercentTarget;
    const bool meanMet = ok && meanPercent <= kMeanPercentTarget;
    const bool timeMet = ok && r.totalSeconds <= kTotalSecondsTarget;
    const bool iterationMet = ok && ratio <= kIterationRatioTarget;
    if (json) {
        out << "{\n  \"blas\": " << quoted(blas.describe())
            << ",\n  \"blas_kernel\": " << quoted(blas.kernel)
            << ",\n  \"approximation\": {\n    \"target\": " << quoted(r.target)
            << ",\n    \"error\": " << quoted(r.error)
            << ",\n    \"target_points\": " << r.targetPoints
            << ",\n    \"thinned_points\": " << r.thinnedPoints
            << ",\n    \"diagonal_mm\": " << number(r.diagonalMm)
            << ",\n    \"rho_mm\": " << number(r.rhoMm) << ",\n    \"strips\": " << r.strips
            << ",\n    \"surfaces\": " << r.surfaces << ",\n    \"parts\": " << r.parts
            << ",\n    \"watertight\": " << (ok && r.parts == 1 ? "true" : "false")
            << ",\n    \"control_points\": " << r.controlPoints
            << ",\n    \"variables\": " << r.variables << ",\n    \"iterations\": " << r.iterations
            << ",\n    \"damped_strips\": " << r.dampedStrips
            << ",\n    \"ms_per_iter\": { \"assembly\": " << number(r.assemblyMs)
            << ", \"factorize\": " << number(r.factorizeMs) << ", \"solve\": " << number(r.solveMs)
            << ", \"total\": " << number(r.iterationMs) << " }"
            << ",\n    \"setup_ms\": " << number(r.setupMs)
            << ",\n    \"total_s\": " << number(r.totalSeconds)
            << ",\n    \"developability_max\": " << number(r.developabilityMax)
            << ",\n    \"strips_developable\": " << r.stripsDevelopable
            << ",\n    \"target_to_surface\": " << distanceJson(r.targetToSurface)
            << ",\n    \"surface_to_target\": " << distanceJson(r.surfaceToTarget)
            << ",\n    \"hausdorff_percent\": " << number(r.hausdorffPercent)
            << ",\n    \"coverage\": " << number(r.coverage)
            << ",\n    \"paper\": { \"strips\": " << kPaperStrips
            << ", \"control_points\": " << kPaperControlPoints
            << ", \"variables\": " << kPaperVariables
            << ", \"ms_per_iter\": " << number(kPaperIterationMs) << " }"
            << ",\n    \"paper_ratio\": " << number(ratio)
            << ",\n    \"targets\": { \"strips\": " << (stripsMet ? "true" : "false")
            << ", \"developable\": " << (developableMet ? "true" : "false")
            << ", \"hausdorff\": " << (hausdorffMet ? "true" : "false")
            << ", \"mean\": " << (meanMet ? "true" : "false")
            << ", \"time\": " << (timeMet ? "true" : "false")
            << ", \"per_iteration\": " << (iterationMet ? "true" : "false") << " }\n  }\n}\n";
        return;
    }
    out << "BLAS: " << blas.describe() << "\n";
    if (!ok) {
        out << "Approximation of " << r.target << ": " << r.error << "\n";
        return;
    }
    char line[4096];
    std::snprintf(line, sizeof line,
                  "%zu points (diagonal %.1f mm), thinned with %.3g mm to "
                  "%zu\n"
                  "  %d strips, %d control points, %d variables (paper: %d, %d, %d)\n"
                  "  %d surface(s) in %d part(s)%s\n"
                  "  %d iterations at most, %d strips pulled again damped\n"
                  "  per iteration over all strips: assembly %.2f ms, factorize %.2f ms, solve "
                  "%.2f ms, total %.2f ms (%.4f of the paper's %.0f ms)\n"
                  "  setup %.0f ms, setup and solve %.2f s\n"
                  "  developable: %d of %d strips at most %.0e (largest %.2e)\n"
                  "  target to surface: mean %.3f %%, p95 %.3f %%, max %.3f %% of the diagonal\n"
                  "  surface to target: mean %.3f %%, p95 %.3f %%, max %.3f %%\n"
                  "  Hausdorff %.3f %%, coverage %.1f %%\n",
                  r.targetPoints, r.diagonalMm, r.rhoMm, r.thinnedPoints, r.strips, r.controlPoints,
                  r.variables, kPaperStrips, kPaperControlPoints, kPaperVariables, r.surfaces,
                  r.parts, r.parts == 1 ? ": watertight" : "", r.iterations, r.dampedStrips,
                  r.assemblyMs, r.factorizeMs, r.solveMs, r.iterationMs, ratio, kPaperIterationMs,
                  r.setupMs, r.totalSeconds, r.stripsDevelopable, r.strips, kDevelopableResidual,
                  r.developabilityMax, r.targetToSurface.meanPercent,
                  r.targetToSurface.percentile95Percent, r.targetToSurface.maxPercent,
                  r.surfaceToTarget.meanPercent, r.surfaceToTarget.percentile95Percent,
                  r.surfaceToTarget.maxPercent, r.hausdorffPercent, 100.0 * r.coverage);
    out << "Approximation of " << r.target << ": " << line;
    std::snprintf(line, sizeof line,
                  "Targets: at most %d strips %s; every strip developable %s; Hausdorff <= %.0f "
                  "%% %s; mean <= %.1f %% %s; <= %.0f s %s; per iteration <= 1/20 of the paper's "
                  "%s\n",
                  kPaperStrips, verdict(stripsMet), verdict(developableMet),
                  kHausdorffPercentTarget, verdict(hausdorffMet), kMeanPercentTarget,
                  verdict(meanMet), kTotalSecondsTarget, verdict(timeMet), verdict(iterationMet));
    out << line;
}

} // namespace devsurf::bench
