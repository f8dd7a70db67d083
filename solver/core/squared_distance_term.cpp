#include "solver/core/squared_distance_term.h"

#include <array>
#include <cmath>
#include <stdexcept>

namespace devsurf::solver {

SquaredDistanceTerm::SquaredDistanceTerm(int leftDimension, int rightDimension)
    : m_leftDimension(leftDimension), m_rightDimension(rightDimension) {
    if (leftDimension < 1 || leftDimension > kMaxDimension || rightDimension < 1 ||
        rightDimension > kMaxDimension) {
        throw std::invalid_argument("SquaredDistanceTerm: dimension out of range");
    }
}

int SquaredDistanceTerm::addRow(const PointCombination& left, const PointCombination& right,
                                double squaredDistance) {
    changed();
    m_points.insert(m_points.end(), left.begin(), left.end());
    m_rightStart.push_back(static_cast<int>(m_points.size()));
    m_points.insert(m_points.end(), right.begin(), right.end());
    m_leftStart.push_back(static_cast<int>(m_points.size()));
    m_squaredDistance.push_back(squaredDistance);
    m_rowScale.push_back(1.0);
    return rowCount() - 1;
}

void SquaredDistanceTerm::buildPattern(PatternBuilder& builder) const {
    for (std::size_t r = 0; r < m_squaredDistance.size(); ++r) {
        builder.beginRow();
        for (int e = m_leftStart[r]; e < m_rightStart[r]; ++e) {
            builder.addColumns(m_points[static_cast<std::size_t>(e)].offset, m_leftDimension);
        }
        for (int e = m_rightStart[r]; e < m_leftStart[r + 1]; ++e) {
            builder.addColumns(m_points[static_cast<std::size_t>(e)].offset, m_rightDimension);
        }
    }
}

double SquaredDistanceTerm::leftLength(int row, const double* x) const {
    const auto r = static_cast<std::size_t>(row);
    std::array<double, kMaxDimension> a{};
    for (int e = m_leftStart[r]; e < m_rightStart[r]; ++e) {
        const PointTerm& p = m_points[static_cast<std::size_t>(e)];
        for (int k = 0; k < m_leftDimension; ++k) {
            a[k] += p.coefficient * x[p.offset + k];
        }
    }
    double squared = 0.0;
    for (int k = 0; k < m_leftDimension; ++k) {
        squared += a[k] * a[k];
    }
    return std::sqrt(squared);
}

int SquaredDistanceTerm::evaluateOne(std::size_t r, const double* x, double* residual,
                                     double* jacobian) const {
    std::array<double, kMaxDimension> a{};
    std::array<double, kMaxDimension> b{};
    const int begin = m_leftStart[r];
    const int middle = m_rightStart[r];
    const int end = m_leftStart[r + 1];
    for (int e = begin; e < middle; ++e) {
        const PointTerm& p = m_points[static_cast<std::size_t>(e)];
        for (int k = 0; k < m_leftDimension; ++k) {
            a[k] += p.coefficient * x[p.offset + k];
        }
    }
    for (int e = middle; e < end; ++e) {
        const PointTerm& p = m_points[static_cast<std::size_t>(e)];
        for (int k = 0; k < m_rightDimension; ++k) {
            b[k] += p.coefficient * x[p.offset + k];
        }
    }
    double value = -m_squaredDistance[r];
    for (int k = 0; k < m_leftDimension; ++k) {
        value += a[k] * a[k];
    }
    for (int k = 0; k < m_rightDimension; ++k) {
        value -= b[k] * b[k];
    }
    const double scale = m_rowScale[r];
    *residual = scale * value;
    double* out = jacobian;
    for (int e = begin; e < middle; ++e) {
        const double c = 2.0 * scale * m_points[static_cast<std::size_t>(e)].coefficient;
        for (int k = 0; k < m_leftDimension; ++k) {
            *out++ = c * a[k];
        }
    }
    for (int e = middle; e < end; ++e) {
        const double c = -2.0 * scale * m_points[static_cast<std::size_t>(e)].coefficient;
        for (int k = 0; k < m_rightDimension; ++k) {
            *out++ = c * b[k];
        }
    }
    return static_cast<int>(out - jacobian);
}

void SquaredDistanceTerm::evaluate(const double* x, double* residuals, double* jacobian) const {
    for (std::size_t r = 0; r < m_squaredDistance.size(); ++r) {
        jacobian += evaluateOne(r, x, residuals + r, jacobian);
    }
}

bool SquaredDistanceTerm::evaluateRow(int row, const double* x, double* residual,
                                      double* jacobian) const {
    evaluateOne(static_cast<std::size_t>(row), x, residual, jacobian);
    return true;
}

} // namespace devsurf::solver
