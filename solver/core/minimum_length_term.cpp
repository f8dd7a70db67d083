#include "solver/core/minimum_length_term.h"

#include <array>
#include <cmath>
#include <stdexcept>

namespace devsurf::solver {

MinimumLengthTerm::MinimumLengthTerm(int dimension) : m_dimension(dimension) {
    if (dimension < 1 || dimension > kMaxDimension) {
        throw std::invalid_argument("MinimumLengthTerm: dimension out of range");
    }
}

int MinimumLengthTerm::addRow(const PointCombination& combination, double minimum) {
    changed();
    m_points.insert(m_points.end(), combination.begin(), combination.end());
    m_start.push_back(static_cast<int>(m_points.size()));
    m_minimum.push_back(minimum);
    return rowCount() - 1;
}

void MinimumLengthTerm::buildPattern(PatternBuilder& builder) const {
    for (std::size_t r = 0; r < m_minimum.size(); ++r) {
        builder.beginRow();
        for (int e = m_start[r]; e < m_start[r + 1]; ++e) {
            builder.addColumns(m_points[static_cast<std::size_t>(e)].offset, m_dimension);
        }
    }
}

double MinimumLengthTerm::length(int row, const double* x) const {
    std::array<double, kMaxDimension> v{};
    const auto r = static_cast<std::size_t>(row);
    for (int e = m_start[r]; e < m_start[r + 1]; ++e) {
        const PointTerm& p = m_points[static_cast<std::size_t>(e)];
        for (int k = 0; k < m_dimension; ++k) {
            v[k] += p.coefficient * x[p.offset + k];
        }
    }
    double squared = 0.0;
    for (int k = 0; k < m_dimension; ++k) {
        squared += v[k] * v[k];
    }
    return std::sqrt(squared);
}

int MinimumLengthTerm::evaluateOne(std::size_t r, const double* x, double* residual,
                                   double* jacobian) const {
    std::array<double, kMaxDimension> v{};
    for (int e = m_start[r]; e < m_start[r + 1]; ++e) {
        const PointTerm& p = m_points[static_cast<std::size_t>(e)];
        for (int k = 0; k < m_dimension; ++k) {
            v[k] += p.coefficient * x[p.offset + k];
        }
    }
    double squared = 0.0;
    for (int k = 0; k < m_dimension; ++k) {
        squared += v[k] * v[k];
    }
    const double length = std::sqrt(squared);
    const double minimum = m_minimum[r];
    const bool engaged = !m_engaged.empty() && m_engaged[r] != 0;
    const bool active = minimum > 0.0 && (length < minimum || engaged);
    *residual = active ? 1.0 - length / minimum : 0.0;
    // ∂/∂pᵢ = −cᵢ v / (|v| L) while active (a zero-length side has no direction: zero row).
    const double factor = active && length > 0.0 ? -1.0 / (length * minimum) : 0.0;
    double* out = jacobian;
    for (int e = m_start[r]; e < m_start[r + 1]; ++e) {
        const double c = m_points[static_cast<std::size_t>(e)].coefficient;
        for (int k = 0; k < m_dimension; ++k) {
            *out++ = factor * c * v[k];
        }
    }
    return static_cast<int>(out - jacobian);
}

void MinimumLengthTerm::evaluate(const double* x, double* residuals, double* jacobian) const {
    for (std::size_t r = 0; r < m_minimum.size(); ++r) {
        jacobian += evaluateOne(r, x, residuals + r, jacobian);
    }
}

bool MinimumLengthTerm::evaluateRow(int row, const double* x, double* residual,
                                    double* jacobian) const {
    evaluateOne(static_cast<std::size_t>(row), x, residual, jacobian);
    return true;
}

MinimumLengthTerm::Products MinimumLengthTerm::rowProducts(std::size_t r, const double* x,
                                                           const double* step) const {
    std::array<double, kMaxDimension> u{};
    std::array<double, kMaxDimension> w{};
    for (int e = m_start[r]; e < m_start[r + 1]; ++e) {
        const PointTerm& p = m_points[static_cast<std::size_t>(e)];
        for (int k = 0; k < m_dimension; ++k) {
            u[k] += p.coefficient * x[p.offset + k];
            w[k] += p.coefficient * step[p.offset + k];
        }
    }
    Products products;
    for (int k = 0; k < m_dimension; ++k) {
        products.uu += u[k] * u[k];
        products.uw += u[k] * w[k];
        products.ww += w[k] * w[k];
    }
    return products;
}

int MinimumLengthTerm::engageCrossedGuards(const double* x, const double* step) const {
    int engaged = 0;
    for (std::size_t r = 0; r < m_minimum.size(); ++r) {
        const double minimum = m_minimum[r];
        if (minimum <= 0.0 || (!m_engaged.empty() && m_engaged[r] != 0)) {
            continue;
        }
        const auto [uu, uw, ww] = rowProducts(r, x, step);
        const double after = uu + 2.0 * uw + ww; // |u + w|²
        if (uu >= minimum * minimum && after < minimum * minimum) {
            if (m_engaged.empty()) {
                m_engaged.assign(m_minimum.size(), 0);
            }
            m_engaged[r] = 1;
            ++engaged;
        }
    }
    if (engaged > 0) {
        changed();
    }
    return engaged;
}

void MinimumLengthTerm::releaseGuards() const {
    if (!m_engaged.empty()) {
        m_engaged.clear();
        changed();
    }
}

double MinimumLengthTerm::admissibleStep(const double* x, const double* step, double keep) const {
    double alpha = 1.0;
    for (std::size_t r = 0; r < m_minimum.size(); ++r) {
        if (m_minimum[r] <= 0.0) {
            continue;
        }
        const auto [uu, uw, ww] = rowProducts(r, x, step);
        // q(α) = |u + αw|² − keep²|u|² = ww α² + 2 uw α + c, positive at α = 0: its first
        // root in (0, 1], if the length falls that far anywhere on the step (a ruling pushed
        // through zero to the other side ends long again, but has collapsed on the way).
        const double c = (1.0 - keep * keep) * uu;
        if (ww <= 0.0 || uw >= 0.0) {
            continue; // not shrinking
        }
        const double lowest = std::min(1.0, -uw / ww);
        if (ww * lowest * lowest + 2.0 * uw * lowest + c >= 0.0) {
            continue;
        }
        const double discriminant = std::max(0.0, uw * uw - ww * c);
        const double root = (-uw - std::sqrt(discriminant)) / ww;
        if (root > 0.0) {
            alpha = std::min(alpha, root);
        }
    }
    return alpha;
}

} // namespace devsurf::solver
