#pragma once

#include "solver/core/normal_equations.h"
#include "solver/core/sparse_cholesky.h"

#include <cstdint>
#include <future>
#include <memory>
#include <vector>

namespace devsurf::solver {

struct CachedAnalysis;

// A factorisation of the normal equations made on another thread while the iteration goes on
// with chord steps (Options::backgroundFactorization): N at one iterate's Jacobian, filled
// (NormalEquations::fillMatrix) and factorised into a SparseCholesky of its own that takes the
// structure's cached analysis. The owner keeps the equations' structure unchanged while a
// factorisation runs, and reads the result only once ready() (or after wait()).
class BackgroundFactor {
public:
    BackgroundFactor();
    BackgroundFactor(const BackgroundFactor&) = delete;
    BackgroundFactor& operator=(const BackgroundFactor&) = delete;
    ~BackgroundFactor(); // waits for a running factorisation

    // Starts a factorisation of N from `jacobian` (copied) with w² per term and the fixed
    // variables; `stamp` orders it among the owner's factorisations. False if one is running
    // or the analysis cannot be taken.
    bool start(const NormalEquations& equations,
               const std::shared_ptr<const CachedAnalysis>& analysis,
               const std::vector<double>& jacobian, const std::vector<double>& termWeight2,
               const std::vector<int>& fixed, std::uint64_t fixedRevision, double eps2,
               long long stamp);
    bool running() const { return m_job.valid(); }
    // True once the last started factorisation has finished (its result: succeeded()), until
    // the next start().
    bool ready();
    void wait();

    bool succeeded() const { return m_succeeded; }
    SparseCholesky& factor() { return *m_cholesky; }
    const std::vector<double>& jacobian() const { return m_jacobian; }
    std::uint64_t fixedRevision() const { return m_fixedRevision; }
    long long stamp() const { return m_stamp; }

private:
    std::unique_ptr<SparseCholesky> m_cholesky;
    std::shared_ptr<const CachedAnalysis> m_analysis; // the one m_cholesky took
    std::vector<double> m_jacobian;
    std::vector<double> m_weights;
    std::vector<int> m_fixed;
    NormalEquations::FillScratch m_scratch;
    std::uint64_t m_fixedRevision = 0;
    double m_eps2 = 0.0;
    long long m_stamp = -1;
    bool m_succeeded = false;
    bool m_done = false;
    std::future<bool> m_job;
};

} // namespace devsurf::solver
