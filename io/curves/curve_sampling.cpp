#include "curve_sampling.h"

#include <algorithm>
#include <cmath>

namespace devsurf::io {

using model::Vec3;

namespace {

double distanceToSegment(const Vec3& p, const Vec3& a, const Vec3& b) {
    const Vec3 d = b - a;
    const double length2 = d.x * d.x + d.y * d.y + d.z * d.z;
    const Vec3 ap = p - a;
    double s = length2 > 0.0 ? (ap.x * d.x + ap.y * d.y + ap.z * d.z) / length2 : 0.0;
    s = std::clamp(s, 0.0, 1.0);
    const Vec3 e = p - (a + d * s);
    return std::sqrt(e.x * e.x + e.y * e.y + e.z * e.z);
}

// Bisects [t0, t1] until the middle of every piece is within tolerance of its chord (and at
// least twice, so that an S-shaped span whose middle lies on the chord is still followed).
class Sampler {
public:
    Sampler(const Nurbs& curve, double tolerance, std::size_t maxPoints)
        : m_curve(curve), m_tolerance(tolerance), m_maxPoints(maxPoints) {}

    bool span(double t0, const Vec3& p0, double t1, const Vec3& p1, int depth) {
        const double tm = 0.5 * (t0 + t1);
        const Vec3 pm = nurbsPoint(m_curve, tm);
        if (!pm.isFinite()) {
            return false;
        }
        if (depth < 2 || (depth < 24 && distanceToSegment(pm, p0, p1) > m_tolerance)) {
            return span(t0, p0, tm, pm, depth + 1) && span(tm, pm, t1, p1, depth + 1);
        }
        points.push_back(p1);
        return points.size() <= m_maxPoints;
    }

    std::vector<Vec3> points;

private:
    const Nurbs& m_curve;
    double m_tolerance;
    std::size_t m_maxPoints;
};

} // namespace

bool isValidNurbs(const Nurbs& curve) {
    const std::size_t n = curve.controlPoints.size();
    if (curve.degree < 1 || curve.degree > 15 || n < static_cast<std::size_t>(curve.degree) + 1 ||
        curve.knots.size() != n + static_cast<std::size_t>(curve.degree) + 1) {
        return false;
    }
    if (!curve.weights.empty() && curve.weights.size() != n) {
        return false;
    }
    for (std::size_t i = 0; i < curve.knots.size(); ++i) {
        if (!std::isfinite(curve.knots[i]) || (i > 0 && curve.knots[i] < curve.knots[i - 1])) {
            return false;
        }
    }
    for (std::size_t i = 0; i < n; ++i) {
        if (!curve.controlPoints[i].isFinite() ||
            (!curve.weights.empty() &&
             !(curve.weights[i] > 0.0 && std::isfinite(curve.weights[i])))) {
            return false;
        }
    }
    const double start = curve.knots[static_cast<std::size_t>(curve.degree)];
    const double end = curve.knots[n];
    return end > start && std::isfinite(end - start);
}

Vec3 nurbsPoint(const Nurbs& curve, double t) {
    const int p = curve.degree;
    const int n = static_cast<int>(curve.controlPoints.size());
    const std::vector<double>& u = curve.knots;
    t = std::clamp(t, u[static_cast<std::size_t>(p)], u[static_cast<std::size_t>(n)]);
    // The span k with u[k] <= t < u[k+1], the last non-empty one at the end of the range.
    int k = p;
    while (k < n - 1 && t >= u[static_cast<std::size_t>(k) + 1]) {
        ++k;
    }
    struct H {
        double x, y, z, w;
    };
    std::vector<H> d(static_cast<std::size_t>(p) + 1);
    for (int j = 0; j <= p; ++j) {
        const std::size_t i = static_cast<std::size_t>(k - p + j);
        const double w = curve.weights.empty() ? 1.0 : curve.weights[i];
        const Vec3& c = curve.controlPoints[i];
        d[static_cast<std::size_t>(j)] = {c.x * w, c.y * w, c.z * w, w};
    }
    for (int r = 1; r <= p; ++r) {
        for (int j = p; j >= r; --j) {
            const double left = u[static_cast<std::size_t>(k - p + j)];
            const double right = u[static_cast<std::size_t>(k + 1 + j - r)];
            const double alpha = right > left ? (t - left) / (right - left) : 0.0;
            H& a = d[static_cast<std::size_t>(j)];
            const H& b = d[static_cast<std::size_t>(j) - 1];
            a = {(1 - alpha) * b.x + alpha * a.x, (1 - alpha) * b.y + alpha * a.y,
                 (1 - alpha) * b.z + alpha * a.z, (1 - alpha) * b.w + alpha * a.w};
        }
    }
    const H& h = d[static_cast<std::size_t>(p)];
    return {h.x / h.w, h.y / h.w, h.z / h.w};
}

std::optional<std::vector<Vec3>> sampleNurbs(const Nurbs& curve, double tolerance,
                                             std::size_t maxPoints) {
    if (!isValidNurbs(curve) || !(tolerance > 0.0)) {
        return std::nullopt;
    }
    Sampler sampler(curve, tolerance, maxPoints);
    const std::size_t n = curve.controlPoints.size();
    double t0 = curve.knots[static_cast<std::size_t>(curve.degree)];
    Vec3 p0 = nurbsPoint(curve, t0);
    if (!p0.isFinite()) {
        return std::nullopt;
    }
    sampler.points.push_back(p0);
    for (std::size_t k = static_cast<std::size_t>(curve.degree); k < n; ++k) {
        const double t1 = curve.knots[k + 1];
        if (t1 <= t0) {
            continue;
        }
        const Vec3 p1 = nurbsPoint(curve, t1);
        if (!p1.isFinite() || !sampler.span(t0, p0, t1, p1, 0)) {
            return std::nullopt;
        }
        t0 = t1;
        p0 = p1;
    }
    return std::move(sampler.points);
}

std::vector<Vec3> sampleArc(const Vec3& center, double radius, const Vec3& u, const Vec3& v,
                            double a0, double a1, double tolerance) {
    const double sweep = a1 - a0;
    // A chord of angle 2·acos(1 - tolerance / radius) strays by exactly tolerance.
    const double ratio = std::clamp(1.0 - tolerance / radius, -1.0, 1.0);
    const double step = std::max(2.0 * std::acos(ratio), 1e-3);
    const int segments =
        std::clamp(static_cast<int>(std::ceil(sweep / step)),
                   std::max(1, static_cast<int>(std::ceil(sweep / (M_PI / 4)))), 100'000);
    std::vector<Vec3> points;
    points.reserve(static_cast<std::size_t>(segments) + 1);
    for (int i = 0; i <= segments; ++i) {
        const double a = a0 + sweep * i / segments;
        points.push_back(center + u * (radius * std::cos(a)) + v * (radius * std::sin(a)));
    }
    return points;
}

} // namespace devsurf::io
