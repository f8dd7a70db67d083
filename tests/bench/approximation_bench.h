#pragma once

// `devsurf-bench --approximation TARGET`: a reference shape covered by developable strips the
// way `devsurf-cli approximate TARGET --strips K` does it (the same setup and solve job), timed
// and measured against the paper's Fig. 10 setting (the Stanford bunny: 94 strips, 303 control
// points, 12,777 variables, 0.5 s per iteration) and the targets of the approximation issue.

#include "model/reference/distance_report.h"

#include <functional>
#include <optional>
#include <ostream>
#include <string>

namespace devsurf::bench {

struct ApproximationBenchOptions {
    std::string target; // a mesh or point cloud file (OBJ, PLY, STL, OFF, XYZ, PTS)
    int strips = 94;    // the paper's count for the bunny
    int intervals = 2;  // spline intervals per strip
    std::optional<int> iterations;
    double rho = 0.0; // thinning radius; ≤ 0: the application's default
    std::function<void(const std::string&)> log;
};

struct ApproximationBenchReport {
    std::string target;
    std::string error; // empty unless the target could not be read or approximated
    std::size_t targetPoints = 0;
    std::size_t thinnedPoints = 0;
    double diagonalMm = 0.0;
    double rhoMm = 0.0;
    int strips = 0;        // strips pulled (K-means may give fewer than asked)
    int surfaces = 0;      // the strips laid as separate surfaces, or as one over a patch
    int parts = 0;         // parts of those surfaces after the solve (model::surfaceParts)
    int controlPoints = 0; // over all strips
    int variables = 0;     // over all strips' problems
    int iterations = 0;    // the most any strip took (the damped rerun's included)
    int dampedStrips = 0;  // strips pulled again by the damped recipe
    // One iteration over every strip: per strip the mean of its iterations, summed (ms).
    double assemblyMs = 0.0;
    double factorizeMs = 0.0;
    double solveMs = 0.0;
    double iterationMs = 0.0;
    double setupMs = 0.0;      // reading excluded: thinning, K-means, strips, assignment
    double totalSeconds = 0.0; // setup and solve
    // Sampled normalised developability residual (solver::worstDevelopability) per strip.
    double developabilityMax = 0.0;
    int stripsDevelopable = 0; // strips of surfaces at most kDevelopableResidual
    model::reference::OneSidedDistance targetToSurface; // mm and % of the diagonal
    model::reference::OneSidedDistance surfaceToTarget;
    double hausdorffPercent = 0.0;
    double coverage = 0.0; // fraction of target points within the report's tolerance
};

// The paper's Fig. 10 row and the targets.
inline constexpr int kPaperStrips = 94;
inline constexpr int kPaperControlPoints = 303;
inline constexpr int kPaperVariables = 12777;
inline constexpr double kPaperIterationMs = 500.0;
inline constexpr double kDevelopableResidual = 1e-8;
inline constexpr double kHausdorffPercentTarget = 2.0;
inline constexpr double kMeanPercentTarget = 0.3;
inline constexpr double kTotalSecondsTarget = 60.0;
inline constexpr double kIterationRatioTarget = 1.0 / 20.0; // of the paper's time per iteration

ApproximationBenchReport runApproximationBench(const ApproximationBenchOptions& options);
void printApproximationBench(const ApproximationBenchReport& report, bool json, std::ostream& out);

} // namespace devsurf::bench
