#include "bspline_checks.h"
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

using namespace devsurf::test::bspline;
using devsurf::model::BSplineCurve;
using devsurf::model::DeBoorPoints;
using devsurf::model::DeBoorRows;
using devsurf::model::SplineSpace;
using devsurf::model::Vec3;

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
    QCOMPARE(SplineSpace({3, 2, 4}).technicalKey(), std::string("S(n=4, m=3, k=2)"));

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
