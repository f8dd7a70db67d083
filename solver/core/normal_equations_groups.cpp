// The row groups of NormalEquations: which consecutive rows are assembled together through
// one dense block (formGroups, at build time) and that block's assembly (fillGroup, in every
// fill). See normal_equations.h.
#include "solver/core/normal_equations.h"

#include "solver/core/problem.h"

#include <algorithm>

namespace devsurf::solver {

namespace {
constexpr int kRowsAtOnce = 4;
} // namespace

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
    m_groupRow.assign(kRowsAtOnce * kMaxWidth, 0.0);
    m_groupBlock.assign(kMaxWidth * (kMaxWidth + 1) / 2, 0.0);
}

int NormalEquations::groupedRowCount() const {
    int rows = 0;
    for (const RowGroup& group : m_groups) {
        rows += group.rowEnd - group.firstRow;
    }
    return rows;
}

void NormalEquations::fillGroup(const RowGroup& group, double w2, double* values, double* rhs) {
    const int width = group.width;
    const auto w = static_cast<std::size_t>(width);
    // Four rows at a time, dense over the group's columns (zero where a row has none).
    double* rows = m_groupRow.data();
    // The block's upper triangle, packed row by row: entry (s, t), s <= t, at
    // start(s) + t with start(s) = s·width − s(s + 1)/2.
    double* block = m_groupBlock.data();
    std::fill_n(block, w * (w + 1) / 2, 0.0);
    const double* jac = m_jacValue.data();
    for (int first = group.firstRow; first < group.rowEnd; first += kRowsAtOnce) {
        std::fill_n(rows, kRowsAtOnce * w, 0.0);
        const int last = std::min(group.rowEnd, first + kRowsAtOnce);
        for (int r = first; r < last; ++r) {
            const double f = w2 * m_residual[static_cast<std::size_t>(r)];
            double* row = rows + static_cast<std::size_t>(r - first) * w;
            for (int i = m_jacRowStart[r]; i < m_jacRowStart[r + 1]; ++i) {
                rhs[m_jacColumn[static_cast<std::size_t>(i)]] -= f * jac[i];
                row[m_entryLocal[static_cast<std::size_t>(i)]] += jac[i];
            }
        }
        // Σ row rowᵀ over the four rows (rows past the group's end are zero): one pass over
        // the block for four rows.
        const double* r0 = rows;
        const double* r1 = rows + w;
        const double* r2 = rows + 2 * w;
        const double* r3 = rows + 3 * w;
        double* out = block;
        for (int s = 0; s < width; ++s) {
            const double a0 = r0[s];
            const double a1 = r1[s];
            const double a2 = r2[s];
            const double a3 = r3[s];
            if (a0 != 0.0 || a1 != 0.0 || a2 != 0.0 || a3 != 0.0) {
                for (int t = s; t < width; ++t) {
                    out[t] += a0 * r0[t] + a1 * r1[t] + a2 * r2[t] + a3 * r3[t];
                }
            }
            out += width - s - 1; // start(s + 1) = start(s) + width − s − 1
        }
    }
    const int* target = m_groupPairTarget.data() + group.pairStart;
    const auto entries = static_cast<std::size_t>(group.pairEnd - group.pairStart);
    for (std::size_t k = 0; k < entries; ++k) {
        values[target[k]] += w2 * block[k];
    }
}

} // namespace devsurf::solver
