#include "solver/core/target_term.h"

namespace devsurf::solver {

int TargetTerm::addTarget(int column, double target) {
    changed();
    m_column.push_back(column);
    m_target.push_back(target);
    return rowCount() - 1;
}

int TargetTerm::addPointTarget(int offset, int dimension, const double* target) {
    const int first = rowCount();
    for (int k = 0; k < dimension; ++k) {
        addTarget(offset + k, target[k]);
    }
    return first;
}

void TargetTerm::buildPattern(PatternBuilder& builder) const {
    for (int column : m_column) {
        builder.beginRow();
        builder.addColumn(column);
    }
}

void TargetTerm::evaluate(const double* x, double* residuals, double* jacobian) const {
    for (std::size_t r = 0; r < m_column.size(); ++r) {
        residuals[r] = x[m_column[r]] - m_target[r];
        jacobian[r] = 1.0;
    }
}

bool TargetTerm::evaluateRow(int row, const double* x, double* residual, double* jacobian) const {
    const auto r = static_cast<std::size_t>(row);
    *residual = x[m_column[r]] - m_target[r];
    jacobian[0] = 1.0;
    return true;
}

} // namespace devsurf::solver
