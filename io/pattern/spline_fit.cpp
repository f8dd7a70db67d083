#include "spline_fit.h"

#include <algorithm>
#include <cmath>

namespace devsurf::io {

using model::Vec2;

namespace {

double pointSegmentDistance(const Vec2& p, const Vec2& a, const Vec2& b) {
    const Vec2 ab = b - a;
    const double length2 = dot2(ab, ab);
    const double t = length2 > 0.0 ? std::clamp(dot2(p - a, ab) / length2, 0.0, 1.0) : 0.0;
    return (p - (a + ab * t)).norm();
}

double polylineDistance(const Vec2& p, const std::vector<Vec2>& line) {
    double best = (p - line.front()).norm();
    for (std::size_t i = 0; i + 1 < line.size(); ++i) {
        best = std::min(best, pointSegmentDistance(p, line[i], line[i + 1]));
    }
    return best;
}

Vec2 bezier(const Vec2* c, double t) {
    const double s = 1.0 - t;
    return c[0] * (s * s * s) + c[1] * (3.0 * s * s * t) + c[2] * (3.0 * s * t * t) +
           c[3] * (t * t * t);
}

class Fitter {
public:
    Fitter(std::vector<Vec2> points, bool closed, double tolerance)
        : m_p(std::move(points)), m_closed(closed), m_tolerance(tolerance) {
        m_t.resize(m_p.size(), 0.0);
        for (std::size_t i = 1; i < m_p.size(); ++i) {
            m_t[i] = m_t[i - 1] + (m_p[i] - m_p[i - 1]).norm();
        }
    }

    CubicSpline fit() {
        const int n = static_cast<int>(m_p.size());
        std::vector<int> breaks{0};
        for (int i = 1; i + 1 < n; ++i) {
            if (isCorner(i)) {
                breaks.push_back(i);
            }
        }
        breaks.push_back(n - 1);
        m_spline.controlPoints.push_back(m_p.front());
        for (std::size_t k = 0; k + 1 < breaks.size(); ++k) {
            m_runBegin = breaks[k];
            m_runEnd = breaks[k + 1];
            fitRange(m_runBegin, m_runEnd);
        }
        const int m = m_spline.segments();
        m_spline.knots.assign(4, 0.0);
        for (int i = 1; i < m; ++i) {
            m_spline.knots.insert(m_spline.knots.end(), 3, double(i));
        }
        m_spline.knots.insert(m_spline.knots.end(), 4, double(m));
        return m_spline;
    }

private:
    bool isCorner(int i) const {
        const Vec2 a = m_p[i] - m_p[i - 1];
        const Vec2 b = m_p[i + 1] - m_p[i];
        const double la = a.norm();
        const double lb = b.norm();
        if (la == 0.0 || lb == 0.0) {
            return true;
        }
        return dot2(a, b) / (la * lb) < std::cos(30.0 * M_PI / 180.0);
    }

    // Derivative with respect to arc length at point i inside the current run (one-sided at
    // the run's ends, across the seam of a closed curve without a corner there).
    Vec2 tangent(int i) const {
        const int n = static_cast<int>(m_p.size());
        const bool seam = m_closed && n > 3 && (i == 0 || i == n - 1) && !seamIsCorner();
        if (seam) {
            const Vec2 d = m_p[1] - m_p[n - 2];
            const double h = (m_t[1] - m_t[0]) + (m_t[n - 1] - m_t[n - 2]);
            return d * (1.0 / h);
        }
        int a = i - 1;
        int b = i + 1;
        if (i == m_runBegin) {
            a = i;
        }
        if (i == m_runEnd) {
            b = i;
        }
        const double h = m_t[b] - m_t[a];
        return h > 0.0 ? (m_p[b] - m_p[a]) * (1.0 / h) : Vec2{};
    }

    bool seamIsCorner() const {
        const int n = static_cast<int>(m_p.size());
        const Vec2 a = m_p[n - 1] - m_p[n - 2];
        const Vec2 b = m_p[1] - m_p[0];
        const double la = a.norm();
        const double lb = b.norm();
        return la == 0.0 || lb == 0.0 || dot2(a, b) / (la * lb) < std::cos(30.0 * M_PI / 180.0);
    }

    bool withinTolerance(const Vec2* c, int a, int b) const {
        constexpr int kSamples = 48;
        std::vector<Vec2> curve(kSamples + 1);
        for (int s = 0; s <= kSamples; ++s) {
            curve[s] = bezier(c, double(s) / kSamples);
        }
        // Half the tolerance each way leaves room for the sampling of the Bézier itself.
        const double limit = 0.5 * m_tolerance;
        for (int k = a; k <= b; ++k) {
            if (polylineDistance(m_p[k], curve) > limit) {
                return false;
            }
        }
        const std::vector<Vec2> line(m_p.begin() + a, m_p.begin() + b + 1);
        for (const Vec2& q : curve) {
            if (polylineDistance(q, line) > limit) {
                return false;
            }
        }
        return true;
    }

    void fitRange(int a, int b) {
        const double h = m_t[b] - m_t[a];
        Vec2 c[4] = {m_p[a], m_p[a] + tangent(a) * (h / 3.0), m_p[b] - tangent(b) * (h / 3.0),
                     m_p[b]};
        if (!withinTolerance(c, a, b)) {
            if (b - a >= 2) {
                const int mid = (a + b) / 2;
                fitRange(a, mid);
                fitRange(mid, b);
                return;
            }
            // Two neighbouring samples: the chord itself, exactly the polyline.
            c[1] = m_p[a] + (m_p[b] - m_p[a]) * (1.0 / 3.0);
            c[2] = m_p[a] + (m_p[b] - m_p[a]) * (2.0 / 3.0);
        }
        m_spline.controlPoints.push_back(c[1]);
        m_spline.controlPoints.push_back(c[2]);
        m_spline.controlPoints.push_back(c[3]);
    }

    std::vector<Vec2> m_p;
    std::vector<double> m_t;
    bool m_closed;
    double m_tolerance;
    int m_runBegin = 0;
    int m_runEnd = 0;
    CubicSpline m_spline;
};

} // namespace

CubicSpline fitCubicSpline(const std::vector<Vec2>& points, bool closed, double tolerance) {
    std::vector<Vec2> p;
    for (const Vec2& q : points) {
        if (p.empty() || !(q == p.back())) {
            p.push_back(q);
        }
    }
    if (closed && p.size() > 1 && !(p.front() == p.back())) {
        p.push_back(p.front());
    }
    if (p.size() < 2) {
        return {};
    }
    return Fitter(std::move(p), closed, tolerance).fit();
}

Vec2 splinePoint(const CubicSpline& spline, int segment, double t) {
    return bezier(&spline.controlPoints[static_cast<std::size_t>(3 * segment)], t);
}

} // namespace devsurf::io
