#include "solver/core/sparse_cholesky.h"

#include "solver/core/analysis_cache.h"
#include "solver/core/blas_info.h"
#include "solver/core/serial_openmp.h"

#include <suitesparse/cholmod.h>

#include <algorithm>
#include <mutex>

namespace devsurf::solver {

namespace {

// CHOLMOD's default switch between simplicial and supernodal (flops per non-zero of L).
constexpr double kCholmodSupernodalSwitch = 40.0;

} // namespace

// A symbolic factorisation owned by the analysis cache, with its own CHOLMOD workspace (it
// is only read, by cholmod_copy_factor, once made).
class SymbolicFactor {
public:
    SymbolicFactor() { cholmod_start(&common); }
    SymbolicFactor(const SymbolicFactor&) = delete;
    SymbolicFactor& operator=(const SymbolicFactor&) = delete;
    ~SymbolicFactor() {
        cholmod_free_factor(&factor, &common);
        cholmod_finish(&common);
    }
    cholmod_common common{};
    cholmod_factor* factor = nullptr;
    double flops = 0.0;
    double lnz = 0.0;
};

namespace {

// L Lᵀ x = b in place for a supernodal factor in its own order, without the BLAS, so that a
// solve does not wait for the BLAS lock while a factorisation runs on another thread
// (SparseCholesky::solve's withoutBlas). As fast as cholmod_solve2's dtrsv and dgemv per
// supernode here (docs/tuning.md). Each supernode's rows below its diagonal block are gathered
// into `scratch` (the largest supernode's height), so the inner loops run over contiguous
// columns of L.
void solveSupernodal(const cholmod_factor& factor, double* x, std::vector<double>& scratch) {
    const auto* super = static_cast<const int*>(factor.super);
    const auto* pi = static_cast<const int*>(factor.pi);
    const auto* px = static_cast<const int*>(factor.px);
    const auto* rows = static_cast<const int*>(factor.s);
    const auto* values = static_cast<const double*>(factor.x);
    const auto nsuper = static_cast<int>(factor.nsuper);
    if (scratch.size() < factor.maxesize) {
        scratch.resize(factor.maxesize);
    }
    double* below = scratch.data();
    // Supernode k: its columns first … first + columns − 1 (x's entries xs), stored as a
    // height × columns block (column j at l(j)), the rows below its diagonal block r[0 … rest).
    struct Supernode {
        int first, columns, height, rest;
        const int* r;
        const double* block;
        const double* l(int j) const { return block + static_cast<std::ptrdiff_t>(j) * height; }
    };
    auto supernode = [&](int k) {
        const int columns = super[k + 1] - super[k];
        const int height = pi[k + 1] - pi[k];
        return Supernode{super[k],      columns, height, height - columns, rows + pi[k] + columns,
                         values + px[k]};
    };
    for (int k = 0; k < nsuper; ++k) {
        const Supernode s = supernode(k);
        double* xs = x + s.first;
        std::fill_n(below, s.rest, 0.0);
        for (int j = 0; j < s.columns; ++j) {
            const double* l = s.l(j);
            const double xj = xs[j] / l[j];
            xs[j] = xj;
            for (int i = j + 1; i < s.columns; ++i) {
                xs[i] -= l[i] * xj;
            }
            const double* lb = l + s.columns;
            for (int i = 0; i < s.rest; ++i) {
                below[i] += lb[i] * xj;
            }
        }
        for (int i = 0; i < s.rest; ++i) {
            x[s.r[i]] -= below[i];
        }
    }
    for (int k = nsuper - 1; k >= 0; --k) {
        const Supernode s = supernode(k);
        double* xs = x + s.first;
        for (int i = 0; i < s.rest; ++i) {
            below[i] = x[s.r[i]];
        }
        for (int j = s.columns - 1; j >= 0; --j) {
            const double* l = s.l(j);
            double sum = xs[j];
            for (int i = j + 1; i < s.columns; ++i) {
                sum -= l[i] * xs[i];
            }
            const double* lb = l + s.columns;
            for (int i = 0; i < s.rest; ++i) {
                sum -= lb[i] * below[i];
            }
            xs[j] = sum / l[j];
        }
    }
}

} // namespace

struct SparseCholesky::Impl {
    cholmod_common common{};
    cholmod_sparse* matrix = nullptr;
    cholmod_factor* factor = nullptr;
    cholmod_dense* rhs = nullptr;
    cholmod_dense* solution = nullptr;
    cholmod_dense* workY = nullptr;
    cholmod_dense* workE = nullptr;
    std::vector<int> permutation;     // empty: CHOLMOD permutes itself (or identity)
    std::vector<double> solveScratch; // solveSupernodal's
    double flops = 0.0;
    double lnz = 0.0;
    bool inPlace = false;
    std::string error;

    Impl() {
        cholmod_start(&common);
        common.print = 0;
    }
    ~Impl() {
        release();
        cholmod_finish(&common);
    }
    void release() {
        cholmod_free_factor(&factor, &common);
        cholmod_free_sparse(&matrix, &common);
        cholmod_free_dense(&rhs, &common);
        cholmod_free_dense(&solution, &common);
        cholmod_free_dense(&workY, &common);
        cholmod_free_dense(&workE, &common);
        permutation.clear();
        inPlace = false;
    }
    bool fail(const char* what) {
        error = std::string(what) + " (CHOLMOD status " + std::to_string(common.status) + ")";
        return false;
    }
    cholmod_sparse* makeMatrix(int n, const std::vector<int>& colStart,
                               const std::vector<int>& rowIndex, int stype, int xtype) {
        cholmod_sparse* a = cholmod_allocate_sparse(static_cast<size_t>(n), static_cast<size_t>(n),
                                                    rowIndex.size(), 1, 1, stype, xtype, &common);
        if (!a) {
            return nullptr;
        }
        std::copy(colStart.begin(), colStart.end(), static_cast<int*>(a->p));
        std::copy(rowIndex.begin(), rowIndex.end(), static_cast<int*>(a->i));
        if (xtype == CHOLMOD_REAL) {
            std::fill_n(static_cast<double*>(a->x), rowIndex.size(), 0.0);
        }
        return a;
    }
    void setMethod(FactorizationMethod method) {
        switch (method) {
        case FactorizationMethod::Supernodal:
            common.supernodal = CHOLMOD_SUPERNODAL;
            break;
        case FactorizationMethod::Simplicial:
            common.supernodal = CHOLMOD_SIMPLICIAL;
            break;
        case FactorizationMethod::Automatic:
        case FactorizationMethod::Measured:
            common.supernodal = CHOLMOD_AUTO;
            common.supernodal_switch = kCholmodSupernodalSwitch;
            break;
        case FactorizationMethod::Calibrated:
            common.supernodal = CHOLMOD_AUTO;
            common.supernodal_switch = kCalibratedSupernodalSwitch;
            break;
        }
    }
    void defaultOrdering() {
        common.nmethods = 0;
        common.postorder = 1;
    }
    // Supernode amalgamation of our cached analysis: columns are merged into a supernode
    // (admitting some explicit zeros) up to 8 / 32 / 64 columns instead of CHOLMOD's 4 / 16 /
    // 48, so the many small supernodes of our problems make fewer, larger BLAS calls.
    // Measured per iteration (factorisation ms, default → ours): fig8-sheet 0.15 → 0.13,
    // fig12-annulus 0.87 → 0.75, large-annulus 40.6 → 33.2 (larger limits were slower).
    void ourAmalgamation() {
        common.nrelax[0] = 8;
        common.nrelax[1] = 32;
        common.nrelax[2] = 64;
    }
    void defaultAmalgamation() {
        common.nrelax[0] = 4;
        common.nrelax[1] = 16;
        common.nrelax[2] = 48;
    }
    bool allocateDense(int n) {
        rhs = cholmod_zeros(static_cast<size_t>(n), 1, CHOLMOD_REAL, &common);
        return rhs != nullptr;
    }
};

SparseCholesky::SparseCholesky() : m_impl(std::make_unique<Impl>()) {}
SparseCholesky::~SparseCholesky() = default;

bool SparseCholesky::computeOrdering(int n, const std::vector<int>& colStart,
                                     const std::vector<int>& rowIndex, FactorizationMethod method,
                                     std::vector<int>& permutation, bool& supernodal) {
    Impl& d = *m_impl;
    d.release();
    d.defaultOrdering();
    // Once per structure, AMD and METIS are both tried and the one with less fill is kept
    // (CHOLMOD's methods 1 and 2; method 0 is a given ordering, which we never pass). Without
    // its sheet AMD mostly wins or ties, but where a surface holds its sheet the development's
    // rows tie the net together and METIS leaves two to six times fewer flops. That costs
    // METIS's time once per structure, spent before the press when a drag is prepared
    // (docs/tuning.md, "AMD and METIS for every structure").
    d.common.nmethods = 3;
    d.setMethod(method == FactorizationMethod::Measured ? FactorizationMethod::Automatic : method);
    cholmod_sparse* pattern = d.makeMatrix(n, colStart, rowIndex, 1, CHOLMOD_PATTERN);
    if (!pattern) {
        return d.fail("allocating the pattern failed");
    }
    countSymbolicAnalysis();
    cholmod_factor* symbolic = cholmod_analyze(pattern, &d.common);
    d.defaultOrdering();
    cholmod_free_sparse(&pattern, &d.common);
    if (!symbolic) {
        return d.fail("symbolic analysis failed");
    }
    const int* perm = static_cast<const int*>(symbolic->Perm);
    permutation.assign(perm, perm + n);
    supernodal = symbolic->is_super != 0;
    cholmod_free_factor(&symbolic, &d.common);
    return true;
}

bool SparseCholesky::analyzePermuted(int n, const std::vector<int>& colStart,
                                     const std::vector<int>& rowIndex, bool lowerTriangle,
                                     bool supernodal, const std::vector<int>& permutation) {
    Impl& d = *m_impl;
    d.release();
    d.matrix = d.makeMatrix(n, colStart, rowIndex, lowerTriangle ? -1 : 1, CHOLMOD_REAL);
    if (!d.matrix) {
        return d.fail("allocating the matrix failed");
    }
    d.common.nmethods = 1;
    d.common.method[0].ordering = CHOLMOD_NATURAL;
    d.common.postorder = 0;
    d.common.supernodal = supernodal ? CHOLMOD_SUPERNODAL : CHOLMOD_SIMPLICIAL;
    d.ourAmalgamation();
    countSymbolicAnalysis();
    d.factor = cholmod_analyze(d.matrix, &d.common);
    d.defaultOrdering();
    d.defaultAmalgamation();
    if (!d.factor) {
        return d.fail("symbolic analysis failed");
    }
    d.flops = d.common.fl;
    d.lnz = d.common.lnz;
    d.permutation = permutation;
    d.inPlace = d.factor->ordering == CHOLMOD_NATURAL &&
                (d.factor->is_super ? lowerTriangle : !lowerTriangle);
    if (!d.allocateDense(n)) {
        return d.fail("allocating the right-hand side failed");
    }
    return true;
}

bool SparseCholesky::analyzeGeneral(int n, const std::vector<int>& colStart,
                                    const std::vector<int>& rowIndex, FactorizationMethod method) {
    Impl& d = *m_impl;
    d.release();
    d.defaultOrdering();
    d.setMethod(method);
    d.matrix = d.makeMatrix(n, colStart, rowIndex, 1, CHOLMOD_REAL);
    if (!d.matrix) {
        return d.fail("allocating the matrix failed");
    }
    countSymbolicAnalysis();
    d.factor = cholmod_analyze(d.matrix, &d.common);
    if (!d.factor) {
        return d.fail("symbolic analysis failed");
    }
    d.flops = d.common.fl;
    d.lnz = d.common.lnz;
    if (!d.allocateDense(n)) {
        return d.fail("allocating the right-hand side failed");
    }
    return true;
}

std::shared_ptr<const SymbolicFactor> SparseCholesky::exportSymbolic() const {
    const Impl& d = *m_impl;
    if (!d.factor) {
        return nullptr;
    }
    auto symbolic = std::make_shared<SymbolicFactor>();
    symbolic->factor = cholmod_copy_factor(d.factor, &symbolic->common);
    if (!symbolic->factor) {
        return nullptr;
    }
    cholmod_factor* f = symbolic->factor;
    if (f->xtype != CHOLMOD_PATTERN &&
        !cholmod_change_factor(CHOLMOD_PATTERN, f->is_ll, f->is_super, true, true, f,
                               &symbolic->common)) {
        return nullptr;
    }
    symbolic->flops = d.flops;
    symbolic->lnz = d.lnz;
    return symbolic;
}

bool SparseCholesky::adoptAnalysis(const CachedAnalysis& analysis, const std::vector<int>& colStart,
                                   const std::vector<int>& rowIndex) {
    Impl& d = *m_impl;
    d.release();
    if (!analysis.symbolic || !analysis.symbolic->factor) {
        d.error = "the cached analysis has no symbolic factorisation";
        return false;
    }
    const int n = analysis.variables;
    d.matrix = d.makeMatrix(n, colStart, rowIndex, analysis.lowerTriangle ? -1 : 1, CHOLMOD_REAL);
    if (!d.matrix) {
        return d.fail("allocating the matrix failed");
    }
    d.factor = cholmod_copy_factor(analysis.symbolic->factor, &d.common);
    if (!d.factor) {
        return d.fail("copying the cached symbolic factorisation failed");
    }
    d.flops = analysis.symbolic->flops;
    d.lnz = analysis.symbolic->lnz;
    d.permutation = analysis.permutation;
    d.inPlace = d.factor->ordering == CHOLMOD_NATURAL &&
                (d.factor->is_super ? analysis.lowerTriangle : !analysis.lowerTriangle);
    if (!d.allocateDense(n)) {
        return d.fail("allocating the right-hand side failed");
    }
    return true;
}

double* SparseCholesky::values() {
    return m_impl->matrix ? static_cast<double*>(m_impl->matrix->x) : nullptr;
}

bool SparseCholesky::factorize() {
    Impl& d = *m_impl;
    if (!d.matrix || !d.factor) {
        d.error = "factorize() before analysis";
        return false;
    }
    int ok = 0;
    {
        std::unique_lock<std::mutex> lock(blasMutex(), std::defer_lock);
        if (d.factor->is_super) {
            lock.lock();
        }
        const SerialOpenMpRegions serial;
        ok = cholmod_factorize(d.matrix, d.factor, &d.common);
    }
    if (!ok || d.common.status != CHOLMOD_OK) {
        if (d.common.status == CHOLMOD_NOT_POSDEF) {
            d.error =
                "matrix not positive definite (pivot " + std::to_string(d.factor->minor) + ")";
            return false;
        }
        return d.fail("numeric factorisation failed");
    }
    return true;
}

bool SparseCholesky::solve(const double* b, double* x, bool withoutBlas) {
    Impl& d = *m_impl;
    if (!d.factor || !d.rhs) {
        d.error = "solve() before analysis";
        return false;
    }
    const auto n = static_cast<int>(d.rhs->nrow);
    auto* bx = static_cast<double*>(d.rhs->x);
    const bool permuted = !d.permutation.empty();
    for (int k = 0; k < n; ++k) {
        bx[k] = b[permuted ? d.permutation[static_cast<std::size_t>(k)] : k];
    }
    const double* sx = bx;
    if (withoutBlas && d.factor->is_super && d.factor->ordering == CHOLMOD_NATURAL) {
        solveSupernodal(*d.factor, bx, d.solveScratch);
    } else {
        bool solved = false;
        {
            std::unique_lock<std::mutex> lock(blasMutex(), std::defer_lock);
            if (d.factor->is_super) {
                lock.lock();
            }
            const SerialOpenMpRegions serial;
            solved = cholmod_solve2(CHOLMOD_A, d.factor, d.rhs, nullptr, &d.solution, nullptr,
                                    &d.workY, &d.workE, &d.common) != 0;
        }
        if (!solved) {
            return d.fail("solve failed");
        }
        sx = static_cast<const double*>(d.solution->x);
    }
    for (int k = 0; k < n; ++k) {
        x[permuted ? d.permutation[static_cast<std::size_t>(k)] : k] = sx[k];
    }
    return true;
}

bool SparseCholesky::isSupernodal() const {
    return m_impl->factor && m_impl->factor->is_super != 0;
}
bool SparseCholesky::factorizesInPlace() const {
    return m_impl->inPlace;
}
double SparseCholesky::flops() const {
    return m_impl->flops;
}
double SparseCholesky::factorNonZeros() const {
    return m_impl->lnz;
}
const std::string& SparseCholesky::error() const {
    return m_impl->error;
}

} // namespace devsurf::solver
