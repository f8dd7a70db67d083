#include "solver/core/background_factor.h"

#include "solver/core/analysis_cache.h"

#include <chrono>
#include <exception>

namespace devsurf::solver {

BackgroundFactor::BackgroundFactor() : m_cholesky(std::make_unique<SparseCholesky>()) {}

BackgroundFactor::~BackgroundFactor() {
    wait();
}

bool BackgroundFactor::start(const NormalEquations& equations,
                             const std::shared_ptr<const CachedAnalysis>& analysis,
                             const std::vector<double>& jacobian,
                             const std::vector<double>& termWeight2, const std::vector<int>& fixed,
                             std::uint64_t fixedRevision, double eps2, long long stamp) {
    if (running() || !analysis) {
        return false;
    }
    if (m_analysis != analysis) {
        // A new structure: this factor takes its analysis (a copy of the symbolic factor).
        m_analysis.reset();
        if (!m_cholesky->adoptAnalysis(*analysis, equations.columnStart(), equations.rowIndex())) {
            return false;
        }
        m_analysis = analysis;
    }
    m_jacobian = jacobian;
    m_weights = termWeight2;
    m_fixed = fixed;
    m_fixedRevision = fixedRevision;
    m_eps2 = eps2;
    m_stamp = stamp;
    m_succeeded = false;
    m_done = false;
    const NormalEquations* structure = &equations;
    m_job = std::async(std::launch::async, [this, structure] {
        try {
            structure->fillMatrix(m_jacobian.data(), m_weights, m_fixed, m_eps2,
                                  m_cholesky->values(), m_scratch);
            return m_cholesky->factorize();
        } catch (const std::exception&) {
            return false; // out of memory: the steps go on with the factorisation they have
        }
    });
    return true;
}

bool BackgroundFactor::ready() {
    if (m_job.valid() && m_job.wait_for(std::chrono::seconds(0)) == std::future_status::ready) {
        wait();
    }
    return m_done;
}

void BackgroundFactor::wait() {
    if (m_job.valid()) {
        m_succeeded = m_job.get();
        m_done = true;
    }
}

} // namespace devsurf::solver
