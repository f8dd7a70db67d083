#pragma once

#include <atomic>
#include <functional>

namespace devsurf::solver {

struct IterationStats;

enum class FactorizationMethod {
    Supernodal, // CHOLMOD supernodal LLᵀ (BLAS-3)
    Simplicial, // CHOLMOD simplicial LDLᵀ
    // CHOLMOD's own choice: supernodal once the factorisation's flops per non-zero of L reach
    // 40 (its default switch).
    Automatic,
    // Both, timed once per structure (in a process) on the first iterate; the faster is kept.
    // Near a tie the choice varies between runs, and so do the last bits of the result.
    Measured,
    // Automatic's rule with our own switch, kCalibratedSupernodalSwitch: decided by the
    // structure alone, so identical input gives bit-identical results. The default.
    Calibrated,
};

// The flops per non-zero of L from which the supernodal factorisation is faster, with the
// single-threaded OpenBLAS that setup.sh selects (measurements: docs/tuning.md).
inline constexpr double kCalibratedSupernodalSwitch = 30.0;

// Options of GuidedProjection::solve (in the style of Ceres' Solver::Options).
struct Options {
    int maxIterations = 10;

    // ε₁ schedule of the paper (Fig. 17): ε₁(i) = eps1Initial · eps1Decay^i for the first
    // eps1Iterations iterations, then eps1Final. `i` counts from scheduleOffset, so an
    // interactive caller running one iteration per solve() can continue the schedule.
    double eps1Initial = 0.1;
    double eps1Decay = 0.9;
    int eps1Iterations = 5;
    double eps1Final = 0.0;
    int scheduleOffset = 0;
    // If set, replaces the schedule above: ε₁ as a function of the iteration index.
    std::function<double(int)> eps1Schedule;
    // ε₁ is at most this factor times the largest constraint residual of the current iterate
    // (0 disables the cap), so energies such as fairness act only while the constraints are
    // violated: a valid design is not pulled towards straight lines (docs/tuning.md).
    double eps1ResidualFactor = 1000.0;

    // Damping ε₂ of ‖x − x_k‖² (paper: 0.01, useful range 1e-6 … 1e-2).
    double eps2 = 0.01;
    // Once the ε₁ phase is over (ε₁ = 0), ε₂ = clamp(r, eps2Minimum, eps2) with r the largest
    // constraint residual of the current iterate: a constant ε₂ converges only linearly on
    // nearly flat, ill-conditioned parts (docs/tuning.md). If a factorisation fails with the
    // smaller ε₂, the iteration is repeated with ε₂ = eps2.
    bool adaptiveEps2 = true;
    // The floor of the adaptive ε₂ (the rough-start configuration uses 3e-4, docs/tuning.md).
    double eps2Minimum = 1e-6;
    // If set, replaces the constant ε₂: a function of the iteration index and of the largest
    // constraint residual at the current iterate x_k.
    std::function<double(int, double)> eps2Schedule;

    // Proximity to the start: families of role Proximity (the formulation's pull of every
    // point towards the state the solve started from) are weighted by
    // μ = min(proximityMaximum, proximityFactor · r), r the largest constraint residual of the
    // current iterate. μ fades as the constraints improve, so the iteration ends near the start
    // instead of at a distant, crumpled solution, and is 0 on a valid design. 0 disables (the
    // default; useRoughStartConfiguration uses 1; measured factors: docs/tuning.md).
    double proximityFactor = 0.0;
    double proximityMaximum = 1.0;
    // Below this residual μ falls with r² instead of r (continuously), so that the pull does
    // not slow the final convergence (docs/tuning.md).
    double proximityThreshold = 1e-2;

    // Step length: a step that would shrink a guarded length (a MinimumLengthTerm row of a
    // constraint family: rulings, curve speeds, the spokes of vertex stars) below this
    // fraction of its current length anywhere along the step is shortened as a whole. The
    // guards are one-sided, so the linearised step does not see them until it has crossed
    // them. 0 disables; the sessions of solver/session use 0.5 (docs/tuning.md).
    double guardShrinkLimit = 0.0;

    // Iterations in a row that may reuse the last factorisation (a chord step of Newton's
    // method: this iterate's residuals, the factorised matrix of an earlier one), saving the
    // fill and the factorisation. 0 (the default) factorises in every iteration. Never reused
    // after the fixed variables changed or a factorisation failed. The sessions use 1 while a
    // drag moves on a large model (kDragFactorizationReuse).
    int reuseFactorization = 0;
    // ... and only a factorisation of at least this many flops (cholmod_common.fl), so that
    // the choice depends on the structure alone.
    double reuseFactorizationMinimumFlops = 0.0;
    // A reused step whose constraint merit rises above this multiple of max(merit before,
    // reusedStepMeritFloor) is undone and factorised afresh (0: never).
    double reusedStepMeritRise = 0.0;
    double reusedStepMeritFloor = 1e-2;
    // While reusing: each iteration's N is also factorised on another thread, and later steps
    // reuse the newest such factorisation (BackgroundFactor).
    bool backgroundFactorization = false;

    // Stop early once the ε₁ phase is over and the largest constraint residual is at most
    // this (0 disables early stopping).
    double residualTolerance = 0.0;

    // The largest constraint residual a solve should end at; Summary::toleranceReached and
    // its report say whether it did (it does not stop the iteration, residualTolerance does).
    double reportTolerance = 1e-8;

    FactorizationMethod factorization = FactorizationMethod::Calibrated;

    // Checked between iterations; when it becomes true, solve() returns the last completed
    // iterate with Status::Cancelled.
    const std::atomic<bool>* cancel = nullptr;

    // Called after every iteration (on the solving thread).
    std::function<void(const IterationStats&)> progress;

    // Called on every new iterate before its residuals are evaluated: moves auxiliary
    // variables onto constraints they satisfy exactly after a scaling (SolveSession normalises
    // the unit normals of planar faces and cones, SurfaceFormulation::normaliseUnitNormals).
    // Unset: nothing.
    std::function<void(double* x)> project;

    // Record per-iteration statistics in Summary::iterations.
    bool recordIterations = true;
};

// ε₁ for iteration `iteration` (counted from 0, without scheduleOffset) under `options`, by
// the schedule alone, and capped by eps1ResidualFactor × `residual` (the largest constraint
// residual at the current iterate).
double epsilon1(const Options& options, int iteration);
double epsilon1(const Options& options, int iteration, double residual);
// ε₂ for iteration `iteration` (counted from 0, without scheduleOffset) at an iterate whose
// largest constraint residual is `residual`.
double epsilon2(const Options& options, int iteration, double residual);

// μ, the weight multiplier of proximity families, at an iterate whose largest constraint
// residual is `residual`.
double proximityWeight(const Options& options, double residual);

// The residual-driven ε₂ schedule: ε₂ = clamp(factor · residual, minimum, maximum).
std::function<double(int, double)> residualEps2Schedule(double maximum = 0.01,
                                                        double minimum = 1e-6, double factor = 1.0);

} // namespace devsurf::solver
