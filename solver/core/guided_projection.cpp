#include "solver/core/guided_projection.h"
#include "solver/core/guided_projection_impl.h"

#include "solver/core/analysis_cache.h"
#include "solver/core/finite_values.h"
#include "solver/core/normal_equations.h"
#include "solver/core/problem.h"
#include "solver/core/sparse_cholesky.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>

namespace devsurf::solver {

double admissibleStep(const Problem& problem, const double* x, const double* step, double keep) {
    double fraction = 1.0;
    for (int t = 0; t < problem.termCount(); ++t) {
        const TermFamily& family = problem.family(problem.termFamily(t));
        if (family.role == TermRole::Constraint && family.weight > 0.0) {
            fraction = std::min(fraction, problem.term(t).admissibleStep(x, step, keep));
        }
    }
    return fraction;
}

namespace {

// Term::engageCrossedGuards over the terms of constraint families with non-zero weight.
int engageCrossedGuards(const Problem& problem, const double* x, const double* step) {
    int engaged = 0;
    for (int t = 0; t < problem.termCount(); ++t) {
        const TermFamily& family = problem.family(problem.termFamily(t));
        if (family.role == TermRole::Constraint && family.weight > 0.0) {
            engaged += problem.term(t).engageCrossedGuards(x, step);
        }
    }
    return engaged;
}

// Term::releaseGuards over all terms.
void releaseGuards(const Problem& problem) {
    for (int t = 0; t < problem.termCount(); ++t) {
        problem.term(t).releaseGuards();
    }
}

// After a factorisation fails at an adaptive ε₂, no smaller ε₂ than this multiple of it is
// tried again. A floor too high stalls the convergence where the Jacobian is nearly singular:
// devsurf-bench --study large-annulus --session from 10 % edge noise, seed 20150806, failed at
// 1.9e-6 in iteration 12, and with a floor of ten times that stayed at det 1.9e-10 for the
// remaining 8 iterations (the residual shrank by 1 % per iteration); with twice that: 3.1e-14,
// all 10 seeds within 1.9e-13. Factorisations repeated after a failure, factor ten → two: none
// in the examples' study either way, 1 → 2 in the drag benchmark, in the large annulus's 10
// seeds and in Solve of the valid annulus.
constexpr double kEps2FloorFactor = 2.0;

} // namespace

GuidedProjection::GuidedProjection() : m_impl(std::make_unique<Impl>()) {}
GuidedProjection::~GuidedProjection() = default;

void GuidedProjection::invalidate() {
    m_impl->reset();
}

void GuidedProjection::waitForBackgroundFactorization() {
    m_impl->waitForBackground();
}

void GuidedProjection::setExperimentalOptions(const ExperimentalOptions& experimental) {
    // The baseline keeps no symbolic factorisation and the boost of rejected steps belongs to
    // the variant that raised it: start afresh.
    m_impl->reset();
    m_impl->experimental = experimental;
}

const ExperimentalOptions& GuidedProjection::experimentalOptions() const {
    return m_impl->experimental;
}

const NormalEquations* GuidedProjection::normalEquations() const {
    return m_impl->equations.isBuilt() ? &m_impl->equations : nullptr;
}

Summary GuidedProjection::solve(const Problem& problem, std::vector<double>& x,
                                const Options& options) {
    if (x.size() != static_cast<std::size_t>(problem.variableCount())) {
        Summary summary;
        summary.status = Status::InvalidProblem;
        summary.detail = "state has " + std::to_string(x.size()) + " values for " +
                         std::to_string(problem.variableCount()) + " variables";
        return summary;
    }
    return solve(problem, x.data(), options);
}

Summary GuidedProjection::solve(const Problem& problem, double* x, const Options& options) {
    Impl& d = *m_impl;
    const ExperimentalOptions& experimental = d.experimental;
    const auto totalStart = Clock::now();
    Summary summary;
    const int n = problem.variableCount();
    summary.variables = n;
    if (n > 0 && !x) {
        summary.status = Status::InvalidProblem;
        summary.detail = "null state";
        return summary;
    }
    d.x.assign(x, x + n);
    d.xNew.resize(static_cast<std::size_t>(n));
    d.step.resize(static_cast<std::size_t>(n));
    d.rhs.resize(static_cast<std::size_t>(n));
    if (!allFinite(d.x)) {
        summary.status = Status::NonFiniteValue;
        summary.detail = "the initial state contains a non-finite value";
        summary.totalMs = millisecondsSince(totalStart);
        return summary;
    }

    // Structure: reuse while the problem structure (and the factorisation method) is unchanged.
    auto analysisStart = Clock::now();
    const bool reusable =
        d.equations.matches(problem) &&
        (experimental.baseline || (d.analysed && d.method == options.factorization));
    if (!reusable) {
        d.waitForBackground(); // it reads the structure about to change
        d.analysis.reset();
        d.chordSlot = -1;
        d.analysed = false;
        d.eps2Floor = 0.0;
        d.eps2Boost = 1.0;
        d.factorReusable = false;
        std::string error;
        if (!d.equations.build(problem, &error)) {
            d.reset();
            summary.status = Status::InvalidProblem;
            summary.detail = error;
            summary.totalMs = millisecondsSince(totalStart);
            return summary;
        }
        summary.analysisMs = millisecondsSince(analysisStart);
    }
    summary.structureReused = reusable;
    summary.rows = d.equations.rowCount();
    summary.jacobianNonZeros = d.equations.jacobianNonZeros();
    summary.normalMatrixNonZeros = d.equations.normalNonZeros();

    auto evaluationStart = Clock::now();
    // x is usually where the last solve() ended: only the terms changed since are evaluated
    // again (a drag's move: its handles, the lengths it keeps). Not in the baseline.
    if (!d.equations.evaluate(problem, d.x.data(), !experimental.baseline)) {
        summary.status = Status::NonFiniteValue;
        summary.detail = "a term produced a non-finite value at the initial state";
        summary.totalMs = millisecondsSince(totalStart);
        return summary;
    }
    double pendingEvaluationMs = millisecondsSince(evaluationStart);
    if (!reusable && !experimental.baseline) {
        analysisStart = Clock::now();
        if (!d.analyseCached(problem, options, summary)) {
            d.reset();
            summary.totalMs = millisecondsSince(totalStart);
            return summary;
        }
        summary.analysisMs += millisecondsSince(analysisStart);
    }
    summary.initialMaxConstraintResidual = d.equations.maxConstraintResidual();
    summary.initialEnergy = d.equations.energy();
    summary.finalMaxConstraintResidual = summary.initialMaxConstraintResidual;
    summary.finalEnergy = summary.initialEnergy;
    summary.status = Status::IterationLimit;
    if (options.recordIterations) {
        summary.iterations.reserve(static_cast<std::size_t>(std::max(0, options.maxIterations)));
    }

    if (options.maxIterations == 0 && options.factorizeAhead && options.reuseFactorization > 0 &&
        !experimental.baseline) {
        IterationStats stats;
        const double assumed = std::max(d.equations.maxConstraintResidual(), options.eps2);
        stats.eps1 = epsilon1(options, options.scheduleOffset); // its top, as ε₂'s
        stats.eps2 = d.flooredEps2(epsilon2(options, options.scheduleOffset, assumed), options);
        stats.proximity = proximityWeight(options, assumed);
        if (d.factorize(problem, stats.eps1, stats, summary)) {
            d.keepForReuse(problem);
        } else {
            summary.status = Status::IterationLimit; // the first step factorises again
            summary.detail.clear();
        }
        summary.analysisMs += stats.assemblyMs + stats.factorizationMs;
    }
    double& eps2Boost = d.eps2Boost;
    for (int iteration = 0; iteration < options.maxIterations; ++iteration) {
        if (options.cancel && options.cancel->load()) {
            summary.status = Status::Cancelled;
            summary.detail = "cancelled";
            break;
        }
        if (options.backgroundFactorization) {
            d.adoptBackground(problem);
        }
        IterationStats stats;
        stats.iteration = iteration;
        stats.eps1 =
            epsilon1(options, options.scheduleOffset + iteration, d.equations.maxDrivingResidual());
        stats.eps2 = epsilon2(options, options.scheduleOffset + iteration,
                              d.equations.maxConstraintResidual());
        stats.proximity = proximityWeight(options, d.equations.maxConstraintResidual());
        if (eps2Boost > 1.0) {
            stats.eps2 = experimental.levenbergMarquardt
                             ? eps2Boost * stats.eps2
                             : std::min(std::max(options.eps2, stats.eps2), eps2Boost * stats.eps2);
        }
        stats.eps2 = d.flooredEps2(stats.eps2, options);
        stats.assemblyMs = pendingEvaluationMs;
        auto step = [&] {
            return experimental.baseline
                       ? d.baselineStep(problem, stats.eps1, options, stats, summary)
                       : d.cachedStep(problem, stats.eps1, stats, summary,
                                      options.reuseFactorization > 0);
        };
        // A step with a fresh factorisation.
        auto factorisedStep = [&] {
            bool stepped = step();
            if (!stepped && summary.status == Status::FactorizationFailed &&
                stats.eps2 < options.eps2) {
                // A smaller adaptive ε₂ can leave the matrix numerically singular (a degenerate
                // strip, or directions no row constrains, as the in-plane motion of a flat
                // design's points); repeat with the configured damping, and try no less than
                // kEps2FloorFactor times this ε₂ from now on. Measured on the annulus example:
                // Tools ▸ Solve factorised twice in each of its 10 iterations at ε₂ = 1e-6.
                d.eps2Floor = std::min(
                    options.eps2, stats.eps2 > 0.0 ? kEps2FloorFactor * stats.eps2 : options.eps2);
                stats.repeated = true;
                summary.status = Status::IterationLimit;
                summary.detail.clear();
                stats.eps2 = options.eps2;
                stepped = step();
            }
            if (stepped) {
                stats.factorFlops = d.cholesky.flops();
                stats.factorNonZeros = d.cholesky.factorNonZeros();
            }
            return stepped;
        };
        // x_{k+1} from the step (shrunk by the guards, projected) and evaluated there; false if
        // the step or a value there is not finite (summary says which).
        double evaluationMs = 0.0;
        auto takeStep = [&] {
            if (!allFinite(d.step)) {
                summary.status = Status::NonFiniteValue;
                summary.detail = "the linear solve produced a non-finite step";
                return false;
            }
            if (options.guardShrinkLimit > 0.0) {
                stats.stepFraction =
                    admissibleStep(problem, d.x.data(), d.step.data(), options.guardShrinkLimit);
                if (stats.stepFraction < 1.0) {
                    for (double& v : d.step) {
                        v *= stats.stepFraction;
                    }
                }
            }
            double stepSquared = 0.0;
            for (int i = 0; i < n; ++i) {
                const auto k = static_cast<std::size_t>(i);
                d.xNew[k] = d.x[k] + d.step[k];
                stepSquared += d.step[k] * d.step[k];
            }
            stats.stepNorm = std::sqrt(stepSquared);
            if (options.project) {
                options.project(d.xNew.data());
            }
            const auto evaluating = Clock::now();
            const bool evaluated =
                allFinite(d.xNew) && d.equations.evaluate(problem, d.xNew.data());
            evaluationMs += millisecondsSince(evaluating);
            if (!evaluated) {
                summary.status = Status::NonFiniteValue;
                summary.detail = "a term produced a non-finite value at iterate " +
                                 std::to_string(iteration + 1);
                return false;
            }
            return true;
        };
        const bool reused =
            d.mayReuseFactorization(problem, options) &&
            d.reusedStep(problem, stats.eps1, options.backgroundFactorization, stats, summary);
        if (!reused) {
            summary.status = Status::IterationLimit; // a failed reuse factorises afresh
            summary.detail.clear();
            if (!factorisedStep()) {
                break;
            }
        }
        if (!reused && options.engageCrossedGuards && !experimental.baseline && allFinite(d.step) &&
            engageCrossedGuards(problem, d.x.data(), d.step.data()) > 0) {
            // The guards this step would cross, held at their bounds, and the step again:
            // otherwise a guard pulled through here is pushed back by the next step, which
            // pulls it through again (docs/tuning.md, "Guards held in a settling"). Only the
            // guards changed at this x, so only they are evaluated again.
            stats.guardsEngaged = true;
            d.equations.evaluate(problem, d.x.data(), true);
            summary.status = Status::IterationLimit;
            summary.detail.clear();
            const bool stepped = factorisedStep();
            releaseGuards(problem);
            d.equations.evaluate(problem, d.x.data(), true); // the merit below is without them
            if (!stepped) {
                break;
            }
        }
        const double meritBefore = d.equations.constraintMerit();
        bool finite = takeStep();
        if (reused && options.reusedStepMeritRise > 0.0 &&
            (!finite || d.equations.constraintMerit() >
                            options.reusedStepMeritRise *
                                std::max(meritBefore, options.reusedStepMeritFloor))) {
            // The earlier factorisation led the step astray (a chord step far from where it
            // was made): back to x_k, and the step again with a fresh factorisation.
            stats.reuseUndone = true;
            stats.factorizationReused = false;
            summary.status = Status::IterationLimit;
            summary.detail.clear();
            const auto evaluating = Clock::now();
            d.equations.evaluate(problem, d.x.data());
            evaluationMs += millisecondsSince(evaluating);
            if (!factorisedStep()) {
                break;
            }
            finite = takeStep();
        }
        evaluationStart = Clock::now();
        const bool worse = finite && d.equations.constraintMerit() > meritBefore;
        if ((worse && experimental.levenbergMarquardt) ||
            (worse && experimental.rejectWorseSteps && stats.eps1 == 0.0 &&
             stats.eps2 < options.eps2)) {
            // Keep x_k (evaluated again: the equations hold the rejected iterate) and damp more.
            stats.rejected = true;
            stats.stepNorm = 0.0;
            d.equations.evaluate(problem, d.x.data());
            std::copy(d.x.begin(), d.x.end(), d.xNew.begin());
            eps2Boost *= 10.0;
        } else if (finite) {
            eps2Boost = std::max(1.0, eps2Boost / 10.0);
        }
        stats.assemblyMs += evaluationMs + millisecondsSince(evaluationStart);
        pendingEvaluationMs = 0.0;
        if (!finite) {
            break;
        }
        d.x.swap(d.xNew);
        ++d.iterate;
        if (options.backgroundFactorization && d.factorReusable && !experimental.baseline &&
            d.cholesky.flops() >= options.reuseFactorizationMinimumFlops) {
            // The next factorisation, made beside the steps: at this iterate, with this
            // step's weights. Those of the iterate itself would be the next step's only if the
            // targets stayed; after a move ε₂ is far larger (the residual rose), and a
            // factorisation at the converged iterate's ε₂ threw the next moves off (0.045
            // instead of 4.5e-6 on the annulus of size 10, docs/tuning.md).
            d.startBackground(problem, stats.eps1, stats.eps2, stats.proximity);
        }
        stats.maxConstraintResidual = d.equations.maxConstraintResidual();
        stats.energy = d.equations.energy();
        summary.finalMaxConstraintResidual = stats.maxConstraintResidual;
        summary.finalEnergy = stats.energy;
        summary.iterationsCompleted = iteration + 1;
        if (options.recordIterations) {
            summary.iterations.push_back(stats);
        }
        if (options.progress) {
            options.progress(stats);
        }
        if (options.residualTolerance > 0.0 &&
            stats.maxConstraintResidual <= options.residualTolerance &&
            epsilon1(options, options.scheduleOffset + iteration + 1) == 0.0) {
            summary.status = Status::Converged;
            break;
        }
    }
    summary.tolerance = options.reportTolerance;
    summary.toleranceReached = summary.finalMaxConstraintResidual <= options.reportTolerance;
    summary.supernodal = d.cholesky.isSupernodal();
    summary.factorizedInPlace = !experimental.baseline && d.cholesky.factorizesInPlace();
    std::copy(d.x.begin(), d.x.end(), x);
    summary.totalMs = millisecondsSince(totalStart);
    return summary;
}

} // namespace devsurf::solver
