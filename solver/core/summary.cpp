#include "solver/core/summary.h"

#include <cstdio>

namespace devsurf::solver {

const char* toString(Status status) {
    switch (status) {
    case Status::Converged:
        return "converged";
    case Status::IterationLimit:
        return "iteration limit";
    case Status::Cancelled:
        return "cancelled";
    case Status::NonFiniteValue:
        return "non-finite value";
    case Status::FactorizationFailed:
        return "factorisation failed";
    case Status::InvalidProblem:
        return "invalid problem";
    case Status::StoppedBeforeDegenerate:
        return "stopped before a degenerate surface";
    }
    return "unknown";
}

std::string Summary::briefReport() const {
    char buffer[640];
    char tolerancePart[96] = "";
    if (tolerance > 0.0) {
        std::snprintf(tolerancePart, sizeof tolerancePart, ", tolerance %.1e %s", tolerance,
                      toleranceReached ? "reached" : "NOT reached");
    }
    std::snprintf(buffer, sizeof buffer,
                  "%s after %d iterations: max residual %.3e -> %.3e%s, energy %.3e -> %.3e, "
                  "%d variables, %d rows, %s, %.1f ms%s%s",
                  toString(status), iterationsCompleted, initialMaxConstraintResidual,
                  finalMaxConstraintResidual, tolerancePart, initialEnergy, finalEnergy, variables,
                  rows, supernodal ? "supernodal" : "simplicial", totalMs,
                  detail.empty() ? "" : ": ", detail.c_str());
    return buffer;
}

} // namespace devsurf::solver
