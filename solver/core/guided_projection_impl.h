#pragma once

// GuidedProjection's state (private to solver/core): guided_projection.cpp runs the iteration,
// guided_projection_analysis.cpp orders and analyses the structure.

#include "solver/core/analysis_cache.h"
#include "solver/core/background_factor.h"
#include "solver/core/experimental_options.h"
#include "solver/core/guided_projection.h"
#include "solver/core/normal_equations.h"
#include "solver/core/options.h"
#include "solver/core/problem.h"
#include "solver/core/sparse_cholesky.h"
#include "solver/core/summary.h"

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <memory>
#include <vector>

namespace devsurf::solver {

using Clock = std::chrono::steady_clock;

inline double millisecondsSince(Clock::time_point since) {
    return std::chrono::duration<double, std::milli>(Clock::now() - since).count();
}

struct GuidedProjection::Impl {
    NormalEquations equations;
    SparseCholesky cholesky;
    bool analysed = false; // cached mode: cholesky holds the symbolic factor for `equations`
    FactorizationMethod method = FactorizationMethod::Supernodal;
    std::vector<double> x;
    std::vector<double> xNew;
    std::vector<double> step;
    std::vector<double> rhs;
    // The smallest adaptive ε₂ worth trying on this structure: raised to kEps2FloorFactor
    // times a value whose factorisation failed (see the retry in solve()), so that a solve or a
    // drag does not factorise twice in every iteration.
    double eps2Floor = 0.0;
    // ε₂ raised to eps2Floor (never above the configured damping).
    double flooredEps2(double eps2, const Options& options) const {
        return eps2 < eps2Floor ? std::min(eps2Floor, options.eps2) : eps2;
    }
    ExperimentalOptions experimental;
    // The factor by which rejected steps raised ε₂ (ExperimentalOptions::levenbergMarquardt,
    // rejectWorseSteps), kept between solve() calls so that a session's step(1) continues
    // where the last one stopped.
    double eps2Boost = 1.0;
    // The last factorisation, while it may be reused (Options::reuseFactorization): the
    // Jacobian values it was made from, the fixed variables then, and how many steps in a row
    // have reused it.
    bool factorReusable = false;
    std::vector<double> factorJacobian;
    std::uint64_t factorFixedRevision = 0;
    int reusesInARow = 0;
    // Options::backgroundFactorization: the structure's cached analysis (which a background
    // factor takes), two factors made on another thread in turn, the one the chord steps use
    // (-1: `cholesky`), the iterates completed and the one the reused factorisation is of.
    std::shared_ptr<const CachedAnalysis> analysis;
    BackgroundFactor background[2];
    int chordSlot = -1;
    long long iterate = 0;
    long long factorIterate = -1;
    std::vector<double> backgroundWeights;

    void reset() {
        waitForBackground();
        equations = NormalEquations();
        analysis.reset();
        analysed = false;
        eps2Floor = 0.0;
        eps2Boost = 1.0;
        factorReusable = false;
        chordSlot = -1;
    }

    // Before the equations' structure changes: no background factorisation may read it.
    void waitForBackground() {
        for (BackgroundFactor& factor : background) {
            factor.wait();
        }
    }

    SparseCholesky& chordFactor() {
        return chordSlot < 0 ? cholesky : background[chordSlot].factor();
    }
    const std::vector<double>& chordJacobian() const {
        return chordSlot < 0 ? factorJacobian : background[chordSlot].jacobian();
    }

    // Takes a finished background factorisation for the chord steps if it is of a later iterate
    // than the factorisation they use (and of the same fixed variables); true if it took one.
    bool adoptBackground(const Problem& problem) {
        bool adopted = false;
        for (int slot = 0; slot < 2; ++slot) {
            BackgroundFactor& factor = background[slot];
            if (slot == chordSlot || !factor.ready() || !factor.succeeded() ||
                factor.stamp() <= factorIterate ||
                factor.fixedRevision() != problem.fixedRevision()) {
                continue;
            }
            chordSlot = slot;
            factorIterate = factor.stamp();
            factorFixedRevision = factor.fixedRevision();
            factorReusable = true;
            reusesInARow = 0;
            adopted = true;
        }
        return adopted;
    }

    // Starts a background factorisation at the current iterate (the equations evaluated there)
    // with the given weights, unless one is running.
    void startBackground(const Problem& problem, double eps1, double eps2, double proximity) {
        if (!analysis || background[0].running() || background[1].running()) {
            return;
        }
        const int slot = chordSlot == 0 ? 1 : 0;
        equations.termWeights2(problem, eps1, eps2, proximity, backgroundWeights);
        background[slot].start(equations, analysis, equations.jacobianValues(), backgroundWeights,
                               problem.fixedVariables(), problem.fixedRevision(), eps2, iterate);
    }

    // Whether a factorisation of a later iterate than the chord steps' is being made beside.
    bool factorizingBeside() const {
        for (const BackgroundFactor& factor : background) {
            if (factor.running() && factor.stamp() > factorIterate) {
                return true;
            }
        }
        return false;
    }

    bool mayReuseFactorization(const Problem& problem, const Options& options) const {
        int limit = options.reuseFactorization;
        if (options.backgroundFactorization && factorizingBeside()) {
            limit += options.reuseWhileFactorizingBeside;
        }
        return options.reuseFactorization > 0 && !experimental.baseline && factorReusable &&
               reusesInARow < limit && factorFixedRevision == problem.fixedRevision() &&
               cholesky.flops() >= options.reuseFactorizationMinimumFlops;
    }

    // A step with the last factorisation: the right-hand side of this iterate's residuals and
    // the factorised Jacobian.
    // Beside background factorisations its solve takes no BLAS lock (SparseCholesky::solve).
    bool reusedStep(const Problem& problem, double eps1, bool beside, IterationStats& stats,
                    Summary& summary) {
        const auto start = Clock::now();
        equations.fillRightHandSide(problem, eps1, stats.proximity, stats.eps2, chordJacobian(),
                                    rhs.data());
        stats.assemblyMs += millisecondsSince(start);
        if (!solveForStep(chordFactor(), beside, stats, summary)) {
            return false;
        }
        stats.factorizationReused = true;
        stats.backgroundFactor = chordSlot >= 0;
        ++reusesInARow;
        return true;
    }

    // step from rhs with `factor`.
    bool solveForStep(SparseCholesky& factor, bool withoutBlas, IterationStats& stats,
                      Summary& summary) {
        const auto start = Clock::now();
        const bool solved = factor.solve(rhs.data(), step.data(), withoutBlas);
        stats.solveMs = millisecondsSince(start);
        if (!solved) {
            summary.status = Status::FactorizationFailed;
            summary.detail = factor.error();
        }
        return solved;
    }

    // Lays the normal matrix out for the chosen factorisation and analyses it.
    bool analyse(const std::vector<int>& permutation, bool supernodal, Summary& summary);

    // Times one numeric factorisation at x with the given method (the faster of two when one
    // takes under 20 ms); infinity if it fails.
    double timeFactorization(const Problem& problem, const Options& options,
                             const std::vector<int>& permutation, bool supernodal,
                             Summary& summary);

    // Ordering, choice of method and symbolic analysis for the cached mode. The equations
    // must be built and evaluated at the first iterate (Measured times factorisations of it).
    // Takes the analysis of this structure from the process-wide cache (no ordering, no
    // symbolic analysis, no timing); false if there is none. The equations must be in their
    // original layout.
    bool adoptCachedAnalysis(const Options& options);

    // Puts the analysis just made into the cache (the pattern in its original order). If
    // another solver cached this structure meanwhile, its decision is taken instead; false if
    // that fails.
    bool storeAnalysis(const Options& options, std::vector<int> colStart, std::vector<int> rowIndex,
                       const std::vector<int>& permutation, bool supernodal);

    bool analyseCached(const Problem& problem, const Options& options, Summary& summary);

    // One linear solve in baseline mode: triplets, Eigen products, full analysis.
    bool baselineStep(const Problem& problem, double eps1, const Options& options,
                      IterationStats& stats, Summary& summary);

    // Fills and factorises N at the evaluated iterate with stats' weights (rhs filled too).
    bool factorize(const Problem& problem, double eps1, IterationStats& stats, Summary& summary) {
        auto start = Clock::now();
        equations.fill(problem, eps1, stats.eps2, cholesky.values(), rhs.data(), stats.proximity);
        stats.assemblyMs += millisecondsSince(start);
        start = Clock::now();
        factorReusable = false;
        if (!cholesky.factorize()) {
            summary.status = Status::FactorizationFailed;
            summary.detail = cholesky.error();
            return false;
        }
        stats.factorizationMs = millisecondsSince(start);
        return true;
    }

    // The factorisation just made becomes the one the chord steps reuse.
    void keepForReuse(const Problem& problem) {
        factorJacobian = equations.jacobianValues();
        factorFixedRevision = problem.fixedRevision();
        factorReusable = true;
        reusesInARow = 0;
        chordSlot = -1;
        factorIterate = iterate;
    }

    bool cachedStep(const Problem& problem, double eps1, IterationStats& stats, Summary& summary,
                    bool reuseLater) {
        if (!factorize(problem, eps1, stats, summary)) {
            return false;
        }
        if (reuseLater) {
            keepForReuse(problem);
        }
        return solveForStep(cholesky, false, stats, summary);
    }
};

} // namespace devsurf::solver
