// GuidedProjection's cached analysis: the ordering, the choice of factorisation and the
// symbolic analysis once per structure (the process-wide AnalysisCache), and the baseline's
// analysis in every iteration.
#include "solver/core/guided_projection_impl.h"

#include "solver/core/problem.h"

#include <Eigen/SparseCore>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

namespace devsurf::solver {

// Lays the normal matrix out for the chosen factorisation and analyses it.
bool GuidedProjection::Impl::analyse(const std::vector<int>& permutation, bool supernodal,
                                     Summary& summary) {
    // Supernodal factorises the lower triangle in place, simplicial the upper one.
    const auto triangle =
        supernodal ? NormalEquations::Triangle::Lower : NormalEquations::Triangle::Upper;
    equations.setLayout(permutation, triangle);
    if (!cholesky.analyzePermuted(
            equations.variableCount(), equations.columnStart(), equations.rowIndex(),
            triangle == NormalEquations::Triangle::Lower, supernodal, permutation)) {
        summary.status = Status::FactorizationFailed;
        summary.detail = cholesky.error();
        return false;
    }
    return true;
}

// Times one numeric factorisation at x with the given method (the faster of two when one
// takes under 20 ms); infinity if it fails.
double GuidedProjection::Impl::timeFactorization(const Problem& problem, const Options& options,
                                                 const std::vector<int>& permutation,
                                                 bool supernodal, Summary& summary) {
    if (!analyse(permutation, supernodal, summary)) {
        return std::numeric_limits<double>::infinity();
    }
    equations.fill(problem, epsilon1(options, options.scheduleOffset), options.eps2,
                   cholesky.values(), rhs.data(),
                   proximityWeight(options, equations.maxConstraintResidual()));
    std::vector<double> values(cholesky.values(), cholesky.values() + equations.normalNonZeros());
    double best = std::numeric_limits<double>::infinity();
    for (int repeat = 0; repeat < 2; ++repeat) {
        std::copy(values.begin(), values.end(), cholesky.values());
        const auto start = Clock::now();
        if (!cholesky.factorize()) {
            return std::numeric_limits<double>::infinity();
        }
        best = std::min(best, millisecondsSince(start));
        if (best > 20.0) {
            break;
        }
    }
    return best;
}

// Ordering, choice of method and symbolic analysis for the cached mode. The equations
// must be built and evaluated at the first iterate (Measured times factorisations of it).
// Takes the analysis of this structure from the process-wide cache (no ordering, no
// symbolic analysis, no timing); false if there is none. The equations must be in their
// original layout.
bool GuidedProjection::Impl::adoptCachedAnalysis(const Options& options) {
    const auto cached =
        AnalysisCache::instance().find(equations.variableCount(), equations.columnStart(),
                                       equations.rowIndex(), options.factorization);
    if (!cached) {
        return false;
    }
    equations.setLayout(cached->permutation, cached->lowerTriangle
                                                 ? NormalEquations::Triangle::Lower
                                                 : NormalEquations::Triangle::Upper);
    if (!cholesky.adoptAnalysis(*cached, equations.columnStart(), equations.rowIndex())) {
        equations.setLayout({}, NormalEquations::Triangle::Upper);
        return false;
    }
    analysis = cached;
    return true;
}

// Puts the analysis just made into the cache (the pattern in its original order). If
// another solver cached this structure meanwhile, its decision is taken instead; false if
// that fails.
bool GuidedProjection::Impl::storeAnalysis(const Options& options, std::vector<int> colStart,
                                           std::vector<int> rowIndex,
                                           const std::vector<int>& permutation, bool supernodal) {
    auto entry = std::make_shared<CachedAnalysis>();
    entry->symbolic = cholesky.exportSymbolic();
    if (!entry->symbolic) {
        return true;
    }
    entry->variables = equations.variableCount();
    entry->method = options.factorization;
    entry->hash = patternHash(entry->variables, colStart, rowIndex, options.factorization);
    entry->colStart = std::move(colStart);
    entry->rowIndex = std::move(rowIndex);
    entry->permutation = permutation;
    entry->supernodal = supernodal;
    entry->lowerTriangle = equations.triangle() == NormalEquations::Triangle::Lower;
    const CachedAnalysis* mine = entry.get();
    const auto kept = AnalysisCache::instance().insert(std::move(entry));
    analysis = kept;
    if (!kept || kept.get() == mine) {
        return true;
    }
    equations.setLayout(kept->permutation, kept->lowerTriangle ? NormalEquations::Triangle::Lower
                                                               : NormalEquations::Triangle::Upper);
    return cholesky.adoptAnalysis(*kept, equations.columnStart(), equations.rowIndex());
}

bool GuidedProjection::Impl::analyseCached(const Problem& problem, const Options& options,
                                           Summary& summary) {
    // Decided once per structure: a structure seen before takes the same analysis and the
    // same supernodal/simplicial choice.
    if (adoptCachedAnalysis(options)) {
        analysed = true;
        method = options.factorization;
        return true;
    }
    std::vector<int> originalColStart = equations.columnStart();
    std::vector<int> originalRowIndex = equations.rowIndex();
    std::vector<int> permutation;
    bool supernodal = false;
    if (!cholesky.computeOrdering(equations.variableCount(), equations.columnStart(),
                                  equations.rowIndex(), options.factorization, permutation,
                                  supernodal)) {
        summary.status = Status::FactorizationFailed;
        summary.detail = cholesky.error();
        return false;
    }
    bool analysedAsChosen = false;
    if (options.factorization == FactorizationMethod::Measured) {
        Summary scratch;
        const double simplicialMs =
            timeFactorization(problem, options, permutation, false, scratch);
        const double supernodalMs = timeFactorization(problem, options, permutation, true, scratch);
        if (std::isfinite(simplicialMs) || std::isfinite(supernodalMs)) {
            supernodal = supernodalMs < simplicialMs;
            // The supernodal analysis was the last one; it stands if supernodal won.
            analysedAsChosen = supernodal && std::isfinite(supernodalMs);
        }
    }
    if (!analysedAsChosen && !analyse(permutation, supernodal, summary)) {
        return false;
    }
    analysed = true;
    method = options.factorization;
    if (!storeAnalysis(options, std::move(originalColStart), std::move(originalRowIndex),
                       permutation, supernodal)) {
        summary.status = Status::FactorizationFailed;
        summary.detail = cholesky.error();
        return false;
    }
    return true;
}

// One linear solve in baseline mode: triplets, Eigen products, full analysis.
bool GuidedProjection::Impl::baselineStep(const Problem& problem, double eps1,
                                          const Options& options, IterationStats& stats,
                                          Summary& summary) {
    auto start = Clock::now();
    Eigen::SparseMatrix<double> upper;
    Eigen::VectorXd g;
    equations.assembleFromScratch(problem, eps1, stats.eps2, upper, g, stats.proximity);
    const int n = equations.variableCount();
    std::vector<int> colStart(upper.outerIndexPtr(), upper.outerIndexPtr() + n + 1);
    std::vector<int> rowIndex(upper.innerIndexPtr(), upper.innerIndexPtr() + upper.nonZeros());
    stats.assemblyMs += millisecondsSince(start);
    start = Clock::now();
    if (!cholesky.analyzeGeneral(n, colStart, rowIndex, options.factorization)) {
        summary.status = Status::FactorizationFailed;
        summary.detail = cholesky.error();
        return false;
    }
    std::memcpy(cholesky.values(), upper.valuePtr(),
                sizeof(double) * static_cast<std::size_t>(upper.nonZeros()));
    if (!cholesky.factorize()) {
        summary.status = Status::FactorizationFailed;
        summary.detail = cholesky.error();
        return false;
    }
    stats.factorizationMs = millisecondsSince(start);
    start = Clock::now();
    std::copy(g.data(), g.data() + n, rhs.begin());
    const bool solved = cholesky.solve(rhs.data(), step.data());
    stats.solveMs = millisecondsSince(start);
    if (!solved) {
        summary.status = Status::FactorizationFailed;
        summary.detail = cholesky.error();
        return false;
    }
    return true;
}

} // namespace devsurf::solver
