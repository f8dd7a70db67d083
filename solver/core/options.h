#pragma once

#include <atomic>
#include <functional>

namespace devsurf::solver {

struct IterationStats;

enum class FactorizationMethod {
    Supernodal, // CHOLMOD supernodal LLᵀ (BLAS-3)
    Simplicial, // CHOLMOD simplicial LDLᵀ
    Automatic,  // CHOLMOD's own switch (40 flops per non-zero of L)
    Measured,   // both timed once per structure; the faster kept (varies near a tie)
    Calibrated, // Automatic with kCalibratedSupernodalSwitch: reproducible. The default.
};

// Flops per non-zero of L from which supernodal is faster with our serial OpenBLAS.
inline constexpr double kCalibratedSupernodalSwitch = 30.0;

// Options of GuidedProjection::solve.
struct Options {
    int maxIterations = 10;

    // ε₁(i) = eps1Initial · eps1Decay^i for eps1Iterations iterations, then eps1Final (paper,
    // Fig. 17); i counts from scheduleOffset, so one-iteration solve() calls continue it.
    double eps1Initial = 0.1;
    double eps1Decay = 0.9;
    int eps1Iterations = 5;
    double eps1Final = 0.0;
    int scheduleOffset = 0;
    std::function<double(int)> eps1Schedule; // if set, replaces the schedule above
    // Caps ε₁ at this times the largest constraint residual (0: no cap), so energies act only
    // while the constraints are violated.
    double eps1ResidualFactor = 1000.0;

    double eps2 = 0.01; // damping of ‖x − x_k‖²
    // After the ε₁ phase, ε₂ = clamp(r, eps2Minimum, eps2), r the largest constraint residual;
    // a failed factorisation is repeated with ε₂ = eps2.
    bool adaptiveEps2 = true;
    double eps2Minimum = 1e-6;
    // If set, replaces ε₂: a function of the iteration index and the residual r.
    std::function<double(int, double)> eps2Schedule;

    // Families of role Proximity are weighted by μ = min(proximityMaximum, proximityFactor · r),
    // falling with r² below proximityThreshold: the pull towards the start fades as the
    // constraints hold and is 0 on a valid design. 0 disables.
    double proximityFactor = 0.0;
    double proximityMaximum = 1.0;
    double proximityThreshold = 1e-2;

    // A step that would shrink a guarded length (MinimumLengthTerm rows of constraint
    // families) below this fraction of its current length is shortened as a whole. 0: off.
    double guardShrinkLimit = 0.0;
    // Guards (MinimumLengthTerm rows) that the linear step would cross are held at their
    // bounds and the step is made again with a fresh factorisation (an active set for the
    // one-sided rows, one round per iteration).
    bool engageCrossedGuards = false;

    // Iterations in a row that may reuse the last factorisation (chord steps), 0: none; never
    // after the fixed variables changed or a factorisation failed, and only for
    // factorisations of at least reuseFactorizationMinimumFlops.
    int reuseFactorization = 0;
    double reuseFactorizationMinimumFlops = 0.0;
    // A reused step whose merit rises above rise × max(merit before, floor) is undone (0: never).
    double reusedStepMeritRise = 0.0;
    double reusedStepMeritFloor = 1e-2;
    bool backgroundFactorization = false; // the next factorisation made beside (BackgroundFactor)
    // More reuses in a row while a factorisation of a later iterate is being made beside.
    int reuseWhileFactorizingBeside = 0;
    // With maxIterations 0 and reuseFactorization: N factorised at x for the chord steps of the
    // next solve() calls, with the weights of a step whose residual is at least ε₂'s top (a
    // drag's move). A drag prepared while the pointer rests so takes its first move as a chord
    // step (the guard of reusedStepMeritRise still applies).
    bool factorizeAhead = false;

    // Stops once the ε₁ phase is over and the largest constraint residual is at most this
    // (0: never early).
    double residualTolerance = 0.0;
    // The residual a solve should end at (Summary::toleranceReached); it does not stop it.
    double reportTolerance = 1e-8;

    FactorizationMethod factorization = FactorizationMethod::Calibrated;

    // Checked between iterations: solve() then returns the last iterate, Status::Cancelled.
    const std::atomic<bool>* cancel = nullptr;
    std::function<void(const IterationStats&)> progress; // after every iteration
    // Applied to every new iterate before it is evaluated (SolveSession normalises unit
    // normals there).
    std::function<void(double* x)> project;
    bool recordIterations = true; // Summary::iterations
};

// ε₁, ε₂ and μ at an iteration (from 0, scheduleOffset included by the caller) whose largest
// constraint residual is `residual`; epsilon1 without it: the schedule alone.
double epsilon1(const Options& options, int iteration);
double epsilon1(const Options& options, int iteration, double residual);
double epsilon2(const Options& options, int iteration, double residual);
double proximityWeight(const Options& options, double residual);

// ε₂ = clamp(factor · residual, minimum, maximum).
std::function<double(int, double)> residualEps2Schedule(double maximum = 0.01,
                                                        double minimum = 1e-6, double factor = 1.0);

} // namespace devsurf::solver
