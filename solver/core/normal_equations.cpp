#include "solver/core/normal_equations.h"

#include "solver/core/problem.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace devsurf::solver {

namespace {

double termWeight(const Problem& problem, int term, double eps1, double proximity) {
    const TermFamily& family = problem.family(problem.termFamily(term));
    switch (family.role) {
    case TermRole::Energy:
        return family.weight * eps1;
    case TermRole::Proximity:
        return family.weight * proximity;
    case TermRole::Constraint:
        break;
    }
    return family.weight;
}

// Builds a CSC pattern from sorted unique keys column * n + row.
void keysToCsc(const std::vector<std::uint64_t>& keys, int n, std::vector<int>& colStart,
               std::vector<int>& rowIndex) {
    colStart.assign(static_cast<std::size_t>(n) + 1, 0);
    rowIndex.resize(keys.size());
    for (std::size_t k = 0; k < keys.size(); ++k) {
        const auto column = static_cast<std::size_t>(keys[k] / static_cast<std::uint64_t>(n));
        rowIndex[k] = static_cast<int>(keys[k] % static_cast<std::uint64_t>(n));
        ++colStart[column + 1];
    }
    std::partial_sum(colStart.begin(), colStart.end(), colStart.begin());
}

} // namespace

bool NormalEquations::build(const Problem& problem, std::string* error) {
    m_built = false;
    const int n = problem.variableCount();
    const int termCount = problem.termCount();
    m_variables = n;
    m_termRowStart.assign(1, 0);
    m_termJacStart.assign(1, 0);
    m_jacRowStart.clear();
    m_jacColumn.clear();
    for (int t = 0; t < termCount; ++t) {
        const Term& term = problem.term(t);
        const std::size_t rowsBefore = m_jacRowStart.size();
        PatternBuilder builder(m_jacRowStart, m_jacColumn);
        term.buildPattern(builder);
        const auto emitted = static_cast<int>(m_jacRowStart.size() - rowsBefore);
        if (emitted != term.rowCount()) {
            if (error) {
                *error = std::string(term.typeName()) + " emitted " + std::to_string(emitted) +
                         " pattern rows for " + std::to_string(term.rowCount()) + " rows";
            }
            return false;
        }
        m_termRowStart.push_back(static_cast<int>(m_jacRowStart.size()));
        m_termJacStart.push_back(static_cast<int>(m_jacColumn.size()));
    }
    m_rows = static_cast<int>(m_jacRowStart.size());
    m_jacRowStart.push_back(static_cast<int>(m_jacColumn.size()));
    for (int c : m_jacColumn) {
        if (c < 0 || c >= n) {
            if (error) {
                *error = "Jacobian column " + std::to_string(c) + " outside [0, " +
                         std::to_string(n) + ")";
            }
            return false;
        }
    }
    m_jacValue.assign(m_jacColumn.size(), 0.0);
    m_residual.assign(static_cast<std::size_t>(m_rows), 0.0);
    m_rowWeight2.assign(static_cast<std::size_t>(m_rows), 0.0);

    // Pattern of the upper triangle of JᵀJ + I, column by column through the transpose of J
    // (a symbolic sparse product), and for every pair of Jacobian entries in a row the index
    // of the nonzero it contributes to. Pairs of row r are enumerated as (i, j), i <= j, in
    // row order, starting at pairBase[r].
    std::vector<std::size_t> pairBase(static_cast<std::size_t>(m_rows) + 1, 0);
    for (int r = 0; r < m_rows; ++r) {
        const auto m = static_cast<std::size_t>(m_jacRowStart[r + 1] - m_jacRowStart[r]);
        pairBase[static_cast<std::size_t>(r) + 1] =
            pairBase[static_cast<std::size_t>(r)] + m * (m + 1) / 2;
    }
    // Transpose of J: for each column, the Jacobian entries in it.
    std::vector<int> transposeStart(static_cast<std::size_t>(n) + 1, 0);
    for (int c : m_jacColumn) {
        ++transposeStart[static_cast<std::size_t>(c) + 1];
    }
    std::partial_sum(transposeStart.begin(), transposeStart.end(), transposeStart.begin());
    std::vector<int> transposeEntry(m_jacColumn.size());
    std::vector<int> transposeRow(m_jacColumn.size());
    {
        std::vector<int> next(transposeStart.begin(), transposeStart.end() - 1);
        for (int r = 0; r < m_rows; ++r) {
            for (int e = m_jacRowStart[r]; e < m_jacRowStart[r + 1]; ++e) {
                const int k = next[static_cast<std::size_t>(m_jacColumn[e])]++;
                transposeEntry[static_cast<std::size_t>(k)] = e;
                transposeRow[static_cast<std::size_t>(k)] = r;
            }
        }
    }
    m_originalColStart.assign(static_cast<std::size_t>(n) + 1, 0);
    m_originalRowIndex.clear();
    m_originalRowIndex.reserve(m_jacColumn.size() * 4 + static_cast<std::size_t>(n));
    m_originalPairTarget.assign(pairBase.back(), -1);
    m_originalDiagonal.resize(static_cast<std::size_t>(n));
    m_duplicates.clear();
    std::vector<int> mark(static_cast<std::size_t>(n), -1);
    std::vector<int> position(static_cast<std::size_t>(n), 0);
    std::vector<int> rowsOfColumn;
    for (int c = 0; c < n; ++c) {
        rowsOfColumn.clear();
        rowsOfColumn.push_back(c);
        mark[static_cast<std::size_t>(c)] = c;
        for (int k = transposeStart[c]; k < transposeStart[static_cast<std::size_t>(c) + 1]; ++k) {
            const int r = transposeRow[static_cast<std::size_t>(k)];
            for (int e = m_jacRowStart[r]; e < m_jacRowStart[r + 1]; ++e) {
                const int other = m_jacColumn[e];
                if (other < c && mark[static_cast<std::size_t>(other)] != c) {
                    mark[static_cast<std::size_t>(other)] = c;
                    rowsOfColumn.push_back(other);
                }
            }
        }
        std::sort(rowsOfColumn.begin(), rowsOfColumn.end());
        const auto start = static_cast<int>(m_originalRowIndex.size());
        for (std::size_t k = 0; k < rowsOfColumn.size(); ++k) {
            position[static_cast<std::size_t>(rowsOfColumn[k])] = start + static_cast<int>(k);
            m_originalRowIndex.push_back(rowsOfColumn[k]);
        }
        m_originalColStart[static_cast<std::size_t>(c) + 1] =
            static_cast<int>(m_originalRowIndex.size());
        m_originalDiagonal[static_cast<std::size_t>(c)] = position[static_cast<std::size_t>(c)];
        // Every pair whose larger column is c gets its target here, exactly once.
        for (int k = transposeStart[c]; k < transposeStart[static_cast<std::size_t>(c) + 1]; ++k) {
            const int r = transposeRow[static_cast<std::size_t>(k)];
            const int begin = m_jacRowStart[r];
            const int m = m_jacRowStart[r + 1] - begin;
            const int j = transposeEntry[static_cast<std::size_t>(k)] - begin;
            for (int i = 0; i < m; ++i) {
                const int other = m_jacColumn[static_cast<std::size_t>(begin + i)];
                if (other > c || (other == c && i > j)) {
                    continue;
                }
                const auto a = static_cast<std::size_t>(std::min(i, j));
                const auto b = static_cast<std::size_t>(std::max(i, j));
                const std::size_t index = pairBase[static_cast<std::size_t>(r)] +
                                          a * static_cast<std::size_t>(m) - a * (a - 1) / 2 +
                                          (b - a);
                const int target = position[static_cast<std::size_t>(other)];
                m_originalPairTarget[index] = target;
                // A column repeated within a row: the cross product lands on the diagonal
                // twice ((Jᵢ + Jⱼ)² = Jᵢ² + 2JᵢJⱼ + Jⱼ²).
                if (other == c && i < j) {
                    m_duplicates.push_back({begin + i, begin + j, r, target});
                }
            }
        }
    }

    formGroups(problem, pairBase);

    m_structureId = problem.structureId();
    m_fixedRevision = ~std::uint64_t{0};
    m_built = true;
    setLayout({}, Triangle::Upper);
    return true;
}

void NormalEquations::formGroups(const Problem& problem, const std::vector<std::size_t>& pairBase) {
    // A group is grown row by row while each new row adds at most half as many block entries
    // as it has products of its own, up to kMaxWidth columns: the rows of (4) at the values of
    // one interval (all on the same control points) join, the next interval's (a shifted set)
    // starts a new group, and rows that share nothing (fairness, unit norms) stay alone.
    constexpr int kMaxWidth = 64;
    const auto maxWidth = static_cast<std::size_t>(kMaxWidth);
    m_groups.clear();
    m_groupPairLocal.clear();
    m_originalGroupPairTarget.clear();
    m_entryLocal.assign(m_jacColumn.size(), -1);
    std::vector<int> localOf(static_cast<std::size_t>(m_variables), -1);
    std::vector<int> groupColumns;
    std::vector<unsigned char> seen(maxWidth * maxWidth, 0);
    std::vector<int> seenList;   // entries of `seen` set for the current group
    std::vector<int> newColumns; // columns a candidate row would add
    std::vector<int> candidate;  // entries of `seen` a candidate row would set
    std::vector<int> rowLocal;   // a candidate row's entries' local indices
    auto localIndex = [&](int column) {
        const int known = localOf[static_cast<std::size_t>(column)];
        if (known >= 0) {
            return known;
        }
        const auto it = std::find(newColumns.begin(), newColumns.end(), column);
        if (it == newColumns.end()) {
            newColumns.push_back(column);
            return static_cast<int>(groupColumns.size() + newColumns.size()) - 1;
        }
        return static_cast<int>(groupColumns.size()) + static_cast<int>(it - newColumns.begin());
    };
    // Tries to add row r to the current group; true if it joined.
    auto tryJoin = [&](int r, bool first) {
        newColumns.clear();
        candidate.clear();
        const int begin = m_jacRowStart[r];
        const int end = m_jacRowStart[r + 1];
        rowLocal.clear();
        for (int i = begin; i < end; ++i) {
            rowLocal.push_back(localIndex(m_jacColumn[static_cast<std::size_t>(i)]));
        }
        for (std::size_t i = 0; i < rowLocal.size(); ++i) {
            const int li = rowLocal[i];
            for (std::size_t j = i; j < rowLocal.size(); ++j) {
                const int lj = rowLocal[j];
                const int packed = std::min(li, lj) * kMaxWidth + std::max(li, lj);
                if (std::max(li, lj) < kMaxWidth && seen[static_cast<std::size_t>(packed)] == 0) {
                    seen[static_cast<std::size_t>(packed)] = 1;
                    candidate.push_back(packed);
                }
            }
        }
        const auto m = static_cast<std::size_t>(end - begin);
        const bool fits = groupColumns.size() + newColumns.size() <= maxWidth;
        // A first row always starts a group unless it is wider than a block (then it is
        // assembled alone); a further row joins if it adds few new block entries.
        if (!fits || (!first && 2 * candidate.size() > m * (m + 1) / 2)) {
            for (int packed : candidate) {
                seen[static_cast<std::size_t>(packed)] = 0;
            }
            return false;
        }
        seenList.insert(seenList.end(), candidate.begin(), candidate.end());
        for (int column : newColumns) {
            localOf[static_cast<std::size_t>(column)] = static_cast<int>(groupColumns.size());
            groupColumns.push_back(column);
        }
        return true;
    };
    auto closeGroup = [&](int firstRow, int rowEnd) {
        const auto width = static_cast<int>(groupColumns.size());
        if (rowEnd - firstRow >= 2) {
            RowGroup group{firstRow, rowEnd, width, static_cast<int>(m_groupPairLocal.size()), 0};
            std::vector<int> targetOf(static_cast<std::size_t>(width * width), -1);
            for (int r = firstRow; r < rowEnd; ++r) {
                const int begin = m_jacRowStart[r];
                const int end = m_jacRowStart[r + 1];
                std::size_t pair = pairBase[static_cast<std::size_t>(r)];
                for (int i = begin; i < end; ++i) {
                    const int li = localOf[static_cast<std::size_t>(m_jacColumn[i])];
                    m_entryLocal[static_cast<std::size_t>(i)] = li;
                    for (int j = i; j < end; ++j, ++pair) {
                        const int lj = localOf[static_cast<std::size_t>(m_jacColumn[j])];
                        const int packed = std::min(li, lj) * width + std::max(li, lj);
                        if (targetOf[static_cast<std::size_t>(packed)] < 0) {
                            targetOf[static_cast<std::size_t>(packed)] = m_originalPairTarget[pair];
                            m_groupPairLocal.push_back(packed);
                            m_originalGroupPairTarget.push_back(m_originalPairTarget[pair]);
                        }
                    }
                }
            }
            group.pairEnd = static_cast<int>(m_groupPairLocal.size());
            m_groups.push_back(group);
        }
        for (int column : groupColumns) {
            localOf[static_cast<std::size_t>(column)] = -1;
        }
        groupColumns.clear();
        for (int packed : seenList) {
            seen[static_cast<std::size_t>(packed)] = 0;
        }
        seenList.clear();
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

    // Keep the per-pair targets and the repeated-column corrections of ungrouped rows only.
    std::vector<char> grouped(static_cast<std::size_t>(m_rows), 0);
    for (const RowGroup& group : m_groups) {
        std::fill(grouped.begin() + group.firstRow, grouped.begin() + group.rowEnd, 1);
    }
    std::vector<int> singleTargets;
    for (int r = 0; r < m_rows; ++r) {
        if (grouped[static_cast<std::size_t>(r)] == 0) {
            singleTargets.insert(
                singleTargets.end(),
                m_originalPairTarget.begin() +
                    static_cast<std::ptrdiff_t>(pairBase[static_cast<std::size_t>(r)]),
                m_originalPairTarget.begin() +
                    static_cast<std::ptrdiff_t>(pairBase[static_cast<std::size_t>(r) + 1]));
        }
    }
    m_originalPairTarget = std::move(singleTargets);
    m_duplicates.erase(std::remove_if(m_duplicates.begin(), m_duplicates.end(),
                                      [&grouped](const DuplicatePair& d) {
                                          return grouped[static_cast<std::size_t>(d.row)] != 0;
                                      }),
                       m_duplicates.end());
    m_groupRow.assign(maxWidth, 0.0);
    m_groupBlock.assign(maxWidth * maxWidth, 0.0);
}

int NormalEquations::groupedRowCount() const {
    int rows = 0;
    for (const RowGroup& group : m_groups) {
        rows += group.rowEnd - group.firstRow;
    }
    return rows;
}

bool NormalEquations::matches(const Problem& problem) const {
    if (!m_built || problem.structureId() != m_structureId ||
        problem.variableCount() != m_variables ||
        problem.termCount() + 1 != static_cast<int>(m_termRowStart.size())) {
        return false;
    }
    for (int t = 0; t < problem.termCount(); ++t) {
        if (problem.term(t).rowCount() !=
            m_termRowStart[static_cast<std::size_t>(t) + 1] - m_termRowStart[t]) {
            return false;
        }
    }
    return true;
}

void NormalEquations::setLayout(const std::vector<int>& permutation, Triangle triangle) {
    const int n = m_variables;
    const auto un = static_cast<std::uint64_t>(n);
    std::vector<int> inverse(static_cast<std::size_t>(n));
    if (permutation.empty()) {
        std::iota(inverse.begin(), inverse.end(), 0);
    } else {
        for (int k = 0; k < n; ++k) {
            inverse[static_cast<std::size_t>(permutation[static_cast<std::size_t>(k)])] = k;
        }
    }
    const std::size_t nnz = m_originalRowIndex.size();
    std::vector<std::uint64_t> newKey(nnz);
    for (int c = 0; c < n; ++c) {
        for (int k = m_originalColStart[c]; k < m_originalColStart[c + 1]; ++k) {
            const int a = inverse[static_cast<std::size_t>(m_originalRowIndex[k])];
            const int b = inverse[static_cast<std::size_t>(c)];
            const auto lo = static_cast<std::uint64_t>(std::min(a, b));
            const auto hi = static_cast<std::uint64_t>(std::max(a, b));
            // Upper: column = hi, row = lo. Lower: column = lo, row = hi.
            newKey[static_cast<std::size_t>(k)] =
                triangle == Triangle::Upper ? hi * un + lo : lo * un + hi;
        }
    }
    std::vector<int> order(nnz);
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(), [&newKey](int a, int b) {
        return newKey[static_cast<std::size_t>(a)] < newKey[static_cast<std::size_t>(b)];
    });
    m_position.resize(nnz);
    std::vector<std::uint64_t> sortedKeys(nnz);
    for (std::size_t k = 0; k < nnz; ++k) {
        m_position[static_cast<std::size_t>(order[k])] = static_cast<int>(k);
        sortedKeys[k] = newKey[static_cast<std::size_t>(order[k])];
    }
    keysToCsc(sortedKeys, n, m_colStart, m_rowIndex);
    m_pairTarget.resize(m_originalPairTarget.size());
    for (std::size_t p = 0; p < m_pairTarget.size(); ++p) {
        m_pairTarget[p] = m_position[static_cast<std::size_t>(m_originalPairTarget[p])];
    }
    m_groupPairTarget.resize(m_originalGroupPairTarget.size());
    for (std::size_t p = 0; p < m_groupPairTarget.size(); ++p) {
        m_groupPairTarget[p] = m_position[static_cast<std::size_t>(m_originalGroupPairTarget[p])];
    }
    m_diagonal.resize(m_originalDiagonal.size());
    for (std::size_t v = 0; v < m_diagonal.size(); ++v) {
        m_diagonal[v] = m_position[static_cast<std::size_t>(m_originalDiagonal[v])];
    }
    m_triangle = triangle;
}

bool NormalEquations::evaluate(const Problem& problem, const double* x) {
    const int termCount = problem.termCount();
    for (int t = 0; t < termCount; ++t) {
        problem.term(t).evaluate(x, m_residual.data() + m_termRowStart[t],
                                 m_jacValue.data() + m_termJacStart[t]);
    }
    bool finite = true;
    for (double v : m_residual) {
        finite = finite && std::isfinite(v);
    }
    for (double v : m_jacValue) {
        finite = finite && std::isfinite(v);
    }
    if (problem.fixedRevision() != m_fixedRevision) {
        // Only when the set of fixed variables changed (not inside the iteration loop).
        m_fixedJacobianEntries.clear();
        for (std::size_t e = 0; e < m_jacColumn.size(); ++e) {
            if (problem.isFixed(m_jacColumn[e])) {
                m_fixedJacobianEntries.push_back(static_cast<int>(e));
            }
        }
        m_fixedRevision = problem.fixedRevision();
    }
    for (int e : m_fixedJacobianEntries) {
        m_jacValue[static_cast<std::size_t>(e)] = 0.0;
    }
    double maxResidual = 0.0;
    double energy = 0.0;
    double merit = 0.0;
    for (int t = 0; t < termCount; ++t) {
        const TermFamily& family = problem.family(problem.termFamily(t));
        if (family.weight == 0.0) {
            continue;
        }
        const double w2 = family.weight * family.weight;
        for (int r = m_termRowStart[t]; r < m_termRowStart[static_cast<std::size_t>(t) + 1]; ++r) {
            const double phi = m_residual[static_cast<std::size_t>(r)];
            if (family.role == TermRole::Constraint) {
                maxResidual = std::max(maxResidual, std::abs(phi));
                merit += w2 * phi * phi;
            } else if (family.role == TermRole::Energy) {
                energy += w2 * phi * phi;
            }
        }
    }
    m_maxConstraintResidual = maxResidual;
    m_energy = energy;
    m_constraintMerit = merit;
    return finite;
}

void NormalEquations::rowWeights(const Problem& problem, double eps1, std::vector<double>& weights,
                                 double proximity) const {
    weights.resize(static_cast<std::size_t>(m_rows));
    for (int t = 0; t < problem.termCount(); ++t) {
        const double w = termWeight(problem, t, eps1, proximity);
        std::fill(weights.begin() + m_termRowStart[t],
                  weights.begin() + m_termRowStart[static_cast<std::size_t>(t) + 1], w);
    }
}

void NormalEquations::fill(const Problem& problem, double eps1, double eps2, double* values,
                           double* rhs, double proximity) {
    std::fill(values, values + m_rowIndex.size(), 0.0);
    std::fill(rhs, rhs + m_variables, 0.0);
    const double* jac = m_jacValue.data();
    const int* column = m_jacColumn.data();
    const int* target = m_pairTarget.data();
    std::size_t p = 0;
    std::size_t nextGroup = 0;
    for (int t = 0; t < problem.termCount(); ++t) {
        const double w = termWeight(problem, t, eps1, proximity);
        const double w2 = w * w;
        const int rowEnd = m_termRowStart[static_cast<std::size_t>(t) + 1];
        int r = m_termRowStart[t];
        while (r < rowEnd) {
            if (nextGroup < m_groups.size() && m_groups[nextGroup].firstRow == r) {
                const RowGroup& group = m_groups[nextGroup++];
                for (int q = group.firstRow; q < group.rowEnd; ++q) {
                    m_rowWeight2[static_cast<std::size_t>(q)] = w2;
                }
                if (w2 != 0.0) {
                    fillGroup(group, w2, values, rhs);
                }
                r = group.rowEnd;
                continue;
            }
            m_rowWeight2[static_cast<std::size_t>(r)] = w2;
            const int begin = m_jacRowStart[r];
            const int end = m_jacRowStart[r + 1];
            if (w2 == 0.0) {
                const auto m = static_cast<std::size_t>(end - begin);
                p += m * (m + 1) / 2;
                ++r;
                continue;
            }
            const double f = w2 * m_residual[static_cast<std::size_t>(r)];
            for (int i = begin; i < end; ++i) {
                const double a = w2 * jac[i];
                rhs[column[i]] -= f * jac[i];
                for (int j = i; j < end; ++j) {
                    values[target[p++]] += a * jac[j];
                }
            }
            ++r;
        }
    }
    for (const DuplicatePair& d : m_duplicates) {
        values[m_position[static_cast<std::size_t>(d.target)]] +=
            m_rowWeight2[static_cast<std::size_t>(d.row)] * jac[d.first] * jac[d.second];
    }
    const double e2 = eps2 * eps2;
    for (int v : m_diagonal) {
        values[v] += e2;
    }
    // Fixed variables: their rows and columns are zero; a unit diagonal keeps N definite.
    for (int v : problem.fixedVariables()) {
        values[m_diagonal[static_cast<std::size_t>(v)]] += 1.0;
    }
}

void NormalEquations::fillGroup(const RowGroup& group, double w2, double* values, double* rhs) {
    const int width = group.width;
    const auto w = static_cast<std::size_t>(width);
    double* row = m_groupRow.data();
    double* block = m_groupBlock.data();
    std::fill_n(block, w * w, 0.0);
    const double* jac = m_jacValue.data();
    for (int r = group.firstRow; r < group.rowEnd; ++r) {
        const int begin = m_jacRowStart[r];
        const int end = m_jacRowStart[r + 1];
        const double f = w2 * m_residual[static_cast<std::size_t>(r)];
        std::fill_n(row, w, 0.0);
        for (int i = begin; i < end; ++i) {
            rhs[m_jacColumn[static_cast<std::size_t>(i)]] -= f * jac[i];
            row[m_entryLocal[static_cast<std::size_t>(i)]] += jac[i];
        }
        // The block's upper triangle in the group's column order: row rowᵀ, summed over rows.
        for (int s = 0; s < width; ++s) {
            const double a = row[s];
            if (a == 0.0) {
                continue;
            }
            double* out = block + static_cast<std::size_t>(s) * w;
            for (int t = s; t < width; ++t) {
                out[t] += a * row[t];
            }
        }
    }
    for (int k = group.pairStart; k < group.pairEnd; ++k) {
        values[m_groupPairTarget[static_cast<std::size_t>(k)]] +=
            w2 * block[m_groupPairLocal[static_cast<std::size_t>(k)]];
    }
}

Eigen::SparseMatrix<double> NormalEquations::weightedJacobian(const Problem& problem, double eps1,
                                                              double proximity) const {
    std::vector<Eigen::Triplet<double>> triplets;
    triplets.reserve(m_jacColumn.size());
    for (int t = 0; t < problem.termCount(); ++t) {
        const double w = termWeight(problem, t, eps1, proximity);
        for (int r = m_termRowStart[t]; r < m_termRowStart[static_cast<std::size_t>(t) + 1]; ++r) {
            for (int e = m_jacRowStart[r]; e < m_jacRowStart[r + 1]; ++e) {
                const int c = m_jacColumn[static_cast<std::size_t>(e)];
                if (!problem.isFixed(c)) {
                    triplets.emplace_back(r, c, w * m_jacValue[static_cast<std::size_t>(e)]);
                }
            }
        }
    }
    Eigen::SparseMatrix<double> h(m_rows, m_variables);
    h.setFromTriplets(triplets.begin(), triplets.end());
    return h;
}

void NormalEquations::assembleFromScratch(const Problem& problem, double eps1, double eps2,
                                          Eigen::SparseMatrix<double>& upper, Eigen::VectorXd& rhs,
                                          double proximity) const {
    const Eigen::SparseMatrix<double> h = weightedJacobian(problem, eps1, proximity);
    std::vector<double> weights;
    rowWeights(problem, eps1, weights, proximity);
    Eigen::VectorXd weightedResidual(m_rows);
    for (int r = 0; r < m_rows; ++r) {
        weightedResidual[r] =
            weights[static_cast<std::size_t>(r)] * m_residual[static_cast<std::size_t>(r)];
    }
    rhs = -(h.transpose() * weightedResidual);
    Eigen::SparseMatrix<double> diagonal(m_variables, m_variables);
    diagonal.setIdentity();
    diagonal *= eps2 * eps2;
    for (int v : problem.fixedVariables()) {
        diagonal.coeffRef(v, v) += 1.0;
    }
    const Eigen::SparseMatrix<double> full =
        Eigen::SparseMatrix<double>(h.transpose() * h) + diagonal;
    upper = full.triangularView<Eigen::Upper>();
    upper.makeCompressed();
}

Eigen::SparseMatrix<double> NormalEquations::toOriginalUpper(const double* values) const {
    std::vector<Eigen::Triplet<double>> triplets;
    triplets.reserve(m_originalRowIndex.size());
    for (int c = 0; c < m_variables; ++c) {
        for (int k = m_originalColStart[c]; k < m_originalColStart[c + 1]; ++k) {
            triplets.emplace_back(m_originalRowIndex[static_cast<std::size_t>(k)], c,
                                  values[m_position[static_cast<std::size_t>(k)]]);
        }
    }
    Eigen::SparseMatrix<double> m(m_variables, m_variables);
    m.setFromTriplets(triplets.begin(), triplets.end());
    return m;
}

} // namespace devsurf::solver
