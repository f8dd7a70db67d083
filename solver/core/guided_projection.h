#pragma once

#include "solver/core/experimental_options.h"
#include "solver/core/options.h"
#include "solver/core/summary.h"

#include <memory>
#include <vector>

namespace devsurf::solver {

class Problem;
class NormalEquations;

// The guided-projection iteration (6) of Tang et al.:
//   x_{k+1} = argmin ‖W(Hx − r)‖² + ε₁²‖Kx − s‖² + ε₂²‖x − x_k‖²,
// solved through its normal equations with CHOLMOD. The Jacobian pattern, the
// normal-matrix pattern with its fill map and the symbolic factorisation are cached across
// iterations and solve() calls while the problem structure stays the same; each iteration
// refills values in place and refactorises numerically.
//
// Not thread-safe; one instance per solving thread.
class GuidedProjection {
public:
    GuidedProjection();
    GuidedProjection(const GuidedProjection&) = delete;
    GuidedProjection& operator=(const GuidedProjection&) = delete;
    ~GuidedProjection();

    // Runs up to options.maxIterations iterations from x (problem.variableCount() values) and
    // writes back the last good iterate: a non-finite value, a failed factorisation or a
    // cancellation never puts a bad or half-done state into x.
    Summary solve(const Problem& problem, double* x, const Options& options);
    Summary solve(const Problem& problem, std::vector<double>& x, const Options& options);

    // Drops the cached structure and symbolic factorisation.
    void invalidate();

    // Waits for a factorisation running on another thread (Options::backgroundFactorization);
    // the next solve() that may reuse takes it if it is of a later iterate.
    void waitForBackgroundFactorization();

    // Variants for the benchmark and the tests (none by default); they apply to later solves.
    void setExperimentalOptions(const ExperimentalOptions& experimental);
    const ExperimentalOptions& experimentalOptions() const;

    // The cached linearised system (for tests and diagnostics); null before the first solve.
    const NormalEquations* normalEquations() const;

private:
    struct Impl;
    std::unique_ptr<Impl> m_impl;
};

// The largest fraction of `step` from x that no constraint family's guard refuses (see
// Options::guardShrinkLimit): the minimum of Term::admissibleStep over the terms of
// constraint families with non-zero weight.
double admissibleStep(const Problem& problem, const double* x, const double* step, double keep);

} // namespace devsurf::solver
