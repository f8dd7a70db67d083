#pragma once

#include <string>
#include <vector>

namespace devsurf::solver {
class Problem;
}

namespace devsurf::bench {

struct CeresResult {
    bool available = false; // built with Ceres
    bool reached = false;   // reached the target residual
    bool hitTimeCap = false;
    int iterations = 0;
    double milliseconds = 0.0; // solver time without our residual check in the callback
    double finalResidual = 0.0;
    std::string message;
};

// Ceres Solver (Levenberg–Marquardt, SPARSE_NORMAL_CHOLESKY) on the constraint rows of
// `problem` (the same residuals, weighted by their family weights; one residual block per row,
// one parameter block per point of 3 variables; fixed points constant), from state x, until
// the largest constraint residual is at most `targetResidual` or `capSeconds` pass.
CeresResult runCeres(const solver::Problem& problem, std::vector<double> x, double targetResidual,
                     double capSeconds);

} // namespace devsurf::bench
