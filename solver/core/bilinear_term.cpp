#include "solver/core/bilinear_term.h"

#include "solver/core/row_scales.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace devsurf::solver {

BilinearTerm::BilinearTerm(int dimension) : m_dimension(dimension) {
    if (dimension < 1 || dimension > kMaxDimension) {
        throw std::invalid_argument("BilinearTerm: dimension out of range");
    }
}

int BilinearTerm::addRow(const PointCombination& left, const PointCombination& right,
                         double target) {
    changed();
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

void BilinearTerm::sides(std::size_t r, const double* x, double* u, double* v) const {
    const int d = m_dimension;
    std::fill(u, u + d, 0.0);
    std::fill(v, v + d, 0.0);
    for (int e = m_leftStart[r]; e < m_rightStart[r]; ++e) {
        const PointTerm& p = m_points[static_cast<std::size_t>(e)];
        for (int k = 0; k < d; ++k) {
            u[k] += p.coefficient * x[p.offset + k];
        }
    }
    for (int e = m_rightStart[r]; e < m_leftStart[r + 1]; ++e) {
        const PointTerm& p = m_points[static_cast<std::size_t>(e)];
        for (int k = 0; k < d; ++k) {
            v[k] += p.coefficient * x[p.offset + k];
        }
    }
}

void BilinearTerm::scaleRowsAt(const double* reference) {
    changed();
    m_scale.clear();
    if (!reference) {
        return;
    }
    m_scale.resize(m_target.size());
    for (std::size_t r = 0; r < m_target.size(); ++r) {
        std::array<double, kMaxDimension> u{};
        std::array<double, kMaxDimension> v{};
        sides(r, reference, u.data(), v.data());
        double uu = 0.0;
        double vv = 0.0;
        for (int k = 0; k < m_dimension; ++k) {
            uu += u[k] * u[k];
            vv += v[k] * v[k];
        }
        const double product = std::sqrt(uu * vv);
        m_scale[r] = product > 0.0 && std::isfinite(1.0 / product) ? 1.0 / product : 0.0;
    }
    clampScalesToMedian(m_scale);
}

int BilinearTerm::evaluateOne(std::size_t r, const double* x, double* residual,
                              double* jacobian) const {
    return m_dimension == 3 ? evaluateOneOf<3>(r, x, residual, jacobian)
                            : evaluateOneOf<0>(r, x, residual, jacobian);
}

template <int D>
int BilinearTerm::evaluateOneOf(std::size_t r, const double* x, double* residual,
                                double* jacobian) const {
    const int d = D > 0 ? D : m_dimension;
    std::array<double, kMaxDimension> u{};
    std::array<double, kMaxDimension> v{};
    const int middle = m_rightStart[r];
    const int end = m_leftStart[r + 1];
    for (int e = m_leftStart[r]; e < middle; ++e) {
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
    const double scale = m_scale.empty() ? 1.0 : m_scale[r];
    double value = -m_target[r];
    for (int k = 0; k < d; ++k) {
        value += u[k] * v[k];
    }
    *residual = scale * value;
    // ∂/∂nₖ = s dₖ v, ∂/∂pᵢ = s cᵢ u.
    double* out = jacobian;
    for (int e = m_leftStart[r]; e < middle; ++e) {
        const double c = scale * m_points[static_cast<std::size_t>(e)].coefficient;
        for (int k = 0; k < d; ++k) {
            *out++ = c * v[k];
        }
    }
    for (int e = middle; e < end; ++e) {
        const double c = scale * m_points[static_cast<std::size_t>(e)].coefficient;
        for (int k = 0; k < d; ++k) {
            *out++ = c * u[k];
        }
    }
    return static_cast<int>(out - jacobian);
}

double BilinearTerm::rowResidual(int row, const double* x) const {
    const auto r = static_cast<std::size_t>(row);
    std::vector<double> jacobian(
        static_cast<std::size_t>((m_leftStart[r + 1] - m_leftStart[r]) * m_dimension));
    double residual = 0.0;
    evaluateOne(r, x, &residual, jacobian.data());
    return residual;
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
