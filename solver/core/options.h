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
    // The timing costs four factorisations and, near a tie or under load, differs between runs,
    // so that two runs of the same input can take different factorisations and end a few
    // ulps apart (the annulus lifted 100 mm keeping lengths: 1.3e-7 of its diameter).
    Measured,
    // The same rule as Automatic with the switch kCalibratedSupernodalSwitch that measurement
    // on our stack gives: decided by the structure alone, so identical input gives
    // bit-identical results in every run, with no timing at the first iterate. The default.
    Calibrated,
};

// The flops per non-zero of L from which the supernodal factorisation is faster with the
// single-threaded OpenBLAS that setup.sh selects and CHOLMOD's parallel regions kept to one
// thread (solver/core/sparse_cholesky.cpp). Measured per iteration (supernodal / simplicial
// ms, devsurf-cli solve from 0.1 % noise): mixed 0.034 / 0.031 at 23 flops per non-zero,
// sheet 0.21 / 0.24 at 33, cylinder 0.32 / 0.43 at 33, fig6 0.043 / 0.076 at 39, fig8
// 0.22 / 0.34 at 42; the annulus at sizes 6 … 28 (2,144 … 45,732 variables) 1.6 / 2.4 at
// 55, 8.1 / 18 at 95, 30 / 103 at 158, 67 / 313 at 213. (With CHOLMOD's four threads on our
// two cores the supernodal factorisation was slower than the simplicial one up to 158.)
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
    // (0 disables the cap). Fairness and other energies then act only while the constraints
    // are violated: a design that already satisfies them (residual ~1e-16) is not pulled
    // towards straight lines, and a rough start still gets the full schedule. (Measured from
    // 0.1 % noise: a factor of 1 weakened fairness too early, det 1e-5 on the annulus instead
    // of 1e-11 with 1000.) (With the
    // paper's schedule alone, 10 iterations with no vertex fixed shrank the exactly
    // developable cylinder example from radius 98 to 6.8 mm.)
    double eps1ResidualFactor = 1000.0;

    // Damping ε₂ of ‖x − x_k‖² (paper: 0.01, useful range 1e-6 … 1e-2).
    double eps2 = 0.01;
    // Once the ε₁ phase is over (ε₁ = 0), shrink ε₂ with the largest constraint residual r of
    // the current iterate: ε₂ = clamp(r, eps2Minimum, eps2), as Levenberg–Marquardt methods
    // do. A constant ε₂ converges only linearly on the nearly flat, ill-conditioned parts of a
    // surface (measured: residual 1e-7 after 30 iterations on the sheet); the adaptive one
    // reaches 1e-15 within 10 iterations there. If a factorisation fails with the smaller ε₂,
    // the iteration is repeated with ε₂ = eps2.
    bool adaptiveEps2 = true;
    // (The rough-start configuration uses 3e-4: with the proximity to the start, a smaller
    // floor let the normal splines' free scale drift in 10 iterations, measured det 3e-6
    // against 6e-7 on the sheet from 1 % of the diameter and a collapse of one annulus seed.)
    double eps2Minimum = 1e-6;
    // If set, replaces the constant ε₂: a function of the iteration index and of the largest
    // constraint residual at the current iterate x_k. Shrinking ε₂ with the residual (as
    // Levenberg–Marquardt methods do) keeps the fast local convergence of Gauss–Newton on
    // redundant, ill-conditioned constraint sets while damping the first, long steps.
    std::function<double(int, double)> eps2Schedule;

    // Once the ε₁ phase is over, a step that increases Σ w² φ² of the constraint rows is
    // rejected (the iterate stays, the iteration counts) and ε₂ is raised tenfold for the next
    // step; accepted steps lower that boost again, as Levenberg–Marquardt methods do. Off by
    // default: measured from 0.1 % noise it changed nothing on the sheet, annulus and mixed
    // examples and made the cylinder worse (det 4.8e-6 against 1.8e-6).
    bool rejectWorseSteps = false;
    // Levenberg–Marquardt step control in every iteration (also during the ε₁ phase): a step
    // that increases Σ w² φ² of the constraint rows (guards included) is rejected and ε₂ is
    // multiplied by 10 for the next step, beyond `eps2`; an accepted step divides that boost
    // by 10 again. Rejected steps count as iterations. Off: measured (10 seeds, 10
    // iterations, with the rough-start configuration) it rejected the long first steps but
    // the rejections used up the iterations: det worst 0.27 instead of 5e-3 on the annulus
    // from 1 % of the diameter, 7e-5 instead of 2e-5 on the cylinder; alone, on the paper's
    // configuration, worse on every example (sheet 0.16 from 10 % edge noise).
    bool levenbergMarquardt = false;

    // Proximity to the start: families of role Proximity (the formulation's pull of every
    // point towards the state the solve started from) are weighted by
    // μ = min(proximityMaximum, proximityFactor · r), r the largest constraint residual of the
    // current iterate. μ decays only as the constraints improve, so the iteration is led to a
    // solution near the start instead of a distant, crumpled one, and vanishes on a design that
    // already satisfies them. 0 disables (the default; see useRoughStartConfiguration in
    // solver/formulation/surface_formulation.h for the configuration it belongs to and its
    // measurements). Measured factors (with normalised rows, 10 seeds): 0.3 let the annulus
    // from 1 % of the diameter crumple (det 0.18), 3 held the start too firmly (det 0.96), 1
    // is best (5e-3); a maximum of 10 instead of 1 changed little (det 0.09 on that annulus).
    double proximityFactor = 0.0;
    double proximityMaximum = 1.0;
    // Below this residual μ falls with r² instead of r (continuously), so the pull towards
    // the start does not slow the final convergence. Measured with the rough-start
    // configuration (det worst over 10 seeds): 0 (μ ∝ r throughout) ended at 1.9e-4 on the
    // sheet from 1 % of the diameter and 3.4e-7 on the cylinder from 0.1 % (4 seeds); 1e-2 at
    // 6.2e-7 and 3.0e-8; 0.1 lost the annulus from 1 % (1.3e-2 against 5.5e-3). (Switching μ
    // off abruptly below the threshold was worse: μ flickered on and off between iterations.)
    double proximityThreshold = 1e-2;

    // Step length: a step that would shrink a guarded length (a MinimumLengthTerm row of a
    // constraint family: rulings, curve speeds, the spokes of vertex stars) below this
    // fraction of its current length anywhere along the step is shortened, as a whole, so that
    // it does not (0 disables; the sessions of solver/session use 0.5). The guards are
    // one-sided: while a length is above its minimum its row is zero and the linearised step
    // does not see it, so one step took a ruling from its full length to a sixth of it (the
    // annulus of size 14, an inner vertex lifted by a tenth of the diameter, stretching) and
    // the guard, active only then, pulled it back in the next; the iteration alternated
    // between the two and crumpled. Measured with devsurf-bench --drag on that annulus
    // (residual after the drag, fold-over places, overlapping patches; the bench's timing makes
    // single runs vary): 0 → 0.95 … 3.1, 146 … 195, 13 … 16; 0.5 → 0.50, 35, 17; 0.6 → 0.40,
    // 12, 14; 0.7 → 0.16, 8, 13; 0.9 → 0.04, 7, 23. None converges: the drag still asks for a
    // degenerate solution there. Above 0.5 the shortened steps slowed legitimate motions:
    // Move/Rotate with Keep developable on the annulus ended at developability 3e-8 (0.6), 2e-7
    // (0.7) and 5e-5 (0.9) against 5e-9 (0.5) and 2e-8 (without). Valid designs, Solve from
    // rough starts (10 seeds of the sheet, annulus, cylinder from 1 % of the diameter) and the
    // Fig. 8 drags are unchanged to the last digit (no step is shortened there).
    double guardShrinkLimit = 0.0;

    // Iterations in a row that may reuse the last factorisation instead of factorising: the
    // step solves the factorised matrix (of an earlier iterate's Jacobian, weights and ε₂) with
    // the right-hand side of this iterate's residuals and that same Jacobian, a chord step of
    // Newton's method. It costs the evaluation and the triangular solves, not the fill and the
    // factorisation. 0 (the default) factorises in every iteration. A factorisation is reused
    // only while the fixed variables are those it was made with, and never after one failed.
    // The sessions of solver/session use 1 while a drag moves on a large model (see
    // kDragFactorizationReuse).
    int reuseFactorization = 0;
    // ... and only a factorisation of at least this many flops (cholmod_common.fl), so that
    // the choice depends on the structure alone.
    double reuseFactorizationMinimumFlops = 0.0;

    // Stop early once the ε₁ phase is over and the largest constraint residual is at most
    // this (0 disables early stopping).
    double residualTolerance = 0.0;

    // The largest constraint residual a solve should end at; Summary::toleranceReached and
    // its report say whether it did (it does not stop the iteration, residualTolerance does).
    double reportTolerance = 1e-8;

    FactorizationMethod factorization = FactorizationMethod::Calibrated;

    // Benchmark reference: rebuild the normal matrix from triplets and run a full symbolic and
    // numeric factorisation every iteration (same terms, no caching).
    bool baseline = false;

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
