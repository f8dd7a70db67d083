#include "solver/core/normal_equations.h"

#include "solver/core/blas_info.h"
#include "solver/core/finite_values.h"
#include "solver/core/problem.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <mutex>
#include <numeric>

namespace devsurf::solver {

namespace {

double termWeight(const Problem& problem, int term, double eps1, double proximity, double eps2) {
    const TermFamily& family = problem.family(problem.termFamily(term));
    switch (family.role) {
    case TermRole::Energy:
        return family.weight * eps1;
    case TermRole::Proximity:
        return family.weight * proximity;
    case TermRole::Damping:
        return family.weight * eps2;
    case TermRole::Constraint:
        break;
    }
    return family.weight;
}

} // namespace

bool NormalEquations::build(const Problem& problem, std::string* error) {
    m_built = false;
    m_evaluated = false;
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

    formGroups(problem);

    // Assembly units: a row outside groups (its entries, a column possibly repeated) or a
    // group (the union of its rows' columns). Every unit adds the products of all pairs of its
    // columns, so the pattern of the upper triangle of N is the union of the units' pairs and
    // the diagonal. Units are numbered rows-outside-groups first (in row order), then groups.
    std::vector<int> singleRows;
    {
        std::vector<char> grouped(static_cast<std::size_t>(m_rows), 0);
        for (const RowGroup& group : m_groups) {
            std::fill(grouped.begin() + group.firstRow, grouped.begin() + group.rowEnd, 1);
        }
        for (int r = 0; r < m_rows; ++r) {
            if (grouped[static_cast<std::size_t>(r)] == 0) {
                singleRows.push_back(r);
            }
        }
    }
    const auto singles = static_cast<int>(singleRows.size());
    const auto units = singles + static_cast<int>(m_groups.size());
    auto unitBegin = [&](int u) {
        return u < singles ? m_jacRowStart[singleRows[static_cast<std::size_t>(u)]]
                           : m_groups[static_cast<std::size_t>(u - singles)].columnStart;
    };
    auto unitEnd = [&](int u) {
        return u < singles ? m_jacRowStart[singleRows[static_cast<std::size_t>(u)] + 1]
                           : m_groups[static_cast<std::size_t>(u - singles)].columnStart +
                                 m_groups[static_cast<std::size_t>(u - singles)].width;
    };
    auto unitColumns = [&](int u) {
        return u < singles ? m_jacColumn.data() : m_groupColumns.data();
    };
    // Per single row, its first pair index; pairs (i, j), i <= j, in row order.
    std::vector<std::size_t> pairBase(static_cast<std::size_t>(singles) + 1, 0);
    for (int u = 0; u < singles; ++u) {
        const auto m = static_cast<std::size_t>(unitEnd(u) - unitBegin(u));
        pairBase[static_cast<std::size_t>(u) + 1] =
            pairBase[static_cast<std::size_t>(u)] + m * (m + 1) / 2;
    }
    // Per group, its block's targets (width × width, upper triangle used).
    std::vector<std::size_t> blockBase(m_groups.size() + 1, 0);
    for (std::size_t g = 0; g < m_groups.size(); ++g) {
        const auto w = static_cast<std::size_t>(m_groups[g].width);
        blockBase[g + 1] = blockBase[g] + w * w;
    }
    std::vector<int> blockTarget(blockBase.back(), -1);
    // Transpose: for each column, the (unit, entry) places it occurs at.
    std::vector<int> transposeStart(static_cast<std::size_t>(n) + 1, 0);
    for (int u = 0; u < units; ++u) {
        const int* columns = unitColumns(u);
        for (int e = unitBegin(u); e < unitEnd(u); ++e) {
            ++transposeStart[static_cast<std::size_t>(columns[e]) + 1];
        }
    }
    std::partial_sum(transposeStart.begin(), transposeStart.end(), transposeStart.begin());
    std::vector<int> transposeUnit(static_cast<std::size_t>(transposeStart.back()));
    std::vector<int> transposeEntry(transposeUnit.size());
    {
        std::vector<int> next(transposeStart.begin(), transposeStart.end() - 1);
        for (int u = 0; u < units; ++u) {
            const int* columns = unitColumns(u);
            for (int e = unitBegin(u); e < unitEnd(u); ++e) {
                const int k = next[static_cast<std::size_t>(columns[e])]++;
                transposeUnit[static_cast<std::size_t>(k)] = u;
                transposeEntry[static_cast<std::size_t>(k)] = e;
            }
        }
    }
    m_originalColStart.assign(static_cast<std::size_t>(n) + 1, 0);
    m_originalRowIndex.clear();
    m_originalRowIndex.reserve(static_cast<std::size_t>(transposeStart.back()) * 4 +
                               static_cast<std::size_t>(n));
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
            const int u = transposeUnit[static_cast<std::size_t>(k)];
            const int* columns = unitColumns(u);
            for (int e = unitBegin(u); e < unitEnd(u); ++e) {
                const int other = columns[e];
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
            const int u = transposeUnit[static_cast<std::size_t>(k)];
            const int begin = unitBegin(u);
            const int m = unitEnd(u) - begin;
            const int j = transposeEntry[static_cast<std::size_t>(k)] - begin;
            const int* columns = unitColumns(u);
            for (int i = 0; i < m; ++i) {
                const int other = columns[begin + i];
                if (other > c || (other == c && i > j)) {
                    continue;
                }
                const int target = position[static_cast<std::size_t>(other)];
                const auto a = static_cast<std::size_t>(std::min(i, j));
                const auto b = static_cast<std::size_t>(std::max(i, j));
                if (u >= singles) { // a group's columns are distinct
                    const auto g = static_cast<std::size_t>(u - singles);
                    blockTarget[blockBase[g] + a * static_cast<std::size_t>(m) + b] = target;
                    continue;
                }
                const std::size_t index = pairBase[static_cast<std::size_t>(u)] +
                                          a * static_cast<std::size_t>(m) - a * (a - 1) / 2 +
                                          (b - a);
                m_originalPairTarget[index] = target;
                // A column repeated within a row: the cross product lands on the diagonal
                // twice ((Jᵢ + Jⱼ)² = Jᵢ² + 2JᵢJⱼ + Jⱼ²).
                if (other == c && i < j) {
                    const int row = singleRows[static_cast<std::size_t>(u)];
                    const auto term = static_cast<int>(
                        std::upper_bound(m_termRowStart.begin(), m_termRowStart.end(), row) -
                        m_termRowStart.begin() - 1);
                    m_duplicates.push_back({begin + i, begin + j, term, target});
                }
            }
        }
    }
    // The blocks' upper triangles, column by column (the order fillGroup scatters in).
    m_originalGroupPairTarget.clear();
    for (std::size_t g = 0; g < m_groups.size(); ++g) {
        RowGroup& group = m_groups[g];
        const auto w = static_cast<std::size_t>(group.width);
        group.pairStart = static_cast<int>(m_originalGroupPairTarget.size());
        for (std::size_t b = 0; b < w; ++b) {
            for (std::size_t a = 0; a <= b; ++a) {
                m_originalGroupPairTarget.push_back(blockTarget[blockBase[g] + a * w + b]);
            }
        }
        group.pairEnd = static_cast<int>(m_originalGroupPairTarget.size());
    }

    m_structureId = problem.structureId();
    m_fixedRevision = ~std::uint64_t{0};
    m_built = true;
    setLayout({}, Triangle::Upper);
    return true;
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
    if (permutation.empty() && triangle == Triangle::Upper) {
        // The original layout itself: build() stores the upper triangle with the rows of each
        // column in increasing order, which is what the counting passes below would give.
        m_colStart = m_originalColStart;
        m_rowIndex = m_originalRowIndex;
        m_position.resize(m_originalRowIndex.size());
        std::iota(m_position.begin(), m_position.end(), 0);
        m_pairTarget = m_originalPairTarget;
        m_groupPairTarget = m_originalGroupPairTarget;
        m_diagonal = m_originalDiagonal;
        m_triangle = triangle;
        return;
    }
    std::vector<int> inverse(static_cast<std::size_t>(n));
    if (permutation.empty()) {
        std::iota(inverse.begin(), inverse.end(), 0);
    } else {
        for (int k = 0; k < n; ++k) {
            inverse[static_cast<std::size_t>(permutation[static_cast<std::size_t>(k)])] = k;
        }
    }
    // The stored entries in the new layout, ordered by column and then row with two counting
    // passes (by row, then stably by column): linear in the number of entries.
    const std::size_t nnz = m_originalRowIndex.size();
    std::vector<int> newRow(nnz);
    std::vector<int> newColumn(nnz);
    for (int c = 0; c < n; ++c) {
        for (int k = m_originalColStart[c]; k < m_originalColStart[c + 1]; ++k) {
            const int a = inverse[static_cast<std::size_t>(m_originalRowIndex[k])];
            const int b = inverse[static_cast<std::size_t>(c)];
            // Upper: column = the larger index, row = the smaller; lower: the other way.
            const bool upper = triangle == Triangle::Upper;
            newRow[static_cast<std::size_t>(k)] = upper ? std::min(a, b) : std::max(a, b);
            newColumn[static_cast<std::size_t>(k)] = upper ? std::max(a, b) : std::min(a, b);
        }
    }
    std::vector<int> byRow(nnz);
    {
        std::vector<int> next(static_cast<std::size_t>(n) + 1, 0);
        for (int row : newRow) {
            ++next[static_cast<std::size_t>(row) + 1];
        }
        std::partial_sum(next.begin(), next.end(), next.begin());
        for (std::size_t k = 0; k < nnz; ++k) {
            byRow[static_cast<std::size_t>(next[static_cast<std::size_t>(newRow[k])]++)] =
                static_cast<int>(k);
        }
    }
    m_colStart.assign(static_cast<std::size_t>(n) + 1, 0);
    for (int column : newColumn) {
        ++m_colStart[static_cast<std::size_t>(column) + 1];
    }
    std::partial_sum(m_colStart.begin(), m_colStart.end(), m_colStart.begin());
    m_rowIndex.resize(nnz);
    m_position.resize(nnz);
    {
        std::vector<int> next(m_colStart.begin(), m_colStart.end() - 1);
        for (int k : byRow) {
            const auto entry = static_cast<std::size_t>(k);
            const int at = next[static_cast<std::size_t>(newColumn[entry])]++;
            m_position[entry] = at;
            m_rowIndex[static_cast<std::size_t>(at)] = newRow[entry];
        }
    }
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

bool NormalEquations::evaluate(const Problem& problem, const double* x, bool onlyChanged) {
    const int termCount = problem.termCount();
    const auto n = static_cast<std::size_t>(problem.variableCount());
    // Skipping a term keeps its Jacobian with the fixed columns zeroed as they were.
    const bool partial = onlyChanged && m_evaluated && problem.fixedRevision() == m_fixedRevision &&
                         m_evaluatedAt.size() == n &&
                         std::memcmp(x, m_evaluatedAt.data(), n * sizeof(double)) == 0;
    m_evaluatedRevision.resize(static_cast<std::size_t>(termCount));
    bool finite = true; // the terms skipped were finite
    for (int t = 0; t < termCount; ++t) {
        const Term& term = problem.term(t);
        const auto k = static_cast<std::size_t>(t);
        const std::uint64_t revision = term.tracksChanges() ? term.revision() : 0;
        if (partial && revision != 0 && m_evaluatedRevision[k] == revision) {
            continue;
        }
        double* residual = m_residual.data() + m_termRowStart[k];
        double* jacobian = m_jacValue.data() + m_termJacStart[k];
        term.evaluate(x, residual, jacobian);
        finite = finite &&
                 allFinite(residual,
                           static_cast<std::size_t>(m_termRowStart[k + 1] - m_termRowStart[k])) &&
                 allFinite(jacobian,
                           static_cast<std::size_t>(m_termJacStart[k + 1] - m_termJacStart[k]));
        m_evaluatedRevision[k] = revision;
    }
    m_evaluated = finite;
    m_evaluatedAt.assign(x, x + n);
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
    double driving = 0.0;
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
                if (!family.judgedApart) {
                    maxResidual = std::max(maxResidual, std::abs(phi));
                }
                merit += w2 * phi * phi;
            } else if (family.role == TermRole::Energy) {
                energy += w2 * phi * phi;
                if (family.drivesEpsilon1) {
                    driving = std::max(driving, std::abs(family.weight * phi));
                }
            }
        }
    }
    m_maxConstraintResidual = maxResidual;
    m_maxDrivingResidual = std::max(maxResidual, driving);
    m_energy = energy;
    m_constraintMerit = merit;
    return finite;
}

void NormalEquations::rowWeights(const Problem& problem, double eps1, std::vector<double>& weights,
                                 double proximity, double eps2) const {
    weights.resize(static_cast<std::size_t>(m_rows));
    for (int t = 0; t < problem.termCount(); ++t) {
        const double w = termWeight(problem, t, eps1, proximity, eps2);
        std::fill(weights.begin() + m_termRowStart[t],
                  weights.begin() + m_termRowStart[static_cast<std::size_t>(t) + 1], w);
    }
}

void NormalEquations::termWeights2(const Problem& problem, double eps1, double eps2,
                                   double proximity, std::vector<double>& weights) const {
    weights.resize(static_cast<std::size_t>(problem.termCount()));
    for (int t = 0; t < problem.termCount(); ++t) {
        const double w = termWeight(problem, t, eps1, proximity, eps2);
        weights[static_cast<std::size_t>(t)] = w * w;
    }
}

void NormalEquations::fill(const Problem& problem, double eps1, double eps2, double* values,
                           double* rhs, double proximity) {
    termWeights2(problem, eps1, eps2, proximity, m_termWeight2);
    fillFrom(m_jacValue.data(), m_residual.data(), m_termWeight2, problem.fixedVariables(), eps2,
             values, rhs, m_scratch);
}

void NormalEquations::fillMatrix(const double* jacobian, const std::vector<double>& termWeight2,
                                 const std::vector<int>& fixed, double eps2, double* values,
                                 FillScratch& scratch) const {
    fillFrom(jacobian, nullptr, termWeight2, fixed, eps2, values, nullptr, scratch);
}

void NormalEquations::fillFrom(const double* jac, const double* residual,
                               const std::vector<double>& termWeight2,
                               const std::vector<int>& fixed, double eps2, double* values,
                               double* rhs, FillScratch& scratch) const {
    std::fill(values, values + m_rowIndex.size(), 0.0);
    if (rhs) {
        std::fill(rhs, rhs + m_variables, 0.0);
    }
    scratch.rows.resize(m_groupRowSize);
    scratch.block.resize(m_groupBlockSize);
    // The row groups call the BLAS (fillGroup).
    std::unique_lock<std::mutex> blasLock(blasMutex(), std::defer_lock);
    if (!m_groups.empty()) {
        blasLock.lock();
    }
    const int* column = m_jacColumn.data();
    const int* target = m_pairTarget.data();
    std::size_t p = 0;
    std::size_t nextGroup = 0;
    const auto terms = static_cast<int>(m_termRowStart.size()) - 1;
    for (int t = 0; t < terms; ++t) {
        const double w2 = termWeight2[static_cast<std::size_t>(t)];
        const int rowEnd = m_termRowStart[static_cast<std::size_t>(t) + 1];
        int r = m_termRowStart[t];
        while (r < rowEnd) {
            if (nextGroup < m_groups.size() && m_groups[nextGroup].firstRow == r) {
                const RowGroup& group = m_groups[nextGroup++];
                if (w2 != 0.0) {
                    fillGroup(group, w2, jac, residual, values, rhs, scratch);
                }
                r = group.rowEnd;
                continue;
            }
            const int begin = m_jacRowStart[r];
            const int end = m_jacRowStart[r + 1];
            if (w2 == 0.0) {
                const auto m = static_cast<std::size_t>(end - begin);
                p += m * (m + 1) / 2;
                ++r;
                continue;
            }
            if (rhs) {
                const double f = w2 * residual[static_cast<std::size_t>(r)];
                for (int i = begin; i < end; ++i) {
                    rhs[column[i]] -= f * jac[i];
                }
            }
            for (int i = begin; i < end; ++i) {
                const double a = w2 * jac[i];
                for (int j = i; j < end; ++j) {
                    values[target[p++]] += a * jac[j];
                }
            }
            ++r;
        }
    }
    for (const DuplicatePair& d : m_duplicates) {
        values[m_position[static_cast<std::size_t>(d.target)]] +=
            termWeight2[static_cast<std::size_t>(d.term)] * jac[d.first] * jac[d.second];
    }
    const double e2 = eps2 * eps2;
    for (int v : m_diagonal) {
        values[v] += e2;
    }
    // Fixed variables: their rows and columns are zero; a unit diagonal keeps N definite.
    for (int v : fixed) {
        values[m_diagonal[static_cast<std::size_t>(v)]] += 1.0;
    }
}

void NormalEquations::fillRightHandSide(const Problem& problem, double eps1, double proximity,
                                        double eps2, const std::vector<double>& jacobian,
                                        double* rhs) const {
    std::fill(rhs, rhs + m_variables, 0.0);
    for (int t = 0; t < problem.termCount(); ++t) {
        const double w = termWeight(problem, t, eps1, proximity, eps2);
        const double w2 = w * w;
        if (w2 == 0.0) {
            continue;
        }
        for (int r = m_termRowStart[t]; r < m_termRowStart[static_cast<std::size_t>(t) + 1]; ++r) {
            const double f = w2 * m_residual[static_cast<std::size_t>(r)];
            for (int i = m_jacRowStart[r]; i < m_jacRowStart[r + 1]; ++i) {
                rhs[m_jacColumn[static_cast<std::size_t>(i)]] -=
                    f * jacobian[static_cast<std::size_t>(i)];
            }
        }
    }
}

Eigen::SparseMatrix<double> NormalEquations::weightedJacobian(const Problem& problem, double eps1,
                                                              double proximity, double eps2) const {
    std::vector<Eigen::Triplet<double>> triplets;
    triplets.reserve(m_jacColumn.size());
    for (int t = 0; t < problem.termCount(); ++t) {
        const double w = termWeight(problem, t, eps1, proximity, eps2);
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
    const Eigen::SparseMatrix<double> h = weightedJacobian(problem, eps1, proximity, eps2);
    std::vector<double> weights;
    rowWeights(problem, eps1, weights, proximity, eps2);
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
