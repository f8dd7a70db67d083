#include "solver/core/linear_term.h"

namespace devsurf::solver {

int LinearTerm::addRow(const std::vector<Entry>& entries, double rhs) {
    changed();
    m_entries.insert(m_entries.end(), entries.begin(), entries.end());
    m_rowStart.push_back(static_cast<int>(m_entries.size()));
    m_rhs.push_back(rhs);
    return static_cast<int>(m_rhs.size()) - 1;
}

int LinearTerm::addPointRelation(int dimension, const PointCombination& points, const double* rhs) {
    const int first = rowCount();
    std::vector<Entry> row;
    for (int k = 0; k < dimension; ++k) {
        row.clear();
        for (const PointTerm& p : points) {
            row.push_back({p.offset + k, p.coefficient});
        }
        addRow(row, rhs ? rhs[k] : 0.0);
    }
    return first;
}

void LinearTerm::buildPattern(PatternBuilder& builder) const {
    for (std::size_t r = 0; r < m_rhs.size(); ++r) {
        builder.beginRow();
        for (int e = m_rowStart[r]; e < m_rowStart[r + 1]; ++e) {
            builder.addColumn(m_entries[static_cast<std::size_t>(e)].column);
        }
    }
}

int LinearTerm::evaluateOne(std::size_t r, const double* x, double* residual,
                            double* jacobian) const {
    double value = -m_rhs[r];
    double* out = jacobian;
    for (int e = m_rowStart[r]; e < m_rowStart[r + 1]; ++e) {
        const Entry& entry = m_entries[static_cast<std::size_t>(e)];
        value += entry.coefficient * x[entry.column];
        *out++ = entry.coefficient;
    }
    *residual = value;
    return static_cast<int>(out - jacobian);
}

void LinearTerm::evaluate(const double* x, double* residuals, double* jacobian) const {
    for (std::size_t r = 0; r < m_rhs.size(); ++r) {
        jacobian += evaluateOne(r, x, residuals + r, jacobian);
    }
}

bool LinearTerm::evaluateRow(int row, const double* x, double* residual, double* jacobian) const {
    evaluateOne(static_cast<std::size_t>(row), x, residual, jacobian);
    return true;
}

} // namespace devsurf::solver
