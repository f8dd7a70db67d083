#include "solver/core/bilinear_term.h"

#include <array>
#include <stdexcept>

namespace devsurf::solver {

BilinearTerm::BilinearTerm(int dimension) : m_dimension(dimension) {
    if (dimension < 1 || dimension > kMaxDimension) {
        throw std::invalid_argument("BilinearTerm: dimension out of range");
    }
}

int BilinearTerm::addRow(const PointCombination& left, const PointCombination& right,
                         double target) {
    m_points.insert(m_points.end(), left.begin(), left.end());
    m_rightStart.push_back(static_cast<int>(m_points.size()));
    m_points.insert(m_points.end(), right.begin(), right.end());
    m_leftStart.push_back(static_cast<int>(m_points.size()));
    m_target.push_back(target);
    return rowCount() - 1;
}

void BilinearTerm::buildPattern(PatternBuilder& builder) const {
    for (std::size_t r = 0; r < m_target.size(); ++r) {
        builder.beginRow();
        for (int e = m_leftStart[r]; e < m_leftStart[r + 1]; ++e) {
            builder.addColumns(m_points[static_cast<std::size_t>(e)].offset, m_dimension);
        }
    }
}

int BilinearTerm::evaluateOne(std::size_t r, const double* x, double* residual,
                              double* jacobian) const {
    const int d = m_dimension;
    std::array<double, kMaxDimension> u{};
    std::array<double, kMaxDimension> v{};
    const int begin = m_leftStart[r];
    const int middle = m_rightStart[r];
    const int end = m_leftStart[r + 1];
    for (int e = begin; e < middle; ++e) {
        const PointTerm& p = m_points[static_cast<std::size_t>(e)];
        for (int k = 0; k < d; ++k) {
            u[k] += p.coefficient * x[p.offset + k];
        }
    }
    for (int e = middle; e < end; ++e) {
        const PointTerm& p = m_points[static_cast<std::size_t>(e)];
        for (int k = 0; k < d; ++k) {
            v[k] += p.coefficient * x[p.offset + k];
        }
    }
    double value = -m_target[r];
    for (int k = 0; k < d; ++k) {
        value += u[k] * v[k];
    }
    *residual = value;
    // ∂/∂nₖ = dₖ v, ∂/∂pᵢ = cᵢ u.
    double* out = jacobian;
    for (int e = begin; e < middle; ++e) {
        const double c = m_points[static_cast<std::size_t>(e)].coefficient;
        for (int k = 0; k < d; ++k) {
            *out++ = c * v[k];
        }
    }
    for (int e = middle; e < end; ++e) {
        const double c = m_points[static_cast<std::size_t>(e)].coefficient;
        for (int k = 0; k < d; ++k) {
            *out++ = c * u[k];
        }
    }
    return static_cast<int>(out - jacobian);
}

void BilinearTerm::evaluate(const double* x, double* residuals, double* jacobian) const {
    for (std::size_t r = 0; r < m_target.size(); ++r) {
        jacobian += evaluateOne(r, x, residuals + r, jacobian);
    }
}

bool BilinearTerm::evaluateRow(int row, const double* x, double* residual, double* jacobian) const {
    evaluateOne(static_cast<std::size_t>(row), x, residual, jacobian);
    return true;
}

} // namespace devsurf::solver
