// The row groups of NormalEquations: which consecutive rows are assembled together through
// one dense block (formGroups, at build time) and that block's assembly (fillGroup, in every
// fill). See normal_equations.h.
#include "solver/core/normal_equations.h"

#include "solver/core/problem.h"

#include <algorithm>

namespace devsurf::solver {

// BLAS (the library CHOLMOD uses): C = α op(A) op(B) + β C.
extern "C" void dgemm_(const char* transa, const char* transb, const int* m, const int* n,
                       const int* k, const double* alpha, const double* a, const int* lda,
                       const double* b, const int* ldb, const double* beta, double* c,
                       const int* ldc);

void NormalEquations::formGroups(const Problem& problem) {
    // A group is grown row by row while each new row adds at most half as many block entries
    // as it has products of its own, up to kMaxWidth columns: the rows of (4) at the values of
    // one interval (all on the same control points) join, the next interval's (a shifted set)
    // starts a new group, and rows that share nothing (fairness, unit norms) stay alone.
    constexpr std::size_t kMaxWidth = 64;
    m_groups.clear();
    m_groupColumns.clear();
    m_entryLocal.assign(m_jacColumn.size(), -1);
    std::vector<int> localOf(static_cast<std::size_t>(m_variables), -1);
    std::vector<int> groupColumns;
    std::vector<int> newColumns; // columns a candidate row would add
    auto blockEntries = [](std::size_t w) { return w * (w + 1) / 2; };
    // Tries to add row r to the current group; true if it joined.
    auto tryJoin = [&](int r, bool first) {
        newColumns.clear();
        const int begin = m_jacRowStart[r];
        const int end = m_jacRowStart[r + 1];
        for (int i = begin; i < end; ++i) {
            const int column = m_jacColumn[static_cast<std::size_t>(i)];
            if (localOf[static_cast<std::size_t>(column)] < 0 &&
                std::find(newColumns.begin(), newColumns.end(), column) == newColumns.end()) {
                newColumns.push_back(column);
            }
        }
        const auto m = static_cast<std::size_t>(end - begin);
        const std::size_t width = groupColumns.size() + newColumns.size();
        // A first row starts a group unless it is wider than a block (then it is assembled
        // alone); a further row joins if it adds few block entries.
        if (width > kMaxWidth ||
            (!first &&
             2 * (blockEntries(width) - blockEntries(groupColumns.size())) > blockEntries(m))) {
            return false;
        }
        for (int column : newColumns) {
            localOf[static_cast<std::size_t>(column)] = static_cast<int>(groupColumns.size());
            groupColumns.push_back(column);
        }
        return true;
    };
    auto closeGroup = [&](int firstRow, int rowEnd) {
        if (rowEnd - firstRow >= 2) {
            m_groups.push_back({firstRow, rowEnd, static_cast<int>(groupColumns.size()),
                                static_cast<int>(m_groupColumns.size()), 0, 0});
            m_groupColumns.insert(m_groupColumns.end(), groupColumns.begin(), groupColumns.end());
            for (int e = m_jacRowStart[firstRow]; e < m_jacRowStart[rowEnd]; ++e) {
                m_entryLocal[static_cast<std::size_t>(e)] =
                    localOf[static_cast<std::size_t>(m_jacColumn[static_cast<std::size_t>(e)])];
            }
        }
        for (int column : groupColumns) {
            localOf[static_cast<std::size_t>(column)] = -1;
        }
        groupColumns.clear();
    };
    for (int t = 0; t < problem.termCount(); ++t) {
        const int rowEnd = m_termRowStart[static_cast<std::size_t>(t) + 1];
        int r = m_termRowStart[t];
        while (r < rowEnd) {
            int q = r;
            if (tryJoin(q, true)) {
                ++q;
                while (q < rowEnd && tryJoin(q, false)) {
                    ++q;
                }
            } else {
                ++q; // wider than a block
            }
            closeGroup(r, q);
            r = q;
        }
    }
    std::size_t mostRows = 0;
    for (const RowGroup& group : m_groups) {
        mostRows = std::max(mostRows, static_cast<std::size_t>(group.rowEnd - group.firstRow));
    }
    m_groupRowSize = mostRows * kMaxWidth;
    m_groupBlockSize = kMaxWidth * kMaxWidth;
    m_scratch.rows.assign(m_groupRowSize, 0.0);
    m_scratch.block.assign(m_groupBlockSize, 0.0);
}

int NormalEquations::groupedRowCount() const {
    int rows = 0;
    for (const RowGroup& group : m_groups) {
        rows += group.rowEnd - group.firstRow;
    }
    return rows;
}

void NormalEquations::fillGroup(const RowGroup& group, double w2, const double* jac,
                                const double* residual, double* values, double* rhs,
                                FillScratch& scratch) const {
    const int width = group.width;
    const int rowCount = group.rowEnd - group.firstRow;
    const auto w = static_cast<std::size_t>(width);
    const auto k = static_cast<std::size_t>(rowCount);
    // The group's rows as a dense k × width matrix R (column-major, zero where a row has no
    // entry) and the right-hand side's share of them.
    double* rows = scratch.rows.data();
    std::fill_n(rows, k * w, 0.0);
    for (int r = group.firstRow; r < group.rowEnd; ++r) {
        double* row = rows + static_cast<std::size_t>(r - group.firstRow);
        for (int i = m_jacRowStart[r]; i < m_jacRowStart[r + 1]; ++i) {
            row[static_cast<std::size_t>(m_entryLocal[static_cast<std::size_t>(i)]) * k] += jac[i];
        }
        if (rhs) {
            const double f = w2 * residual[static_cast<std::size_t>(r)];
            for (int i = m_jacRowStart[r]; i < m_jacRowStart[r + 1]; ++i) {
                rhs[m_jacColumn[static_cast<std::size_t>(i)]] -= f * jac[i];
            }
        }
    }
    // The block Rᵀ R (column-major, leading dimension width) by BLAS; its upper triangle is
    // used. dgemm rather than dsyrk although it computes both triangles: OpenBLAS multiplies
    // small matrices without packing them only in dgemm (assembly ms per iteration with dsyrk /
    // dgemm: fig8-sheet 0.096 / 0.090, fig12-annulus 0.517 / 0.478, large-annulus 23.4 / 21.6).
    double* block = scratch.block.data();
    const char transposed = 'T';
    const char plain = 'N';
    const double one = 1.0;
    const double zero = 0.0;
    dgemm_(&transposed, &plain, &width, &width, &rowCount, &one, rows, &rowCount, rows, &rowCount,
           &zero, block, &width);
    // Its targets run column by column, (0, b) … (b, b) for b = 0 … width − 1 (build()).
    const int* target = m_groupPairTarget.data() + group.pairStart;
    for (std::size_t b = 0; b < w; ++b) {
        const double* column = block + b * w;
        for (std::size_t a = 0; a <= b; ++a) {
            values[*target++] += w2 * column[a];
        }
    }
}

} // namespace devsurf::solver
