#include "solver/core/options.h"

#include <algorithm>
#include <cmath>

// The schedules of ε₁, ε₂ and the proximity weight that Options describes.
namespace devsurf::solver {

double epsilon1(const Options& options, int iteration) {
    if (options.eps1Schedule) {
        return options.eps1Schedule(iteration);
    }
    if (iteration < options.eps1Iterations) {
        return options.eps1Initial * std::pow(options.eps1Decay, iteration);
    }
    return options.eps1Final;
}

double epsilon1(const Options& options, int iteration, double residual) {
    const double scheduled = epsilon1(options, iteration);
    if (options.eps1ResidualFactor > 0.0) {
        return std::min(scheduled, options.eps1ResidualFactor * residual);
    }
    return scheduled;
}

double epsilon2(const Options& options, int iteration, double residual) {
    if (options.eps2Schedule) {
        return options.eps2Schedule(iteration, residual);
    }
    if (options.adaptiveEps2 && epsilon1(options, iteration) == 0.0) {
        return std::clamp(residual, std::min(options.eps2Minimum, options.eps2), options.eps2);
    }
    return options.eps2;
}

double proximityWeight(const Options& options, double residual) {
    if (options.proximityFactor <= 0.0) {
        return 0.0;
    }
    double scaled = residual;
    if (residual < options.proximityThreshold) {
        // Below the threshold μ decays with the square of the residual (continuously), so the
        // pull towards the start does not slow the final, fast convergence.
        scaled *= residual / options.proximityThreshold;
    }
    return std::min(options.proximityMaximum, options.proximityFactor * scaled);
}

std::function<double(int, double)> residualEps2Schedule(double maximum, double minimum,
                                                        double factor) {
    return [maximum, minimum, factor](int, double residual) {
        return std::clamp(factor * residual, minimum, maximum);
    };
}

} // namespace devsurf::solver
