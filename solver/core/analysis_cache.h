#pragma once

#include "solver/core/options.h"

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

namespace devsurf::solver {

// A symbolic factorisation held by the cache (defined next to the CHOLMOD wrapper, so that
// cholmod.h stays out of this header).
class SymbolicFactor;

// Everything the cached mode of GuidedProjection decides once per structure: the fill-reducing
// ordering, the choice between supernodal and simplicial factorisation (timed for
// FactorizationMethod::Measured) and the symbolic factorisation of the permuted pattern.
struct CachedAnalysis {
    // The key: the normal matrix's upper-triangle pattern in the original variable order
    // (CSC) and the requested method. Hits are confirmed on the whole pattern, not the hash.
    int variables = 0;
    FactorizationMethod method = FactorizationMethod::Calibrated;
    std::uint64_t hash = 0;
    std::vector<int> colStart;
    std::vector<int> rowIndex;
    // The analysis.
    std::vector<int> permutation;
    bool supernodal = false;
    bool lowerTriangle = false; // the layout the symbolic factor was made for
    std::shared_ptr<const SymbolicFactor> symbolic;
};

// Hash of a pattern and its sizes (FNV-1a over the sizes, the method and both index arrays).
std::uint64_t patternHash(int variables, const std::vector<int>& colStart,
                          const std::vector<int>& rowIndex, FactorizationMethod method);

// The process-wide cache of analyses, keyed by structure: a second solver on the same
// sparsity pattern (a new drag, a second Solve, another thread) neither orders, analyses nor
// re-times the factorisations, and so makes the same supernodal/simplicial choice as the
// first: results are bit-identical for identical input within a process. Thread-safe;
// bounded (the least recently used entry is dropped beyond capacity()).
class AnalysisCache {
public:
    static AnalysisCache& instance();

    // The analysis of this pattern and method, or null.
    std::shared_ptr<const CachedAnalysis> find(int variables, const std::vector<int>& colStart,
                                               const std::vector<int>& rowIndex,
                                               FactorizationMethod method);
    // Adds an analysis and returns the one that stands for its structure: an analysis of the
    // same structure already in the cache (made at the same time by another thread) wins, so
    // that a structure gets one decision per process.
    std::shared_ptr<const CachedAnalysis> insert(std::shared_ptr<const CachedAnalysis> analysis);

    void clear();
    std::size_t size() const;
    std::size_t capacity() const;
    void setCapacity(std::size_t capacity);
    // Off: every solver analyses its structure itself (for benchmarks of the cold analysis).
    // Also off for the whole process when the environment has DEVSURF_ANALYSIS_CACHE=0.
    bool isEnabled() const;
    void setEnabled(bool enabled);
    // Lookups answered from the cache since the start of the process (for tests).
    long long hits() const;

private:
    AnalysisCache();
    struct Impl;
    std::unique_ptr<Impl> m_impl;
};

// Symbolic analyses (CHOLMOD's cholmod_analyze) run in this process, by any solver: tests use
// it to check that a structure is analysed once.
long long symbolicAnalysisCount();
void countSymbolicAnalysis();

} // namespace devsurf::solver
