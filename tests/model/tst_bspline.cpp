#include "bspline_curve.h"
#include "spline_space.h"
#include "test_registry.h"

#include <QObject>
#include <QTest>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <random>
#include <stdexcept>
#include <vector>

using devsurf::model::BSplineCurve;
using devsurf::model::DeBoorPoints;
using devsurf::model::DeBoorRows;
using devsurf::model::SplineSpace;
using devsurf::model::Vec3;

namespace {

// Returns from the calling test function when a helper has recorded a failure.
#define RUN_CHECK(call)                                                                            \
    do {                                                                                           \
        call;                                                                                      \
        if (QTest::currentTestFailed())                                                            \
            return;                                                                                \
    } while (false)

struct Case {
    BSplineCurve curve;
    QByteArray name;
    int degree = 0;
    int smoothness = 0;
    int intervals = 0;
    bool closed = false;
    double diameter = 0.0; // of the control polygon; the geometric scale
};

std::vector<Vec3> randomPoints(std::mt19937& rng, int count, double scale) {
    std::uniform_real_distribution<double> coordinate(-scale, scale);
    std::vector<Vec3> points;
    for (int i = 0; i < count; ++i) {
        const double x = coordinate(rng);
        const double y = coordinate(rng);
        points.emplace_back(x, y, coordinate(rng));
    }
    return points;
}

double diameterOf(const std::vector<Vec3>& points) {
    Vec3 lo = points.front();
    Vec3 hi = points.front();
    for (const Vec3& p : points) {
        for (int c = 0; c < 3; ++c) {
            lo[c] = std::min(lo[c], p[c]);
            hi[c] = std::max(hi[c], p[c]);
        }
    }
    // A single point (closed curves with one control point) still has a scale.
    double largest = 0.0;
    for (int c = 0; c < 3; ++c) {
        largest = std::max({largest, std::abs(lo[c]), std::abs(hi[c])});
    }
    return std::max((hi - lo).norm(), largest);
}

// Every uniform space with degree 1..5, every smoothness, several interval counts, open and
// closed. geometryScale scales the control points, parameterScale the parameter domain
// (those curves go through the general constructor).
std::vector<Case> sweep(double geometryScale = 1.0, double parameterScale = 1.0,
                        unsigned seed = 12345) {
    std::mt19937 rng(seed);
    std::vector<Case> cases;
    for (int m = 1; m <= 5; ++m) {
        for (int k = 0; k < m; ++k) {
            for (int n : {1, 2, 3, 5}) {
                for (bool closed : {false, true}) {
                    const SplineSpace space{m, k, n};
                    Case c;
                    c.degree = m;
                    c.smoothness = k;
                    c.intervals = n;
                    c.closed = closed;
                    auto points = randomPoints(rng, space.controlPointCount(closed), geometryScale);
                    c.diameter = diameterOf(points);
                    if (parameterScale == 1.0) {
                        c.curve = BSplineCurve::uniform(space, points, closed);
                    } else {
                        auto knots = space.knots(closed);
                        for (double& t : knots) {
                            t *= parameterScale;
                        }
                        c.curve = BSplineCurve(m, knots, points, closed);
                    }
                    c.name = QByteArray("m=") + QByteArray::number(m) +
                             " k=" + QByteArray::number(k) + " n=" + QByteArray::number(n) +
                             (closed ? " closed" : " open");
                    cases.push_back(std::move(c));
                }
            }
        }
    }
    return cases;
}

std::vector<double> distinctDomainKnots(const BSplineCurve& curve) {
    std::vector<double> values;
    for (double t : curve.knots()) {
        if (t >= curve.domainBegin() && t <= curve.domainEnd() &&
            (values.empty() || values.back() != t)) {
            values.push_back(t);
        }
    }
    return values;
}

// Parameters including every knot, both ends and random values.
std::vector<double> sampleParameters(const BSplineCurve& curve, std::mt19937& rng,
                                     int randomCount = 25) {
    std::vector<double> u = distinctDomainKnots(curve);
    std::uniform_real_distribution<double> in(curve.domainBegin(), curve.domainEnd());
    for (int i = 0; i < randomCount; ++i) {
        u.push_back(in(rng));
    }
    return u;
}

// Sample parameters strictly inside each non-empty span, away from its ends.
std::vector<std::pair<double, double>> spans(const BSplineCurve& curve) {
    std::vector<std::pair<double, double>> result;
    const auto knots = distinctDomainKnots(curve);
    for (std::size_t i = 0; i + 1 < knots.size(); ++i) {
        result.emplace_back(knots[i], knots[i + 1]);
    }
    return result;
}

double maxDeviation(const BSplineCurve& a, const BSplineCurve& b,
                    const std::vector<double>& parameters) {
    double worst = 0.0;
    for (double u : parameters) {
        worst = std::max(worst, (a.evaluate(u) - b.evaluate(u)).norm());
    }
    return worst;
}

std::vector<double> uniformSamples(double begin, double end, int count) {
    std::vector<double> u;
    for (int i = 0; i <= count; ++i) {
        u.push_back(begin + (end - begin) * i / count);
    }
    return u;
}

QByteArray describe(const Case& c, double u) {
    return c.name + " u=" + QByteArray::number(u, 'g', 17);
}

// Independent reference: Cox–de Boor recursion on an explicit knot vector, half-open spans.
double basis(const std::vector<double>& t, int i, int p, double u) {
    if (p == 0) {
        return t[i] <= u && u < t[i + 1] ? 1.0 : 0.0;
    }
    double value = 0.0;
    if (t[i + p] > t[i]) {
        value += (u - t[i]) / (t[i + p] - t[i]) * basis(t, i, p - 1, u);
    }
    if (t[i + p + 1] > t[i + 1]) {
        value += (t[i + p + 1] - u) / (t[i + p + 1] - t[i + 1]) * basis(t, i + 1, p - 1, u);
    }
    return value;
}

// Σ P_{i mod N} N_i(u) over knots.size() - m - 1 basis functions.
Vec3 coxDeBoor(int m, const std::vector<double>& knots, const std::vector<Vec3>& points, double u) {
    Vec3 sum;
    const int count = static_cast<int>(knots.size()) - m - 1;
    const int n = static_cast<int>(points.size());
    for (int i = 0; i < count; ++i) {
        sum += points[i % n] * basis(knots, i, m, u);
    }
    return sum;
}

// Periodic knot sequence t_0..t_{N+2m} from the knots of one period, built independently of
// the library.
std::vector<double> periodicKnots(int m, const std::vector<double>& base, double period) {
    const int n = static_cast<int>(base.size());
    std::vector<double> t;
    for (int i = 0; i <= n + 2 * m; ++i) {
        const int q = i - m;
        const int p = static_cast<int>(std::floor(static_cast<double>(q) / n));
        t.push_back(base[q - p * n] + p * period);
    }
    return t;
}

// ---------------------------------------------------------------------------------------------

void checkRows(const Case& c, std::mt19937& rng) {
    const BSplineCurve& curve = c.curve;
    const int m = c.degree;
    const int count = static_cast<int>(curve.controlPoints().size());
    auto parameters = sampleParameters(curve, rng);
    // Slightly outside: clamped (open) or wrapped (closed).
    const double length = curve.domainEnd() - curve.domainBegin();
    parameters.push_back(curve.domainBegin() - 1e-14 * length);
    parameters.push_back(curve.domainEnd() + 1e-14 * length);
    for (double u : parameters) {
        const DeBoorRows rows = curve.deBoorRows(u);
        QVERIFY2(rows.indices.size() == std::size_t(m + 1), describe(c, u));
        for (int i : rows.indices) {
            QVERIFY2(i >= 0 && i < count, describe(c, u));
        }
        std::vector<const std::vector<double>*> all{&rows.point, &rows.firstDerivative[0],
                                                    &rows.firstDerivative[1]};
        if (m >= 2) {
            for (const auto& r : rows.secondDerivative) {
                all.push_back(&r);
            }
        } else {
            for (const auto& r : rows.secondDerivative) {
                QVERIFY2(r.empty(), describe(c, u));
            }
        }
        for (const auto* r : all) {
            QVERIFY2(r->size() == std::size_t(m + 1), describe(c, u));
            double sum = 0.0;
            for (double x : *r) {
                sum += x;
            }
            QVERIFY2(std::abs(sum - 1.0) < 1e-12,
                     describe(c, u) + " sum " + QByteArray::number(sum, 'g', 17));
        }
        Vec3 viaRows;
        for (int i = 0; i <= m; ++i) {
            viaRows += curve.controlPoints()[rows.indices[i]] * rows.point[i];
        }
        const Vec3 direct = curve.evaluate(u);
        QVERIFY2((viaRows - direct).norm() <= 1e-12 * c.diameter, describe(c, u));

        // deBoorPoints must be the same combinations.
        const DeBoorPoints points = curve.deBoorPoints(u);
        QVERIFY2((points.point - direct).norm() <= 1e-12 * c.diameter, describe(c, u));
        QCOMPARE(points.hasSecondDerivativePoints, m >= 2);
        QCOMPARE(points.firstDerivativeScale, rows.firstDerivativeScale);
        for (int a = 0; a < 2; ++a) {
            Vec3 p;
            for (int i = 0; i <= m; ++i) {
                p += curve.controlPoints()[rows.indices[i]] * rows.firstDerivative[a][i];
            }
            QVERIFY2((p - points.firstDerivativePoints[a]).norm() <= 1e-12 * c.diameter,
                     describe(c, u));
        }
        if (m == 1) {
            // The two control points of the span.
            QCOMPARE(points.firstDerivativePoints[0], curve.controlPoints()[rows.indices[0]]);
            QCOMPARE(points.firstDerivativePoints[1], curve.controlPoints()[rows.indices[1]]);
        }
        if (m == 2) {
            for (int a = 0; a < 3; ++a) {
                QCOMPARE(points.secondDerivativePoints[a], curve.controlPoints()[rows.indices[a]]);
            }
        }
    }
}

void checkDerivatives(const Case& c) {
    const BSplineCurve& curve = c.curve;
    const int m = c.degree;
    for (const auto& [a, b] : spans(curve)) {
        const double length = b - a;
        for (double fraction : {0.2, 0.5, 0.8}) {
            const double u = a + fraction * length;
            const DeBoorPoints points = curve.deBoorPoints(u);
            const Vec3 d1 = points.firstDerivative();
            const double ref1 = std::max(d1.norm(), c.diameter / length);

            const double h1 = 1e-5 * length;
            const Vec3 fd1 = (curve.evaluate(u + h1) - curve.evaluate(u - h1)) / (2 * h1);
            QVERIFY2((fd1 - d1).norm() <= 1e-6 * ref1,
                     describe(c, u) + " first " + QByteArray::number((fd1 - d1).norm() / ref1));
            QVERIFY2((curve.derivative(u, 1) - d1).norm() <= 1e-10 * ref1, describe(c, u));
            Vec3 point;
            Vec3 tangent;
            curve.pointAndTangent(u, point, tangent);
            QVERIFY2((point - curve.evaluate(u)).norm() <= 1e-12 * c.diameter, describe(c, u));
            QVERIFY2((tangent - d1).norm() <= 1e-10 * ref1, describe(c, u));

            const Vec3 d2 = points.secondDerivative();
            const double ref2 = std::max(d2.norm(), c.diameter / (length * length));
            const Vec3 fd2 = (curve.deBoorPoints(u + h1).firstDerivative() -
                              curve.deBoorPoints(u - h1).firstDerivative()) /
                             (2 * h1);
            QVERIFY2((fd2 - d2).norm() <= 1e-6 * ref2,
                     describe(c, u) + " second " + QByteArray::number((fd2 - d2).norm() / ref2));
            QVERIFY2((curve.derivative(u, 2) - d2).norm() <= 1e-10 * ref2, describe(c, u));
            if (m == 1) {
                QCOMPARE(d2, Vec3());
            }
            const double sumWeights = points.secondDerivativeWeights[0] +
                                      points.secondDerivativeWeights[1] +
                                      points.secondDerivativeWeights[2];
            QVERIFY(std::abs(sumWeights) <=
                    1e-12 * std::abs(points.secondDerivativeWeights[1]) + 1e-300);

            // Higher orders: finite differences of the next lower order; zero beyond m.
            for (int order = 3; order <= m; ++order) {
                const Vec3 exact = curve.derivative(u, order);
                const double ref = std::max(exact.norm(), c.diameter / std::pow(length, order));
                const Vec3 fd =
                    (curve.derivative(u + h1, order - 1) - curve.derivative(u - h1, order - 1)) /
                    (2 * h1);
                QVERIFY2((fd - exact).norm() <= 1e-6 * ref, describe(c, u));
            }
            QCOMPARE(curve.derivative(u, m + 1), Vec3());
            QVERIFY2((curve.derivative(u, 0) - curve.evaluate(u)).norm() == 0.0, describe(c, u));
        }
    }
    // pointAndTangent at the knots and the domain ends takes the same span as derivative().
    for (const double u : distinctDomainKnots(curve)) {
        Vec3 point;
        Vec3 tangent;
        curve.pointAndTangent(u, point, tangent);
        const Vec3 d1 = curve.derivative(u, 1);
        QVERIFY2((point - curve.evaluate(u)).norm() <= 1e-12 * c.diameter, describe(c, u));
        QVERIFY2((tangent - d1).norm() <= 1e-10 * std::max(d1.norm(), c.diameter), describe(c, u));
    }
}

// C^k across every breakpoint (for closed curves also across the seam); a generic jump in
// derivative k+1.
void checkSmoothness(const Case& c) {
    const BSplineCurve& curve = c.curve;
    const int m = c.degree;
    const int k = c.smoothness;
    const double length = (curve.domainEnd() - curve.domainBegin()) / c.intervals;
    std::vector<double> breakpoints;
    for (double t : distinctDomainKnots(curve)) {
        const bool interior = t > curve.domainBegin() && t < curve.domainEnd();
        if (interior || (c.closed && t == curve.domainBegin())) {
            breakpoints.push_back(t);
        }
    }
    double largestJump = 0.0;
    for (double t : breakpoints) {
        const double delta = 1e-10 * length;
        for (int order = 0; order <= std::min(k + 1, m); ++order) {
            const double ref = c.diameter / std::pow(length, order);
            const double jump =
                (curve.derivative(t + delta, order) - curve.derivative(t - delta, order)).norm() /
                ref;
            if (order <= k) {
                QVERIFY2(jump <= 1e-5, describe(c, t) + " order " + QByteArray::number(order) +
                                           " jump " + QByteArray::number(jump));
            } else {
                largestJump = std::max(largestJump, jump);
            }
        }
    }
    // One control point makes a constant curve.
    if (!breakpoints.empty() && k + 1 <= m && curve.controlPoints().size() > 1) {
        QVERIFY2(largestJump > 1e-3, c.name + " expected a jump in derivative k+1");
    }
}

void checkSameGeometry(const Case& c, const BSplineCurve& changed, const QByteArray& what) {
    std::vector<double> u = uniformSamples(c.curve.domainBegin(), c.curve.domainEnd(), 97);
    for (double t : distinctDomainKnots(c.curve)) {
        u.push_back(t);
    }
    const double deviation = maxDeviation(c.curve, changed, u);
    QVERIFY2(deviation <= 1e-12 * c.diameter,
             c.name + " " + what + " deviation " + QByteArray::number(deviation / c.diameter));
}

void checkPeriodicRepresentation(const BSplineCurve& curve, const QByteArray& what) {
    const int m = curve.degree();
    const int n = static_cast<int>(curve.controlPoints().size());
    const auto& t = curve.knots();
    QVERIFY2(t.size() == std::size_t(n + 2 * m + 1), what);
    QVERIFY2(std::is_sorted(t.begin(), t.end()), what);
    QVERIFY2(t[m - 1] < t[m], what);
    const double period = t[m + n] - t[m];
    for (int i = 0; i <= 2 * m; ++i) {
        QVERIFY2(std::abs(t[i + n] - t[i] - period) <= 1e-12 * period, what);
    }
    const auto exported = curve.exportControlPoints();
    QVERIFY2(curve.exportKnots().size() == exported.size() + m + 1, what);
}

void checkInsertion(const Case& c, std::mt19937& rng) {
    const BSplineCurve& curve = c.curve;
    const int m = c.degree;
    const double begin = curve.domainBegin();
    const double end = curve.domainEnd();
    std::uniform_real_distribution<double> in(begin, end);
    std::vector<double> candidates{in(rng), in(rng), begin + 0.5 * (end - begin)};
    for (double t : distinctDomainKnots(curve)) {
        candidates.push_back(t);
    }
    if (c.closed) {
        candidates.push_back(end + 0.3 * (end - begin)); // reduced modulo the period
        candidates.push_back(begin - 0.45 * (end - begin));
    }
    for (double u : candidates) {
        const double reduced =
            c.closed && (u < begin || u >= end)
                ? begin + std::fmod(std::fmod(u - begin, end - begin) + (end - begin), end - begin)
                : (c.closed && u == end ? begin : u);
        int existing = 0;
        if (c.closed) {
            const auto& t = curve.knots();
            existing = static_cast<int>(
                std::count(t.begin() + m, t.begin() + (m + curve.controlPoints().size()), reduced));
        } else {
            existing =
                static_cast<int>(std::count(curve.knots().begin(), curve.knots().end(), reduced));
        }
        if (existing >= m) {
            BSplineCurve copy = curve;
            QVERIFY_THROWS_EXCEPTION(std::invalid_argument, copy.insertKnot(u));
            continue;
        }
        for (int times = 1; times <= m - existing; ++times) {
            BSplineCurve refined = curve;
            refined.insertKnot(u, times);
            const QByteArray what =
                "insert " + QByteArray::number(u, 'g', 17) + " x" + QByteArray::number(times);
            QCOMPARE(refined.controlPoints().size(), curve.controlPoints().size() + times);
            QCOMPARE(refined.isClosed(), c.closed);
            QCOMPARE(refined.domainBegin(), begin);
            QVERIFY2(std::abs(refined.domainEnd() - end) <= 1e-15 * std::abs(end), what);
            RUN_CHECK(checkSameGeometry(c, refined, what));
            if (c.closed) {
                RUN_CHECK(checkPeriodicRepresentation(refined, c.name + " " + what));
            } else {
                QCOMPARE(refined.knots().size(), refined.controlPoints().size() + m + 1);
            }
            if (times == m - existing) {
                QVERIFY_THROWS_EXCEPTION(std::invalid_argument, refined.insertKnot(u));
            }
        }
    }
    // Many insertions in a row.
    BSplineCurve refined = curve;
    for (int i = 0; i < 12; ++i) {
        const double u = in(rng);
        refined.insertKnot(u);
    }
    RUN_CHECK(checkSameGeometry(c, refined, "12 insertions"));
    if (c.closed) {
        RUN_CHECK(checkPeriodicRepresentation(refined, c.name + " 12 insertions"));
    }
}

void checkSplit(const Case& c, std::mt19937& rng) {
    const BSplineCurve& curve = c.curve;
    const int m = c.degree;
    const double begin = curve.domainBegin();
    const double end = curve.domainEnd();
    std::uniform_real_distribution<double> in(begin, end);
    std::vector<double> candidates{in(rng), in(rng), begin + 0.5 * (end - begin)};
    for (double t : distinctDomainKnots(curve)) {
        if (t > begin && t < end) {
            candidates.push_back(t);
        }
    }
    for (double u : candidates) {
        const auto [left, right] = curve.split(u);
        const QByteArray what = describe(c, u);
        QCOMPARE(left.domainBegin(), begin);
        QCOMPARE(left.domainEnd(), u);
        QCOMPARE(right.domainBegin(), u);
        QCOMPARE(right.domainEnd(), end);
        for (const BSplineCurve* piece : {&left, &right}) {
            const auto& t = piece->knots();
            QCOMPARE(t.size(), piece->controlPoints().size() + m + 1);
            QVERIFY2(std::count(t.begin(), t.end(), piece->domainBegin()) == m + 1, what);
            QVERIFY2(std::count(t.begin(), t.end(), piece->domainEnd()) == m + 1, what);
            const auto samples = uniformSamples(piece->domainBegin(), piece->domainEnd(), 41);
            const double deviation = maxDeviation(curve, *piece, samples);
            QVERIFY2(deviation <= 1e-12 * c.diameter,
                     what + " deviation " + QByteArray::number(deviation / c.diameter));
        }
        QVERIFY2((left.controlPoints().front() - curve.evaluate(begin)).norm() <=
                     1e-12 * c.diameter,
                 what);
        QVERIFY2((right.controlPoints().back() - curve.evaluate(end)).norm() <= 1e-12 * c.diameter,
                 what);
        QVERIFY2((left.controlPoints().back() - curve.evaluate(u)).norm() <= 1e-12 * c.diameter,
                 what);
        QCOMPARE(right.controlPoints().front(), left.controlPoints().back());
    }
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, curve.split(begin));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, curve.split(end));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, curve.split(begin - 0.1 * (end - begin)));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, curve.split(end + 0.1 * (end - begin)));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument,
                             curve.split(std::numeric_limits<double>::quiet_NaN()));
}

void checkOpenedAt(const Case& c, std::mt19937& rng) {
    const BSplineCurve& curve = c.curve;
    const int m = c.degree;
    const double begin = curve.domainBegin();
    const double end = curve.domainEnd();
    const double period = end - begin;
    std::uniform_real_distribution<double> in(begin, end);
    std::vector<double> candidates{
        begin, in(rng), in(rng), end, begin + 1.37 * period, begin - 0.42 * period};
    for (double t : distinctDomainKnots(curve)) {
        candidates.push_back(t);
    }
    for (double u : candidates) {
        const BSplineCurve open = curve.openedAt(u);
        const QByteArray what = describe(c, u);
        QVERIFY2(!open.isClosed(), what);
        QCOMPARE(open.domainBegin(), u);
        QVERIFY2(std::abs(open.domainEnd() - (u + period)) <= 1e-14 * (std::abs(u) + period), what);
        const auto& t = open.knots();
        QVERIFY2(std::count(t.begin(), t.end(), open.domainBegin()) == m + 1, what);
        QVERIFY2(std::count(t.begin(), t.end(), open.domainEnd()) == m + 1, what);
        QCOMPARE(open.controlPoints().front(), open.controlPoints().back());
        QVERIFY2((open.controlPoints().front() - curve.evaluate(u)).norm() <= 1e-12 * c.diameter,
                 what);
        const auto samples = uniformSamples(open.domainBegin(), open.domainEnd(), 83);
        const double deviation = maxDeviation(curve, open, samples);
        // Parameters beyond the base period are reduced by the closed curve: rounding of u.
        QVERIFY2(deviation <= 1e-12 * c.diameter,
                 what + " deviation " + QByteArray::number(deviation / c.diameter));
    }
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument,
                             curve.openedAt(std::numeric_limits<double>::infinity()));
}

void checkReversed(const Case& c) {
    const BSplineCurve& curve = c.curve;
    const BSplineCurve back = curve.reversed();
    const double begin = curve.domainBegin();
    const double end = curve.domainEnd();
    QCOMPARE(back.isClosed(), c.closed);
    QCOMPARE(back.degree(), c.degree);
    QCOMPARE(back.controlPoints().size(), curve.controlPoints().size());
    QCOMPARE(back.domainBegin(), begin);
    QCOMPARE(back.domainEnd(), end);
    if (c.closed) {
        RUN_CHECK(checkPeriodicRepresentation(back, c.name + " reversed"));
    }
    for (double u : uniformSamples(begin, end, 61)) {
        const double v = begin + end - u;
        QVERIFY2((back.evaluate(v) - curve.evaluate(u)).norm() <= 1e-12 * c.diameter,
                 describe(c, u));
    }
    for (const auto& [a, b] : spans(curve)) {
        const double u = a + 0.3 * (b - a);
        const Vec3 d = curve.derivative(u, 1);
        const double ref = std::max(d.norm(), c.diameter / (b - a));
        QVERIFY2((back.derivative(begin + end - u, 1) + d).norm() <= 1e-10 * ref, describe(c, u));
    }
    const BSplineCurve twice = back.reversed();
    RUN_CHECK(checkSameGeometry(c, twice, "reversed twice"));
}

} // namespace

class TstBSpline : public QObject {
    Q_OBJECT

private slots:
    void splineSpace();
    void matchesCoxDeBoor();
    void nonUniformCurves();
    void partitionOfUnity();
    void derivativesMatchFiniteDifferences();
    void smoothnessAtKnots();
    void knotInsertion();
    void split();
    void openedAt();
    void reversed();
    void clampedEndpoints();
    void exportRoundTrip();
    void parameterHandling();
    void invalidInput();
    void scales();
};

void TstBSpline::splineSpace() {
    for (int m = 1; m <= 6; ++m) {
        for (int k = 0; k < m; ++k) {
            for (int n : {1, 2, 3, 7}) {
                const SplineSpace space{m, k, n};
                QVERIFY(space.isValid());
                const int open = space.controlPointCount(false);
                const int closed = space.controlPointCount(true);
                QCOMPARE(open, n * (m + 1) - (n - 1) * (k + 1));
                QCOMPARE(closed, n * (m - k));
                const auto openKnots = space.knots(false);
                QCOMPARE(openKnots.size(), std::size_t(open + m + 1));
                QVERIFY(std::is_sorted(openKnots.begin(), openKnots.end()));
                std::map<double, int> counts;
                for (double t : openKnots) {
                    ++counts[t];
                }
                QCOMPARE(int(counts.size()), n + 1);
                QCOMPARE(counts[0.0], m + 1);
                QCOMPARE(counts[1.0], m + 1);
                for (int i = 1; i < n; ++i) {
                    QCOMPARE(counts[double(i) / n], m - k);
                }
                const auto closedKnots = space.knots(true);
                QCOMPARE(closedKnots.size(), std::size_t(closed + 2 * m + 1));
                QCOMPARE(closedKnots[m], 0.0);
                QCOMPARE(closedKnots[m + closed], 1.0);
                QVERIFY(closedKnots[m - 1] < 0.0);
                QVERIFY(std::is_sorted(closedKnots.begin(), closedKnots.end()));
                for (int i = 0; i <= 2 * m; ++i) {
                    QVERIFY(std::abs(closedKnots[i + closed] - closedKnots[i] - 1.0) < 1e-15);
                }
            }
        }
    }
    QCOMPARE(SplineSpace({3, 2, 1}).controlPointCount(false), 4); // cubic C2: n + 3
    QCOMPARE(SplineSpace({3, 2, 4}).controlPointCount(false), 7);
    QCOMPARE(SplineSpace({3, 2, 4}).describe(), std::string("degree 3, C2, 4 intervals"));
    QCOMPARE(SplineSpace({2, 0, 1}).describe(), std::string("degree 2, C0, 1 interval"));

    QVERIFY(!SplineSpace({0, 0, 1}).isValid());
    QVERIFY(!SplineSpace({3, 3, 1}).isValid());
    QVERIFY(!SplineSpace({3, -1, 1}).isValid());
    QVERIFY(!SplineSpace({3, 2, 0}).isValid());
    QVERIFY(!SplineSpace({11, 2, 1}).isValid());
    QVERIFY(SplineSpace({10, 9, 100000}).isValid());
    QVERIFY(!SplineSpace({3, 2, 100001}).isValid());
    QCOMPARE(SplineSpace({3, 2, 0}).controlPointCount(false), 0);
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, SplineSpace({3, 3, 1}).knots(false));

    const SplineSpace a{3, 2, 4};
    const SplineSpace b{3, 2, 5};
    const SplineSpace c{3, 1, 9};
    QVERIFY(a == SplineSpace({3, 2, 4}));
    QVERIFY(a != b);
    QVERIFY(a < b && !(b < a));
    QVERIFY(c < a && !(a < c));
    QVERIFY(SplineSpace({2, 1, 50}) < c);
    QVERIFY(!(a < a));
    std::map<SplineSpace, int> keyed{{a, 1}, {b, 2}, {c, 3}};
    QCOMPARE(keyed.size(), std::size_t(3));
    QCOMPARE(keyed.begin()->second, 3);
}

void TstBSpline::matchesCoxDeBoor() {
    std::mt19937 rng(7);
    for (const Case& c : sweep()) {
        const int m = c.degree;
        const SplineSpace space{m, c.smoothness, c.intervals};
        const int count = space.controlPointCount(c.closed);
        // Reference knot vector built here, not by the library.
        std::vector<double> knots;
        if (!c.closed) {
            knots.assign(m + 1, 0.0);
            for (int i = 1; i < c.intervals; ++i) {
                knots.insert(knots.end(), m - c.smoothness, double(i) / c.intervals);
            }
            knots.insert(knots.end(), m + 1, 1.0);
        } else {
            std::vector<double> base;
            for (int i = 0; i < c.intervals; ++i) {
                base.insert(base.end(), m - c.smoothness, double(i) / c.intervals);
            }
            knots = periodicKnots(m, base, 1.0);
        }
        QCOMPARE(int(knots.size()), count + m + 1 + (c.closed ? m : 0));
        std::uniform_real_distribution<double> in(0.0, 1.0);
        for (int s = 0; s < 30; ++s) {
            const double u = in(rng);
            const Vec3 expected = coxDeBoor(m, knots, c.curve.controlPoints(), u);
            QVERIFY2((c.curve.evaluate(u) - expected).norm() <= 1e-12 * c.diameter, describe(c, u));
        }
    }
}

void TstBSpline::nonUniformCurves() {
    std::mt19937 rng(99);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int m = 1; m <= 5; ++m) {
        for (int trial = 0; trial < 4; ++trial) {
            // Open and unclamped, with a repeated interior knot.
            const int count = m + 4 + trial;
            std::vector<double> knots;
            for (int i = 0; i < count + m + 1; ++i) {
                knots.push_back(3.0 * unit(rng) - 1.0);
            }
            std::sort(knots.begin(), knots.end());
            if (m >= 2) {
                knots[m + 2] = knots[m + 1]; // a double knot (a jump needs multiplicity m+1)
            }
            const auto points = randomPoints(rng, count, 2.0);
            const BSplineCurve open(m, knots, points, false);
            Case oc{open,
                    "non-uniform open m=" + QByteArray::number(m),
                    m,
                    0,
                    count - m,
                    false,
                    diameterOf(points)};
            QCOMPARE(open.domainBegin(), knots[m]);
            QCOMPARE(open.domainEnd(), knots[count]);
            for (int s = 0; s < 20; ++s) {
                const double u =
                    open.domainBegin() + unit(rng) * (open.domainEnd() - open.domainBegin());
                QVERIFY2((open.evaluate(u) - coxDeBoor(m, knots, points, u)).norm() <=
                             1e-12 * oc.diameter,
                         describe(oc, u));
            }
            RUN_CHECK(checkRows(oc, rng));
            RUN_CHECK(checkDerivatives(oc));
            RUN_CHECK(checkInsertion(oc, rng));
            RUN_CHECK(checkSplit(oc, rng));
            RUN_CHECK(checkReversed(oc));
            const BSplineCurve clamped = open.clamped();
            RUN_CHECK(checkSameGeometry(oc, clamped, "clamped"));
            QCOMPARE(clamped.controlPoints().front(), open.evaluate(open.domainBegin()));
            QVERIFY((clamped.controlPoints().back() - open.evaluate(open.domainEnd())).norm() <=
                    1e-12 * oc.diameter);

            // Closed, non-uniform periodic knots with a double knot, period 2.5, start -0.7.
            const int n = m + 2 + trial;
            std::vector<double> base;
            for (int i = 0; i < n; ++i) {
                base.push_back(unit(rng));
            }
            std::sort(base.begin(), base.end());
            base[0] = 0.0;
            if (m >= 2) {
                base[n - 1] = base[n - 2];
            }
            for (double& t : base) {
                t = -0.7 + 2.5 * t;
            }
            const auto periodic = periodicKnots(m, base, 2.5);
            const auto ring = randomPoints(rng, n, 2.0);
            const BSplineCurve closed(m, periodic, ring, true);
            Case cc{closed,          "non-uniform closed m=" + QByteArray::number(m), m, 0, n, true,
                    diameterOf(ring)};
            QCOMPARE(closed.domainBegin(), -0.7);
            QVERIFY(std::abs(closed.domainEnd() - 1.8) < 1e-15);
            for (int s = 0; s < 20; ++s) {
                const double u = -0.7 + 2.5 * unit(rng);
                QVERIFY2((closed.evaluate(u) - coxDeBoor(m, periodic, ring, u)).norm() <=
                             1e-12 * cc.diameter,
                         describe(cc, u));
            }
            RUN_CHECK(checkRows(cc, rng));
            RUN_CHECK(checkDerivatives(cc));
            RUN_CHECK(checkInsertion(cc, rng));
            RUN_CHECK(checkOpenedAt(cc, rng));
            RUN_CHECK(checkReversed(cc));

            // The same curve given with its knot sequence started one knot later: here the
            // domain start is not the first of its knots, which the library normalises away.
            if (m >= 2) {
                // Make base knots 0 and 1 coincide so that t_{m-1} == t_m after the shift.
                std::vector<double> doubled = base;
                doubled[1] = doubled[0];
                const auto doubledKnots = periodicKnots(m, doubled, 2.5);
                const BSplineCurve reference(m, doubledKnots, ring, true);
                std::vector<double> rotated(doubledKnots.begin() + 1, doubledKnots.end());
                rotated.push_back(rotated[2 * m] + 2.5); // t_{N+2m+1} = t_{2m+1} + period
                std::vector<Vec3> rotatedRing(ring.begin() + 1, ring.end());
                rotatedRing.push_back(ring[0]);
                // rotated[m] == doubledKnots[m + 1] == doubledKnots[m]: same domain start.
                QCOMPARE(rotated[m - 1], rotated[m]);
                const BSplineCurve rotatedCurve(m, rotated, rotatedRing, true);
                QCOMPARE(rotatedCurve.domainBegin(), reference.domainBegin());
                Case rc{reference,       "rotated closed m=" + QByteArray::number(m), m, 0, n, true,
                        diameterOf(ring)};
                for (int s = 0; s < 20; ++s) {
                    const double u = -0.7 + 2.5 * unit(rng);
                    QVERIFY2(
                        (rotatedCurve.evaluate(u) - coxDeBoor(m, rotated, rotatedRing, u)).norm() <=
                            1e-12 * rc.diameter,
                        describe(rc, u));
                }
                RUN_CHECK(checkSameGeometry(rc, rotatedCurve, "rotated input"));
                RUN_CHECK(checkPeriodicRepresentation(rotatedCurve, "rotated input"));
            }
        }
    }
}

void TstBSpline::partitionOfUnity() {
    std::mt19937 rng(1);
    for (const Case& c : sweep()) {
        RUN_CHECK(checkRows(c, rng));
    }
}

void TstBSpline::derivativesMatchFiniteDifferences() {
    for (const Case& c : sweep()) {
        RUN_CHECK(checkDerivatives(c));
    }
}

void TstBSpline::smoothnessAtKnots() {
    for (const Case& c : sweep()) {
        RUN_CHECK(checkSmoothness(c));
    }
}

void TstBSpline::knotInsertion() {
    std::mt19937 rng(2);
    for (const Case& c : sweep()) {
        RUN_CHECK(checkInsertion(c, rng));
    }
}

void TstBSpline::split() {
    std::mt19937 rng(3);
    for (const Case& c : sweep()) {
        if (c.closed) {
            QVERIFY_THROWS_EXCEPTION(std::invalid_argument, c.curve.split(0.5));
            continue;
        }
        RUN_CHECK(checkSplit(c, rng));
    }
}

void TstBSpline::openedAt() {
    std::mt19937 rng(4);
    for (const Case& c : sweep()) {
        if (!c.closed) {
            QVERIFY_THROWS_EXCEPTION(std::invalid_argument, c.curve.openedAt(0.5));
            continue;
        }
        RUN_CHECK(checkOpenedAt(c, rng));
    }
}

void TstBSpline::reversed() {
    for (const Case& c : sweep()) {
        RUN_CHECK(checkReversed(c));
    }
}

void TstBSpline::clampedEndpoints() {
    for (const Case& c : sweep()) {
        if (c.closed) {
            continue;
        }
        const BSplineCurve& curve = c.curve;
        const auto& p = curve.controlPoints();
        const std::size_t last = p.size() - 1;
        const int m = c.degree;
        const double n = c.intervals;
        QVERIFY2((curve.evaluate(0.0) - p.front()).norm() <= 1e-15 * c.diameter, c.name);
        QVERIFY2((curve.evaluate(1.0) - p.back()).norm() <= 1e-15 * c.diameter, c.name);
        // End tangents along the first and last control legs (end spans have length 1/n).
        const Vec3 start = (p[1] - p[0]) * (m * n);
        const Vec3 end = (p[last] - p[last - 1]) * (m * n);
        QVERIFY2((curve.derivative(0.0, 1) - start).norm() <= 1e-12 * start.norm(), c.name);
        QVERIFY2((curve.derivative(1.0, 1) - end).norm() <= 1e-12 * end.norm(), c.name);
        QVERIFY2((curve.deBoorPoints(1.0).firstDerivative() - end).norm() <= 1e-12 * end.norm(),
                 c.name);
        QCOMPARE(curve.knots().size(), p.size() + m + 1);
        // Already clamped: clamping changes nothing.
        const BSplineCurve clamped = curve.clamped();
        QCOMPARE(clamped.knots(), curve.knots());
        QVERIFY(clamped.controlPoints() == curve.controlPoints());
    }
}

void TstBSpline::exportRoundTrip() {
    for (const Case& c : sweep()) {
        const BSplineCurve& curve = c.curve;
        const int m = c.degree;
        const auto knots = curve.exportKnots();
        const auto points = curve.exportControlPoints();
        QCOMPARE(knots.size(), points.size() + m + 1);
        if (!c.closed) {
            QCOMPARE(knots, curve.knots());
            QVERIFY(points == curve.controlPoints());
            continue;
        }
        QCOMPARE(points.size(), curve.controlPoints().size() + m);
        for (int i = 0; i < m; ++i) {
            QCOMPARE(points[points.size() - m + i], points[i]);
        }
        const BSplineCurve again(m, knots, points, true);
        QCOMPARE(again.knots(), curve.knots());
        QVERIFY(again.controlPoints() == curve.controlPoints());
        // The interchange form read as an ordinary unclamped open curve is the same curve.
        const BSplineCurve asOpen(m, knots, points, false);
        QCOMPARE(asOpen.domainBegin(), 0.0);
        QCOMPARE(asOpen.domainEnd(), 1.0);
        RUN_CHECK(checkSameGeometry(c, asOpen, "export as open"));
        // Mismatched repetition is rejected.
        auto broken = points;
        broken.back() = broken.back() + Vec3(1.0, 0.0, 0.0);
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, BSplineCurve(m, knots, broken, true));
    }
}

void TstBSpline::parameterHandling() {
    std::mt19937 rng(5);
    for (const Case& c : sweep()) {
        const BSplineCurve& curve = c.curve;
        const int m = c.degree;
        const double tolerance = 1e-12 * c.diameter * c.intervals * m;
        std::uniform_real_distribution<double> in(0.0, 1.0);
        if (c.closed) {
            for (int s = 0; s < 10; ++s) {
                const double u = in(rng);
                QVERIFY2((curve.evaluate(u + 1.0) - curve.evaluate(u)).norm() <= tolerance,
                         describe(c, u));
                QVERIFY2((curve.evaluate(u - 3.0) - curve.evaluate(u)).norm() <= tolerance,
                         describe(c, u));
            }
            QVERIFY((curve.evaluate(1.0) - curve.evaluate(0.0)).norm() <= tolerance);
            const DeBoorRows atEnd = curve.deBoorRows(1.0);
            QCOMPARE(atEnd.parameter, 0.0);
            const auto& t = curve.knots();
            QVERIFY(t[atEnd.span] <= 0.0 && 0.0 < t[atEnd.span + 1] && atEnd.span >= m);
            // Just below a knot after reduction modulo the period still finds that knot.
            const DeBoorRows wrapped = curve.deBoorRows(1.5);
            QCOMPARE(wrapped.parameter, curve.deBoorRows(0.5).parameter);
        } else {
            QCOMPARE(curve.evaluate(-1e-13), curve.evaluate(0.0));
            QCOMPARE(curve.evaluate(1.0 + 1e-13), curve.evaluate(1.0));
            QCOMPARE(curve.evaluate(7.0), curve.evaluate(1.0));
            const DeBoorRows atEnd = curve.deBoorRows(1.0);
            QCOMPARE(atEnd.parameter, 1.0);
            QCOMPARE(atEnd.span, int(curve.controlPoints().size()) - 1);
            QCOMPARE(atEnd.point.back(), 1.0);
        }
        // At a knot the span to the right is used.
        const auto& t = curve.knots();
        for (double knot : distinctDomainKnots(curve)) {
            if (knot == curve.domainEnd()) {
                continue;
            }
            const DeBoorRows rows = curve.deBoorRows(knot);
            QVERIFY2(t[rows.span] <= knot && knot < t[rows.span + 1], describe(c, knot));
        }
    }
    // Domain end inside a repeated knot (t_{N-1} == t_N): the last non-empty span is used.
    const std::vector<Vec3> quadPoints{Vec3(0, 0, 0), Vec3(1, 2, 0), Vec3(3, 1, 0), Vec3(4, 4, 1)};
    const std::vector<double> quadKnots{0, 1, 2, 3, 3, 4, 5};
    const BSplineCurve quad(2, quadKnots, quadPoints, false);
    QCOMPARE(quad.domainEnd(), 3.0);
    QCOMPARE(quad.deBoorRows(3.0).span, 2);
    const Vec3 atEnd = quad.evaluate(3.0);
    const Vec3 nearEnd = quad.evaluate(3.0 - 1e-9);
    QVERIFY(atEnd.isFinite() && (atEnd - nearEnd).norm() < 1e-8);
    QVERIFY((atEnd - coxDeBoor(2, quadKnots, quadPoints, 3.0 - 1e-15)).norm() < 1e-12);
    QVERIFY(quad.derivative(3.0, 2).isFinite());

    const BSplineCurve empty;
    QVERIFY(empty.isEmpty());
    QVERIFY_THROWS_EXCEPTION(std::logic_error, empty.evaluate(0.0));
    const BSplineCurve line = BSplineCurve::uniform({1, 0, 1}, {Vec3(0, 0, 0), Vec3(2, 0, 0)});
    QCOMPARE(line.evaluate(0.25), Vec3(0.5, 0, 0));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument,
                             line.evaluate(std::numeric_limits<double>::quiet_NaN()));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, line.derivative(0.5, -1));
}

void TstBSpline::invalidInput() {
    const std::vector<Vec3> four{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0)};
    const std::vector<double> cubicKnots{0, 0, 0, 0, 1, 1, 1, 1};
    QVERIFY(!BSplineCurve(3, cubicKnots, four, false).isEmpty());
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();

    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, BSplineCurve(0, cubicKnots, four, false));
    // Wrong counts.
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument,
                             BSplineCurve(3, {0, 0, 0, 0, 1, 1, 1}, four, false));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument,
                             BSplineCurve(3, {0, 0, 0, 1, 1, 1}, {four[0], four[1]}, false));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument,
                             BSplineCurve::uniform({3, 2, 2}, four)); // needs 5
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, BSplineCurve::uniform({3, 2, 2}, four, true));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, BSplineCurve::uniform({3, 3, 1}, four));
    // Decreasing knots, over-repeated knots, empty domain.
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument,
                             BSplineCurve(3, {0, 0, 0, 0, 1, 0.5, 1, 1}, four, false));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument,
                             BSplineCurve(1, {0, 0, 0, 1, 1}, {four[0], four[1], four[2]}, false));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument,
                             BSplineCurve(3, {1, 1, 1, 1, 1, 1, 1, 1}, four, false));
    // Non-finite values.
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument,
                             BSplineCurve(3, {0, 0, 0, 0, nan, 1, 1, 1}, four, false));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument,
                             BSplineCurve(3, {0, 0, 0, 0, 1, 1, 1, inf}, four, false));
    auto withNan = four;
    withNan[2].y = nan;
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, BSplineCurve(3, cubicKnots, withNan, false));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, BSplineCurve::uniform({3, 2, 1}, withNan));
    // Closed: wrong count, not periodic, no period.
    const auto periodic = SplineSpace{3, 2, 4}.knots(true); // 4 control points
    QVERIFY(BSplineCurve(3, periodic, four, true).isClosed());
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument,
                             BSplineCurve(3, periodic, {four[0], four[1], four[2]}, true));
    auto notPeriodic = periodic;
    notPeriodic.front() -= 0.1;
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, BSplineCurve(3, notPeriodic, four, true));
    notPeriodic = periodic;
    notPeriodic.back() += 1e-3;
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, BSplineCurve(3, notPeriodic, four, true));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, BSplineCurve(1, {0, 0, 0}, {four[0]}, true));
    // Operations with bad arguments.
    BSplineCurve curve = BSplineCurve::uniform({3, 2, 1}, four);
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, curve.insertKnot(1.5));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, curve.insertKnot(nan));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, curve.insertKnot(0.5, 4));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, curve.insertKnot(0.5, -1));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, curve.insertKnot(0.0));
    QCOMPARE(curve.controlPoints().size(), std::size_t(4)); // failed calls left it alone
    curve.insertKnot(0.5, 0);
    QCOMPARE(curve.controlPoints().size(), std::size_t(4));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, curve.openedAt(0.5));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, curve.split(0.0));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, curve.derivative(inf, 1));
}

void TstBSpline::scales() {
    for (double geometry : {1e-3, 1e3}) {
        for (double parameter : {1.0, 1e-3, 1e3}) {
            std::mt19937 rng(6);
            for (const Case& c : sweep(geometry, parameter, 77)) {
                if (c.degree > 3 && c.intervals > 2) {
                    continue; // keep the run short; the full sweep runs at scale 1
                }
                RUN_CHECK(checkRows(c, rng));
                RUN_CHECK(checkDerivatives(c));
                RUN_CHECK(checkInsertion(c, rng));
                RUN_CHECK(checkReversed(c));
                if (c.closed) {
                    RUN_CHECK(checkOpenedAt(c, rng));
                } else {
                    RUN_CHECK(checkSplit(c, rng));
                }
            }
        }
    }
}

DEVSURF_REGISTER_TEST(TstBSpline);

#include "tst_bspline.moc"
