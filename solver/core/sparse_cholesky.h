#pragma once

#include "solver/core/options.h"

#include <memory>
#include <string>
#include <vector>

namespace devsurf::solver {

class SymbolicFactor;
struct CachedAnalysis;

// CHOLMOD behind a small interface (pimpl: cholmod.h stays out of our headers).
//
// Cached use, once per structure: computeOrdering() on the pattern in the original order,
// then analyzePermuted() on the pattern laid out in that order (lower triangle for the
// supernodal, upper for the simplicial factorisation: the layouts CHOLMOD factorises without
// copying). Every iteration: write values(), factorize(), solve().
// Baseline use: analyzeGeneral() every time (CHOLMOD orders, permutes and transposes itself).
class SparseCholesky {
public:
    SparseCholesky();
    SparseCholesky(const SparseCholesky&) = delete;
    SparseCholesky& operator=(const SparseCholesky&) = delete;
    ~SparseCholesky();

    // Fill-reducing ordering (the better of AMD and METIS by fill, with postordering) of the upper
    // triangle pattern (CSC, sorted rows) of an n×n symmetric matrix; also decides between
    // supernodal and simplicial for Automatic and gives CHOLMOD's choice for Measured (which the
    // caller then times).
    bool computeOrdering(int n, const std::vector<int>& colStart, const std::vector<int>& rowIndex,
                         FactorizationMethod method, std::vector<int>& permutation,
                         bool& supernodal);
    // Symbolic analysis of the already permuted pattern with the natural ordering.
    bool analyzePermuted(int n, const std::vector<int>& colStart, const std::vector<int>& rowIndex,
                         bool lowerTriangle, bool supernodal, const std::vector<int>& permutation);
    // Symbolic analysis of the upper triangle in the original order (baseline mode).
    bool analyzeGeneral(int n, const std::vector<int>& colStart, const std::vector<int>& rowIndex,
                        FactorizationMethod method);
    // A copy of the current analysis as a symbolic factorisation (numeric values dropped), for
    // the AnalysisCache; null before an analysis or if copying fails.
    std::shared_ptr<const SymbolicFactor> exportSymbolic() const;
    // Takes a cached analysis instead of running analyzePermuted(): the pattern (CSC) must be
    // laid out as the analysis was made (its permutation and triangle). No symbolic analysis.
    bool adoptAnalysis(const CachedAnalysis& analysis, const std::vector<int>& colStart,
                       const std::vector<int>& rowIndex);

    // The value array of the analysed matrix (in the analysed layout), to be filled in place.
    double* values();
    bool factorize();
    // Solves N x = b; b and x in the original variable order. No allocation after the first
    // call for a given analysis. withoutBlas: a supernodal factor in its own order (the cached
    // mode's) is solved by our own loops, which take no BLAS lock, for a step beside a
    // factorisation on another thread (Options::backgroundFactorization); on nearly singular
    // systems its rounding differs from CHOLMOD's visibly.
    bool solve(const double* b, double* x, bool withoutBlas = false);

    bool isSupernodal() const;
    // True if the factorisation runs on our matrix in place (natural ordering in CHOLMOD).
    bool factorizesInPlace() const;
    double flops() const;          // cholmod_common.fl of the analysis
    double factorNonZeros() const; // cholmod_common.lnz
    const std::string& error() const;

private:
    struct Impl;
    std::unique_ptr<Impl> m_impl;
};

} // namespace devsurf::solver
