#include "solver/core/bisector_term.h"

#include "solver/core/row_scales.h"

#include <algorithm>
#include <cmath>

namespace devsurf::solver {

namespace {

double dot3(const double* a, const double* b) {
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

double norm3(const double* a) {
    return std::sqrt(dot3(a, a));
}

} // namespace

int BisectorTerm::addRow(const PointCombination& n, const PointCombination& m,
                         const PointCombination& d) {
    changed();
    m_points.insert(m_points.end(), n.begin(), n.end());
    m_mStart.push_back(static_cast<int>(m_points.size()));
    m_points.insert(m_points.end(), m.begin(), m.end());
    m_dStart.push_back(static_cast<int>(m_points.size()));
    m_points.insert(m_points.end(), d.begin(), d.end());
    m_rowStart.push_back(static_cast<int>(m_points.size()));
    m_nWeight.push_back(1.0);
    m_mWeight.push_back(1.0);
    return rowCount() - 1;
}

void BisectorTerm::buildPattern(PatternBuilder& builder) const {
    for (std::size_t r = 0; r + 1 < m_rowStart.size(); ++r) {
        builder.beginRow();
        for (int e = m_rowStart[r]; e < m_rowStart[r + 1]; ++e) {
            builder.addColumns(m_points[static_cast<std::size_t>(e)].offset, 3);
        }
    }
}

BisectorTerm::Sides BisectorTerm::sides(std::size_t r, const double* x) const {
    Sides s{};
    auto accumulate = [&](int begin, int end, double* out) {
        for (int e = begin; e < end; ++e) {
            const PointTerm& p = m_points[static_cast<std::size_t>(e)];
            for (int k = 0; k < 3; ++k) {
                out[k] += p.coefficient * x[p.offset + k];
            }
        }
    };
    accumulate(m_rowStart[r], m_mStart[r], s.n);
    accumulate(m_mStart[r], m_dStart[r], s.m);
    accumulate(m_dStart[r], m_rowStart[r + 1], s.d);
    return s;
}

void BisectorTerm::bisector(std::size_t r, const Sides& s, double* out) const {
    for (int k = 0; k < 3; ++k) {
        out[k] = m_nWeight[r] * s.n[k] + m_mWeight[r] * s.m[k];
    }
}

void BisectorTerm::weighSidesAt(const double* x) {
    changed();
    for (std::size_t r = 0; r < m_mStart.size(); ++r) {
        const Sides s = sides(r, x);
        const double n = norm3(s.n);
        const double m = norm3(s.m);
        const bool usable = n > 0.0 && m > 0.0 && std::isfinite(n + m);
        m_nWeight[r] = usable ? 2.0 * m / (n + m) : 1.0;
        m_mWeight[r] = usable ? 2.0 * n / (n + m) : 1.0;
    }
}

void BisectorTerm::scaleRowsAt(const double* reference) {
    changed();
    m_scale.clear();
    if (!reference) {
        return;
    }
    const std::size_t rows = m_mStart.size();
    m_scale.resize(rows);
    for (std::size_t r = 0; r < rows; ++r) {
        const Sides s = sides(r, reference);
        double b[3];
        bisector(r, s, b);
        const double product = norm3(b) * norm3(s.d);
        m_scale[r] = product > 0.0 && std::isfinite(1.0 / product) ? 1.0 / product : 0.0;
    }
    clampScalesToMedian(m_scale);
}

int BisectorTerm::evaluateOne(std::size_t r, const double* x, double* residual,
                              double* jacobian) const {
    const Sides s = sides(r, x);
    const double scale = m_scale.empty() ? 1.0 : m_scale[r];
    double b[3];
    bisector(r, s, b);
    *residual = scale * dot3(s.d, b);
    // ∂/∂n = w_n d, ∂/∂m = w_m d, ∂/∂d = w_n n + w_m m.
    double* out = jacobian;
    auto write = [&](int begin, int end, double weight, const double* gradient) {
        for (int e = begin; e < end; ++e) {
            const double c = scale * weight * m_points[static_cast<std::size_t>(e)].coefficient;
            for (int k = 0; k < 3; ++k) {
                *out++ = c * gradient[k];
            }
        }
    };
    write(m_rowStart[r], m_mStart[r], m_nWeight[r], s.d);
    write(m_mStart[r], m_dStart[r], m_mWeight[r], s.d);
    write(m_dStart[r], m_rowStart[r + 1], 1.0, b);
    return static_cast<int>(out - jacobian);
}

double BisectorTerm::rowResidual(int row, const double* x) const {
    // The residual of evaluateOne without its Jacobian.
    const auto r = static_cast<std::size_t>(row);
    const Sides s = sides(r, x);
    double b[3];
    bisector(r, s, b);
    return (m_scale.empty() ? 1.0 : m_scale[r]) * dot3(s.d, b);
}

void BisectorTerm::evaluate(const double* x, double* residuals, double* jacobian) const {
    for (std::size_t r = 0; r < m_mStart.size(); ++r) {
        jacobian += evaluateOne(r, x, residuals + r, jacobian);
    }
}

bool BisectorTerm::evaluateRow(int row, const double* x, double* residual, double* jacobian) const {
    evaluateOne(static_cast<std::size_t>(row), x, residual, jacobian);
    return true;
}

} // namespace devsurf::solver
