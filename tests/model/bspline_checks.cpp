#include "bspline_checks.h"

#include "spline_space.h"

#include <QObject>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <stdexcept>

namespace devsurf::test::bspline {

using model::DeBoorPoints;
using model::DeBoorRows;
using model::SplineSpace;

namespace {

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

// Two random parameters, the middle of the domain and the knots (with `interiorOnly`, those
// strictly inside the domain).
std::vector<double> candidateParameters(const BSplineCurve& curve, std::mt19937& rng,
                                        bool interiorOnly) {
    const double begin = curve.domainBegin();
    const double end = curve.domainEnd();
    std::uniform_real_distribution<double> in(begin, end);
    std::vector<double> candidates{in(rng), in(rng), begin + 0.5 * (end - begin)};
    for (double t : distinctDomainKnots(curve)) {
        if (!interiorOnly || (t > begin && t < end)) {
            candidates.push_back(t);
        }
    }
    return candidates;
}

} // namespace

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
std::vector<Case> sweep(double geometryScale, double parameterScale, unsigned seed) {
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
                                     int randomCount) {
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
    std::vector<double> candidates = candidateParameters(curve, rng, false);
    std::uniform_real_distribution<double> in(begin, end);
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
    std::vector<double> candidates = candidateParameters(curve, rng, true);
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

} // namespace devsurf::test::bspline
