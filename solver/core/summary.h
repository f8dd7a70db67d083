#pragma once

#include <string>
#include <vector>

namespace devsurf::solver {

enum class Status {
    Converged,           // residualTolerance reached
    IterationLimit,      // ran maxIterations
    Cancelled,           // the cancel flag was raised
    NonFiniteValue,      // a residual, Jacobian entry or step was NaN/Inf
    FactorizationFailed, // CHOLMOD failed (not positive definite, out of memory, …)
    InvalidProblem,      // inconsistent structure (column out of range, wrong row count, …)
    // SolveSession: the next iterate was a degenerate surface (a ruling, curve or patch
    // collapsed); the session stays at the last valid one, its result.
    StoppedBeforeDegenerate,
};

const char* toString(Status status);

struct IterationStats {
    int iteration = 0; // 0-based, within this solve()
    double eps1 = 0.0;
    double eps2 = 0.0;
    double proximity = 0.0; // μ (Options::proximityFactor)
    // At the new iterate x_{k+1}: largest |φ| over constraint rows with non-zero weight and
    // Σ w² φ² over energy rows (without ε₁).
    double maxConstraintResidual = 0.0;
    double energy = 0.0;
    double stepNorm = 0.0;      // ‖x_{k+1} − x_k‖
    double stepFraction = 1.0;  // of the linear step taken (Options::guardShrinkLimit)
    bool rejected = false;      // the step raised the constraint merit; x_k was kept
    bool repeated = false;      // factorised again with Options::eps2 after a failure
    bool guardsEngaged = false; // guards the step crossed were held at their bounds, stepped again
    // No factorisation: the step solved the last one with this iterate's right-hand side
    // (Options::reuseFactorization).
    bool factorizationReused = false;
    // A reused factorisation's step was undone: factorised afresh (Options::reusedStepMeritRise).
    bool reuseUndone = false;
    // The reused factorisation was made on another thread (Options::backgroundFactorization).
    bool backgroundFactor = false;
    double assemblyMs = 0.0;      // term evaluation + normal-equation fill
    double factorizationMs = 0.0; // numeric (plus symbolic in baseline mode)
    double solveMs = 0.0;         // triangular solves
    double factorFlops = 0.0;     // cholmod_common.fl of the factorisation
    double factorNonZeros = 0.0;  // cholmod_common.lnz
};

struct Summary {
    Status status = Status::IterationLimit;
    // A technical note on a failure (a CHOLMOD status, the check that failed), for logs and bug
    // reports; the front ends word `status`, never this.
    std::string detail;
    int iterationsCompleted = 0;
    std::vector<IterationStats> iterations;
    double initialMaxConstraintResidual = 0.0;
    double initialEnergy = 0.0;
    double finalMaxConstraintResidual = 0.0;
    double finalEnergy = 0.0;
    // Options::reportTolerance and whether the final largest constraint residual is within it.
    // A solve can succeed (no error) without reaching it; the caller should then show where
    // (e.g. SurfaceFormulation::faceResiduals).
    double tolerance = 0.0;
    bool toleranceReached = false;
    int variables = 0;
    int rows = 0;
    long long jacobianNonZeros = 0;
    long long normalMatrixNonZeros = 0; // stored triangle
    bool structureReused = false;       // symbolic analysis from a previous solve() reused
    bool supernodal = false;
    bool factorizedInPlace = false; // CHOLMOD factorises our array without a permuted copy
    // Structure build + symbolic analysis in this solve() (0 if reused), and the factorisation
    // of Options::factorizeAhead.
    double analysisMs = 0.0;
    double totalMs = 0.0;

    bool succeeded() const {
        return status == Status::Converged || status == Status::IterationLimit ||
               status == Status::StoppedBeforeDegenerate;
    }
    std::string briefReport() const;
};

} // namespace devsurf::solver
