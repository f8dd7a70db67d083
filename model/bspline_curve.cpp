#include "bspline_curve.h"
#include "bspline_support.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <stdexcept>
#include <string>

namespace devsurf::model {
namespace {

using namespace bspline_support;

// Parameters this close to a knot (relative to the domain length) are taken to be the knot:
// inserting a knot a rounding error away from an existing one would create a degenerate span.
constexpr double kSnapTolerance = 1e-12;
// Closed knot vectors from outside (files, other programs) are periodic only up to rounding.
constexpr double kPeriodicTolerance = 1e-10;

std::string num(double value) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.17g", value);
    return buffer;
}

int floorDiv(int a, int b) {
    return a >= 0 ? a / b : -((-a + b - 1) / b);
}

void checkKnots(int m, const std::vector<double>& t) {
    for (double x : t) {
        if (!std::isfinite(x)) {
            fail("B-spline knots must be finite numbers.");
        }
    }
    int run = 1;
    for (std::size_t i = 1; i < t.size(); ++i) {
        if (t[i] < t[i - 1]) {
            fail("B-spline knots must be non-decreasing (knot " + std::to_string(i) + " is " +
                 num(t[i]) + ", after " + num(t[i - 1]) + ").");
        }
        run = t[i] == t[i - 1] ? run + 1 : 1;
        if (run > m + 1) {
            // A basis function over an empty interval would vanish identically.
            fail("A B-spline knot may be repeated at most degree + 1 = " + std::to_string(m + 1) +
                 " times (knot " + num(t[i]) + ").");
        }
    }
}

int multiplicity(const std::vector<double>& t, double u) {
    const auto range = std::equal_range(t.begin(), t.end(), u);
    return static_cast<int>(range.second - range.first);
}

// One step of Boehm's algorithm on an open knot vector. The caller guarantees that u lies in
// the domain and that its multiplicity stays at most m. Returns the index of the new knot.
int insertOnce(int m, std::vector<double>& t, std::vector<Vec3>& p, double u) {
    const int j = static_cast<int>(std::upper_bound(t.begin(), t.end(), u) - t.begin()) - 1;
    int s = 0;
    while (j - s >= 0 && t[idx(j - s)] == u) {
        ++s;
    }
    const int n = static_cast<int>(p.size());
    std::vector<Vec3> q(idx(n + 1));
    for (int i = 0; i <= n; ++i) {
        if (i <= j - m) {
            q[idx(i)] = p[idx(i)];
        } else if (i <= j - s) {
            const double a = (u - t[idx(i)]) / (t[idx(i + m)] - t[idx(i)]);
            q[idx(i)] = p[idx(i - 1)] * (1.0 - a) + p[idx(i)] * a;
        } else {
            q[idx(i)] = p[idx(i - 1)];
        }
    }
    t.insert(t.begin() + (j + 1), u);
    p = std::move(q);
    return j + 1;
}

} // namespace

BSplineCurve::BSplineCurve(int degree, std::vector<double> knots, std::vector<Vec3> controlPoints,
                           bool closed) {
    if (degree < 1) {
        fail("B-spline degree must be at least 1 (got " + std::to_string(degree) + ").");
    }
    for (const Vec3& p : controlPoints) {
        if (!p.isFinite()) {
            fail("B-spline control points must have finite coordinates.");
        }
    }
    const int m = degree;
    const std::size_t mm = idx(m);
    const std::string counts = std::to_string(controlPoints.size()) + " control points and " +
                               std::to_string(knots.size()) + " knots";
    if (!closed) {
        if (controlPoints.size() < mm + 1) {
            fail("An open B-spline curve of degree " + std::to_string(m) + " needs at least " +
                 std::to_string(m + 1) + " control points (got " +
                 std::to_string(controlPoints.size()) + ").");
        }
        if (knots.size() != controlPoints.size() + mm + 1) {
            fail("An open B-spline curve of degree " + std::to_string(m) +
                 " needs (control points + degree + 1) knots; got " + counts + ".");
        }
        checkKnots(m, knots);
        if (!(knots[mm] < knots[controlPoints.size()])) {
            fail("The B-spline knot vector leaves an empty parameter domain.");
        }
        m_degree = m;
        m_closed = false;
        m_knots = std::move(knots);
        m_controlPoints = std::move(controlPoints);
        return;
    }

    std::size_t n = 0;
    if (knots.size() == controlPoints.size() + 2 * mm + 1) {
        n = controlPoints.size();
    } else if (knots.size() == controlPoints.size() + mm + 1 && controlPoints.size() > mm) {
        n = controlPoints.size() - mm;
        double scale = 0.0;
        for (const Vec3& p : controlPoints) {
            scale = std::max({scale, std::abs(p.x), std::abs(p.y), std::abs(p.z)});
        }
        for (std::size_t i = 0; i < mm; ++i) {
            if ((controlPoints[n + i] - controlPoints[i]).norm() > kPeriodicTolerance * scale) {
                fail("In the interchange form of a closed B-spline curve the last " +
                     std::to_string(m) + " control points must repeat the first ones.");
            }
        }
        controlPoints.resize(n);
    } else {
        fail("A closed B-spline curve of degree " + std::to_string(m) +
             " with N control points needs N + 2*degree + 1 knots (or, with the first degree "
             "control points repeated at the end, control points + degree + 1); got " +
             counts + ".");
    }
    if (n < 1) {
        fail("A closed B-spline curve needs at least one control point.");
    }
    checkKnots(m, knots);
    const double period = knots[mm + n] - knots[mm];
    if (!(period > 0.0)) {
        fail("The closed B-spline knot vector has an empty period.");
    }
    const double tolerance =
        kPeriodicTolerance * std::max({period, std::abs(knots.front()), std::abs(knots.back())});
    for (std::size_t i = 0; i <= 2 * mm; ++i) {
        if (std::abs(knots[i + n] - knots[i] - period) > tolerance) {
            fail("The knot vector of a closed B-spline curve must be periodic (t[i+N] - t[i] "
                 "must equal the period " +
                 num(period) + " for every i; fails at i = " + std::to_string(i) + ").");
        }
    }
    m_degree = m;
    m_closed = true;
    std::vector<double> base(knots.begin() + static_cast<std::ptrdiff_t>(mm),
                             knots.begin() + static_cast<std::ptrdiff_t>(mm + n));
    setClosedCanonical(std::move(base), period, std::move(controlPoints), tolerance);
}

BSplineCurve BSplineCurve::uniform(const SplineSpace& space, std::vector<Vec3> controlPoints,
                                   bool closed) {
    if (!space.isValid()) {
        fail("Invalid spline space: " + space.technicalKey() + ".");
    }
    const int count = space.controlPointCount(closed);
    if (controlPoints.size() != idx(count)) {
        fail("A" + std::string(closed ? " closed" : "n open") + " curve in the spline space " +
             space.technicalKey() + " needs " + std::to_string(count) + " control points, got " +
             std::to_string(controlPoints.size()) + ".");
    }
    return BSplineCurve(space.degree, space.knots(closed), std::move(controlPoints), closed);
}

void BSplineCurve::setClosedCanonical(std::vector<double> base, double period,
                                      std::vector<Vec3> points, double tolerance) {
    const int m = m_degree;
    const int n = static_cast<int>(base.size());
    const double begin = base.front();
    // Base knots that are copies of the next period's start belong in front: that keeps t_m
    // the first knot at the domain start, so all copies of a parameter sit in one period.
    int c = 0;
    while (c < n - 1 && base[idx(n - 1 - c)] >= begin + period - tolerance) {
        ++c;
    }
    std::vector<double> rotated(idx(n));
    for (int i = 0; i < n; ++i) {
        rotated[idx(i)] = i < c ? begin : base[idx(i - c)];
    }
    m_controlPoints.resize(idx(n));
    for (int i = 0; i < n; ++i) {
        m_controlPoints[idx(i)] = points[idx(wrapIndex(i - c, n))];
    }
    m_period = period;
    m_knots.resize(idx(n + 2 * m + 1));
    for (int i = 0; i <= n + 2 * m; ++i) {
        const int q = i - m;
        const int p = floorDiv(q, n);
        // Same expression as SplineSpace::knots and knotAt(), so copies agree bit for bit.
        m_knots[idx(i)] = rotated[idx(q - p * n)] + static_cast<double>(p) * period;
    }
}

double BSplineCurve::knotAt(int i) const {
    if (!m_closed) {
        return m_knots[idx(i)];
    }
    const int n = controlCount();
    const int q = i - m_degree;
    const int p = floorDiv(q, n);
    return m_knots[idx(m_degree + q - p * n)] + static_cast<double>(p) * m_period;
}

double BSplineCurve::domainBegin() const {
    return isEmpty() ? 0.0 : m_knots[idx(m_degree)];
}

double BSplineCurve::domainEnd() const {
    if (isEmpty()) {
        return 0.0;
    }
    return m_knots[idx(controlCount() + (m_closed ? m_degree : 0))];
}

const Vec3& BSplineCurve::controlAt(int i) const {
    return m_controlPoints[idx(m_closed ? wrapIndex(i, controlCount()) : i)];
}

void BSplineCurve::requireNonEmpty() const {
    if (isEmpty()) {
        throw std::logic_error("The B-spline curve is empty.");
    }
}

double BSplineCurve::snapToKnot(double u) const {
    const double tolerance = kSnapTolerance * (domainEnd() - domainBegin());
    const auto it = std::lower_bound(m_knots.begin(), m_knots.end(), u);
    if (it != m_knots.end() && *it - u <= tolerance) {
        return *it;
    }
    if (it != m_knots.begin() && u - *(it - 1) <= tolerance) {
        return *(it - 1);
    }
    return u;
}

double BSplineCurve::reduceClosed(double u, bool snap) const {
    const double begin = domainBegin();
    const double end = domainEnd();
    if (u >= begin && u < end && !snap) {
        return u;
    }
    if (u < begin || u >= end) {
        double w = std::fmod(u - begin, m_period);
        if (w < 0.0) {
            w += m_period;
        }
        u = begin + w;
    }
    // Reduction modulo the period loses the exact knot value that the caller may have meant.
    u = snapToKnot(u);
    return u >= end ? begin : u;
}

int BSplineCurve::locate(double& u) const {
    requireNonEmpty();
    if (!std::isfinite(u)) {
        fail("B-spline parameter must be a finite number.");
    }
    const int m = m_degree;
    int last = controlCount();
    if (m_closed) {
        last += m;
        u = reduceClosed(u, false);
    } else {
        u = std::clamp(u, m_knots[idx(m)], m_knots[idx(last)]);
    }
    const auto first = m_knots.begin() + (m + 1);
    const auto stop = m_knots.begin() + last;
    int j = static_cast<int>(std::upper_bound(first, stop, u) - m_knots.begin()) - 1;
    // Only at the domain end can the span found be empty; use the last non-empty one.
    while (j > m && m_knots[idx(j)] == m_knots[idx(j + 1)]) {
        --j;
    }
    return j;
}

void BSplineCurve::insertKnot(double u, int times) {
    requireNonEmpty();
    if (times < 0) {
        fail("A knot cannot be inserted a negative number of times.");
    }
    if (!std::isfinite(u)) {
        fail("B-spline parameter must be a finite number.");
    }
    if (times == 0) {
        return;
    }
    if (m_closed) {
        insertKnotClosed(u, times);
    } else {
        insertKnotOpen(u, times);
    }
}

void BSplineCurve::checkInsertion(double u, int existing, int times) const {
    if (existing + times > m_degree) {
        fail("Cannot insert the knot " + num(u) + " " + std::to_string(times) +
             " time(s): it already has multiplicity " + std::to_string(existing) +
             " and the multiplicity may not exceed the degree " + std::to_string(m_degree) + ".");
    }
}

void BSplineCurve::insertKnotOpen(double u, int times) {
    const double begin = domainBegin();
    const double end = domainEnd();
    const double tolerance = kSnapTolerance * (end - begin);
    if (u < begin - tolerance || u > end + tolerance) {
        fail("Cannot insert the knot " + num(u) + " outside the curve's domain [" + num(begin) +
             ", " + num(end) + "].");
    }
    u = snapToKnot(std::clamp(u, begin, end));
    checkInsertion(u, multiplicity(m_knots, u), times);
    for (int r = 0; r < times; ++r) {
        insertOnce(m_degree, m_knots, m_controlPoints, u);
    }
}

void BSplineCurve::insertKnotClosed(double u, int times) {
    const int m = m_degree;
    const int n = controlCount();
    u = reduceClosed(u, true);
    const auto baseBegin = m_knots.begin() + m;
    const auto baseEnd = baseBegin + n;
    const auto range = std::equal_range(baseBegin, baseEnd, u);
    checkInsertion(u, static_cast<int>(range.second - range.first), times);

    // Insert every periodic copy into an unrolled open curve several periods long, then read
    // one period off its middle. Boehm's algorithm is local, so the middle is exactly the
    // periodic result, even when a period has fewer than m knots and copies interact.
    const int periods = (2 * m + 2) / n + 2;
    const int offset = periods * n;
    std::vector<double> knots;
    for (int i = -offset; i <= n + 2 * m + offset; ++i) {
        knots.push_back(knotAt(i));
    }
    std::vector<Vec3> points;
    for (int i = -offset; i < n + m + offset; ++i) {
        points.push_back(controlAt(i));
    }
    int start = m + offset; // index of the domain start knot in the unrolled sequence
    for (int r = 0; r < times; ++r) {
        for (int k = -(periods + 1); k <= periods + 1; ++k) {
            const double v = u + static_cast<double>(k) * m_period;
            if (!(v > knots[idx(m)] && v < knots[points.size()])) {
                continue; // near the ends of the unrolled curve, far from the period we keep
            }
            if (insertOnce(m, knots, points, v) <= start) {
                ++start;
            }
        }
    }
    const int count = n + times;
    std::vector<double> base(knots.begin() + start, knots.begin() + (start + count));
    std::vector<Vec3> newPoints(points.begin() + (start - m), points.begin() + (start - m + count));
    setClosedCanonical(std::move(base), m_period, std::move(newPoints), 0.0);
}

std::pair<BSplineCurve, BSplineCurve> BSplineCurve::split(double u) const {
    requireNonEmpty();
    if (m_closed) {
        fail("Only open curves can be split; open a closed curve first.");
    }
    const double begin = domainBegin();
    const double end = domainEnd();
    const double tolerance = kSnapTolerance * (end - begin);
    if (!std::isfinite(u) || !(u > begin + tolerance && u < end - tolerance)) {
        fail("The split parameter " + num(u) + " must lie strictly inside the domain [" +
             num(begin) + ", " + num(end) + "].");
    }
    const int m = m_degree;
    BSplineCurve c = *this;
    u = c.snapToKnot(u);
    const int s = multiplicity(c.m_knots, u);
    if (s < m) {
        c.insertKnot(u, m - s);
    }
    const auto& t = c.m_knots;
    const auto& p = c.m_controlPoints;
    const int a = static_cast<int>(std::lower_bound(t.begin(), t.end(), u) - t.begin());
    const int g = multiplicity(t, u);

    std::vector<double> leftKnots(t.begin(), t.begin() + a);
    leftKnots.insert(leftKnots.end(), idx(m + 1), u);
    std::vector<Vec3> leftPoints(p.begin(), p.begin() + a);

    std::vector<double> rightKnots(idx(m + 1), u);
    rightKnots.insert(rightKnots.end(), t.begin() + (a + g), t.end());
    std::vector<Vec3> rightPoints(p.begin() + (a + g - 1 - m), p.end());

    return {BSplineCurve(m, std::move(leftKnots), std::move(leftPoints), false).clamped(),
            BSplineCurve(m, std::move(rightKnots), std::move(rightPoints), false).clamped()};
}

BSplineCurve BSplineCurve::clamped() const {
    requireNonEmpty();
    if (m_closed) {
        fail("A closed curve cannot be clamped; use openedAt().");
    }
    const int m = m_degree;
    BSplineCurve c = *this;

    const double begin = c.domainBegin();
    const int sb = multiplicity(c.m_knots, begin);
    if (sb < m) {
        c.insertKnot(begin, m - sb);
    }
    // With multiplicity >= m at the start, the curve starts at control point g1 - m.
    const int g1 = static_cast<int>(std::upper_bound(c.m_knots.begin(), c.m_knots.end(), begin) -
                                    c.m_knots.begin()) -
                   1;
    const int drop = g1 - m;
    std::vector<double> knots(c.m_knots.begin() + drop, c.m_knots.end());
    std::vector<Vec3> points(c.m_controlPoints.begin() + drop, c.m_controlPoints.end());
    knots.front() = begin;
    c = BSplineCurve(m, std::move(knots), std::move(points), false);

    const double end = c.domainEnd();
    const int se = multiplicity(c.m_knots, end);
    if (se < m) {
        c.insertKnot(end, m - se);
    }
    const int h0 = static_cast<int>(std::lower_bound(c.m_knots.begin(), c.m_knots.end(), end) -
                                    c.m_knots.begin());
    knots.assign(c.m_knots.begin(), c.m_knots.begin() + (h0 + m + 1));
    points.assign(c.m_controlPoints.begin(), c.m_controlPoints.begin() + h0);
    knots.back() = end;
    return BSplineCurve(m, std::move(knots), std::move(points), false);
}

BSplineCurve BSplineCurve::openedAt(double u) const {
    requireNonEmpty();
    if (!m_closed) {
        fail("Only a closed curve can be opened.");
    }
    if (!std::isfinite(u)) {
        fail("B-spline parameter must be a finite number.");
    }
    const int m = m_degree;
    const double w = reduceClosed(u, true);
    BSplineCurve c = *this;
    {
        const auto range =
            std::equal_range(c.m_knots.begin() + m, c.m_knots.begin() + (m + controlCount()), w);
        const int s = static_cast<int>(range.second - range.first);
        if (s < m) {
            c.insertKnot(w, m - s);
        }
    }
    const int n = c.controlCount();
    const auto baseBegin = c.m_knots.begin() + m;
    const auto range = std::equal_range(baseBegin, baseBegin + n, w);
    const int a = static_cast<int>(range.first - c.m_knots.begin());
    const int g = static_cast<int>(range.second - range.first);

    // Keep the parameters the caller asked for, not their reduction into the base period.
    const double shift = u - w;
    const double first = u;
    const double last = u + m_period;
    std::vector<double> knots(idx(m + 1), first);
    for (int i = a + g; i < a + n; ++i) {
        knots.push_back(std::clamp(c.knotAt(i) + shift, first, last));
    }
    knots.insert(knots.end(), idx(m + 1), last);
    std::vector<Vec3> points;
    for (int i = a + g - 1 - m; i <= a + n - 1; ++i) {
        points.push_back(c.controlAt(i));
    }
    return BSplineCurve(m, std::move(knots), std::move(points), false);
}

BSplineCurve BSplineCurve::reversed() const {
    requireNonEmpty();
    const int m = m_degree;
    const double begin = domainBegin();
    const double end = domainEnd();
    // Exact at the ends so the domain maps onto itself bit for bit.
    const auto reflect = [&](double t) {
        if (t == end) {
            return begin;
        }
        if (t == begin) {
            return end;
        }
        const double r = (begin + end) - t;
        return t >= begin && t <= end ? std::clamp(r, begin, end) : r;
    };
    if (!m_closed) {
        std::vector<double> knots(m_knots.size());
        for (std::size_t i = 0; i < knots.size(); ++i) {
            knots[i] = reflect(m_knots[m_knots.size() - 1 - i]);
            if (i > 0) {
                knots[i] = std::max(knots[i], knots[i - 1]);
            }
        }
        std::vector<Vec3> points(m_controlPoints.rbegin(), m_controlPoints.rend());
        return BSplineCurve(m, std::move(knots), std::move(points), false);
    }
    const int n = controlCount();
    std::vector<double> base(idx(n));
    std::vector<Vec3> points(idx(n));
    for (int i = 0; i < n; ++i) {
        base[idx(i)] = reflect(m_knots[idx(n + m - i)]);
        if (i > 0) {
            base[idx(i)] = std::max(base[idx(i)], base[idx(i - 1)]);
        }
        // Basis function i, supported on [t_i, t_{i+m+1}], reflects onto basis N + m - 1 - i.
        points[idx(i)] = controlAt(n + m - 1 - i);
    }
    BSplineCurve result;
    result.m_degree = m;
    result.m_closed = true;
    result.setClosedCanonical(std::move(base), m_period, std::move(points), 0.0);
    return result;
}

std::vector<double> BSplineCurve::exportKnots() const {
    return m_knots;
}

std::vector<Vec3> BSplineCurve::exportControlPoints() const {
    if (!m_closed) {
        return m_controlPoints;
    }
    std::vector<Vec3> points;
    points.reserve(m_controlPoints.size() + idx(m_degree));
    for (int i = 0; i < controlCount() + m_degree; ++i) {
        points.push_back(controlAt(i));
    }
    return points;
}

} // namespace devsurf::model
