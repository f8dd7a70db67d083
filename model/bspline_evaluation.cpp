// BSplineCurve's evaluation: points, derivatives and de Boor rows (construction and editing
// are in bspline_curve.cpp).
#include "bspline_curve.h"
#include "bspline_support.h"

#include <array>
#include <vector>

namespace devsurf::model {

using namespace bspline_support;

Vec3* BSplineCurve::spanPoints(int j, std::array<Vec3, 16>& onStack,
                               std::vector<Vec3>& onHeap) const {
    const int m = m_degree;
    Vec3* d = onStack.data();
    if (idx(m + 1) > onStack.size()) {
        onHeap.resize(idx(m + 1));
        d = onHeap.data();
    }
    for (int i = 0; i <= m; ++i) {
        d[idx(i)] = controlAt(j - m + i);
    }
    return d;
}

Vec3 BSplineCurve::evaluate(double u) const {
    return derivative(u, 0);
}

Vec3 BSplineCurve::derivative(double u, int order) const {
    if (order < 0) {
        fail("Derivative order must not be negative.");
    }
    const int j = locate(u);
    const int m = m_degree;
    if (order > m) {
        return {};
    }
    std::array<Vec3, 16> onStack;
    std::vector<Vec3> onHeap;
    Vec3* d = spanPoints(j, onStack, onHeap);
    // Control points of the derivative curve, restricted to the span.
    for (int r = 1; r <= order; ++r) {
        const int p = m - r + 1;
        for (int i = m; i >= r; --i) {
            const int l = j - m + i;
            d[idx(i)] = (d[idx(i)] - d[idx(i - 1)]) *
                        (static_cast<double>(p) / (m_knots[idx(l + p)] - m_knots[idx(l)]));
        }
    }
    const int q = m - order;
    for (int r = 1; r <= q; ++r) {
        for (int i = m; i >= order + r; --i) {
            const int l = j - m + i;
            const double a =
                (u - m_knots[idx(l)]) / (m_knots[idx(l + m - order - r + 1)] - m_knots[idx(l)]);
            d[idx(i)] = d[idx(i - 1)] * (1.0 - a) + d[idx(i)] * a;
        }
    }
    return d[idx(m)];
}

void BSplineCurve::pointAndTangent(double u, Vec3& point, Vec3& tangent) const {
    const int j = locate(u);
    const int m = m_degree;
    std::array<Vec3, 16> onStack;
    std::vector<Vec3> onHeap;
    Vec3* d = spanPoints(j, onStack, onHeap);
    // Rounds 1 … m − 1 of de Boor; the last two points span the tangent, the last round
    // gives the point.
    for (int r = 1; r < m; ++r) {
        for (int i = m; i >= r; --i) {
            const int l = j - m + i;
            const double a =
                (u - m_knots[idx(l)]) / (m_knots[idx(l + m - r + 1)] - m_knots[idx(l)]);
            d[idx(i)] = d[idx(i - 1)] * (1.0 - a) + d[idx(i)] * a;
        }
    }
    const double h = m_knots[idx(j + 1)] - m_knots[idx(j)];
    tangent = (d[idx(m)] - d[idx(m - 1)]) * (static_cast<double>(m) / h);
    const double a = (u - m_knots[idx(j)]) / h;
    point = d[idx(m - 1)] * (1.0 - a) + d[idx(m)] * a;
}

DeBoorRows BSplineCurve::deBoorRows(double u) const {
    const int j = locate(u);
    const int m = m_degree;
    const std::size_t w = idx(m + 1);
    DeBoorRows rows;
    rows.span = j;
    rows.parameter = u;
    rows.indices.resize(w);
    for (int i = 0; i <= m; ++i) {
        const int l = j - m + i;
        rows.indices[idx(i)] = m_closed ? wrapIndex(l, controlCount()) : l;
    }
    // Row i holds the coefficients of the current de Boor point d_i over the span's m+1
    // control points.
    std::vector<double> c(w * w, 0.0);
    for (std::size_t i = 0; i < w; ++i) {
        c[i * w + i] = 1.0;
    }
    const auto row = [&](int i) {
        const auto start = c.begin() + static_cast<std::ptrdiff_t>(idx(i) * w);
        return std::vector<double>(start, start + static_cast<std::ptrdiff_t>(w));
    };
    const auto snapshot = [&](int round) {
        if (round == m - 1) {
            rows.firstDerivative[0] = row(m - 1);
            rows.firstDerivative[1] = row(m);
        }
        if (round == m - 2) {
            for (int k = 0; k < 3; ++k) {
                rows.secondDerivative[k] = row(m - 2 + k);
            }
        }
    };
    snapshot(0);
    for (int r = 1; r <= m; ++r) {
        for (int i = m; i >= r; --i) {
            const int l = j - m + i;
            const double a =
                (u - m_knots[idx(l)]) / (m_knots[idx(l + m - r + 1)] - m_knots[idx(l)]);
            for (std::size_t k = 0; k < w; ++k) {
                c[idx(i) * w + k] = (1.0 - a) * c[idx(i - 1) * w + k] + a * c[idx(i) * w + k];
            }
        }
        snapshot(r);
    }
    rows.point = row(m);

    const double h = m_knots[idx(j + 1)] - m_knots[idx(j)];
    rows.firstDerivativeScale = m / h;
    if (m >= 2) {
        // a'' = m(m-1) times the blossom at (u,...,u, δ, δ), written in the three round-(m-2)
        // points, whose blossom arguments are (t_{j-1},t_j), (t_j,t_{j+1}), (t_{j+1},t_{j+2}).
        const double s = m * (m - 1) / h;
        const double w0 = s / (m_knots[idx(j + 1)] - m_knots[idx(j - 1)]);
        const double w2 = s / (m_knots[idx(j + 2)] - m_knots[idx(j)]);
        rows.secondDerivativeWeights[0] = w0;
        rows.secondDerivativeWeights[1] = -(w0 + w2);
        rows.secondDerivativeWeights[2] = w2;
    }
    return rows;
}

DeBoorPoints BSplineCurve::deBoorPoints(double u) const {
    const DeBoorRows rows = deBoorRows(u);
    const auto combine = [&](const std::vector<double>& coefficients) {
        Vec3 sum;
        for (std::size_t i = 0; i < coefficients.size(); ++i) {
            sum += m_controlPoints[idx(rows.indices[i])] * coefficients[i];
        }
        return sum;
    };
    DeBoorPoints points;
    points.point = combine(rows.point);
    points.firstDerivativePoints[0] = combine(rows.firstDerivative[0]);
    points.firstDerivativePoints[1] = combine(rows.firstDerivative[1]);
    points.hasSecondDerivativePoints = m_degree >= 2;
    if (points.hasSecondDerivativePoints) {
        for (int k = 0; k < 3; ++k) {
            points.secondDerivativePoints[k] = combine(rows.secondDerivative[k]);
            points.secondDerivativeWeights[k] = rows.secondDerivativeWeights[k];
        }
    }
    points.firstDerivativeScale = rows.firstDerivativeScale;
    return points;
}

} // namespace devsurf::model
