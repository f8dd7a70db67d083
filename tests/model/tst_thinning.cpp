#include "model/math_constants.h"
#include "model/reference/thinning.h"
#include "test_registry.h"

#include <QTest>

#include <algorithm>
#include <cmath>
#include <random>

using namespace devsurf::model;
using namespace devsurf::model::reference;

namespace {

using devsurf::model::kPi;

// n points spread evenly over the sphere of radius r about c (a Fibonacci lattice).
std::vector<Vec3> sphere(std::size_t n, double r, const Vec3& c) {
    std::vector<Vec3> points;
    const double golden = kPi * (3.0 - std::sqrt(5.0));
    for (std::size_t i = 0; i < n; ++i) {
        const double z = 1.0 - (2.0 * static_cast<double>(i) + 1.0) / static_cast<double>(n);
        const double ring = std::sqrt(1.0 - z * z);
        const double phi = golden * static_cast<double>(i);
        points.push_back(c + Vec3(ring * std::cos(phi), ring * std::sin(phi), z) * r);
    }
    return points;
}

// n random points of the square [0, size]² of the plane through `origin` spanned by e1, e2.
std::vector<Vec3> plane(std::size_t n, double size, const Vec3& origin, const Vec3& e1,
                        const Vec3& e2, unsigned seed) {
    std::mt19937 random(seed);
    std::uniform_real_distribution<double> along(0.0, size);
    std::vector<Vec3> points;
    for (std::size_t i = 0; i < n; ++i) {
        const double s = along(random);
        const double t = along(random);
        points.push_back(origin + e1 * s + e2 * t);
    }
    return points;
}

Vec3 unitVector(const Vec3& v) {
    return v / v.norm();
}

// The smallest distance between two kept points, by brute force.
double closestPair(const ThinningResult& thinned) {
    double closest = INFINITY;
    for (std::size_t i = 0; i < thinned.points.size(); ++i) {
        for (std::size_t j = i + 1; j < thinned.points.size(); ++j) {
            closest =
                std::min(closest, distance(thinned.points[i].position, thinned.points[j].position));
        }
    }
    return closest;
}

} // namespace

class TstThinning : public QObject {
    Q_OBJECT
private slots:
    void sphereNormalsAreRadial_data() {
        QTest::addColumn<double>("scale");
        QTest::newRow("1e-3") << 1e-3;
        QTest::newRow("1") << 1.0;
        QTest::newRow("1e3") << 1e3;
    }
    void sphereNormalsAreRadial() {
        QFETCH(double, scale);
        const Vec3 centre = Vec3(3.0, -2.0, 5.0) * scale;
        const double r = 100.0 * scale;
        const std::vector<Vec3> points = sphere(600000, r, centre);
        const double rho = 0.05 * r;
        const ThinningResult thinned = thinReference(points, rho);
        QCOMPARE(thinned.radius, rho);
        QCOMPARE(thinned.isolated, std::size_t{0});
        QVERIFY(!thinned.cancelled);
        // A ball holds ρ²/4r² of the sphere, about 370 points. The balls of the kept points
        // cover the sphere (at least 4r²/ρ² = 1600 of them), and the balls of half the radius
        // do not overlap (at most 6400).
        QVERIFY2(thinned.points.size() >= 1600 && thinned.points.size() <= 6400,
                 qPrintable(QString::number(thinned.points.size())));
        double worst = 0.0;
        for (const ThinnedPoint& q : thinned.points) {
            QCOMPARE(q.position, points[q.source]);
            QVERIFY(q.ballCount > 100);
            worst = std::max(worst, angleBetween(q.normal, unitVector(q.position - centre)));
        }
        QVERIFY2(worst < 1e-3, qPrintable(QString::number(worst)));
        QVERIFY(closestPair(thinned) >= rho);
        // Every reference point lies in the ball of a kept point.
        for (std::size_t i = 0; i < points.size(); i += 997) {
            bool inBall = false;
            for (const ThinnedPoint& q : thinned.points) {
                inBall = inBall || distance(q.position, points[i]) < rho;
            }
            QVERIFY(inBall);
        }
    }

    void planeNormalsAreThePlaneNormal() {
        const Vec3 e1 = unitVector(Vec3(1.0, 2.0, -0.5));
        const Vec3 e2 = unitVector(cross(e1, Vec3(0.3, -1.0, 2.0)));
        const Vec3 n = unitVector(cross(e1, e2));
        const std::vector<Vec3> points = plane(100000, 50.0, Vec3(10, 20, 30), e1, e2, 3);
        const double rho = defaultThinningRadius(points);
        const ThinningResult thinned = thinReference(points, rho);
        QVERIFY(thinned.points.size() > 1000);
        for (const ThinnedPoint& q : thinned.points) {
            QVERIFY(std::abs(angleBetween(q.normal, n)) < 1e-9 ||
                    std::abs(angleBetween(q.normal, -n)) < 1e-9);
            QCOMPARE(q.position, points[q.source]);
        }
        QVERIFY(closestPair(thinned) >= rho);
        // The visit order is the index order, so the first point is always kept.
        QCOMPARE(thinned.points.front().source, std::size_t{0});
        QCOMPARE(thinReference(points, rho).points.size(), thinned.points.size());
    }

    void pointsWithoutAPlaneAreDroppedAlone() {
        const Vec3 e1(1, 0, 0);
        const Vec3 e2(0, 1, 0);
        std::vector<Vec3> points{Vec3(500, 500, 500)}; // a stray point first
        for (const Vec3& p : plane(20000, 10.0, Vec3(), e1, e2, 5)) {
            points.push_back(p);
        }
        // Three collinear points, and a non-finite one.
        points.push_back(Vec3(-300, 0, 0));
        points.push_back(Vec3(-300.1, 0, 0));
        points.push_back(Vec3(-300.2, 0, 0));
        points.push_back(Vec3(NAN, 0, 0));
        const ThinningResult thinned = thinReference(points, 0.5);
        QCOMPARE(thinned.isolated, std::size_t{4});
        QCOMPARE(thinned.nonFinite, std::size_t{1});
        for (const ThinnedPoint& q : thinned.points) {
            QVERIFY(q.position.x >= 0.0 && q.position.x <= 10.0 && q.position.z == 0.0);
            QVERIFY(std::abs(std::abs(q.normal.z) - 1.0) < 1e-12);
            QVERIFY(q.ballCount >= 3);
        }
        QCOMPARE(thinned.points.front().source, std::size_t{1});
        QCOMPARE(thinReference(points, 0.0).radius, defaultThinningRadius(points));
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, thinReference(points, NAN));
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, thinReference(points, INFINITY));
    }

    void defaultRadiusFollowsSizeAndSpacing() {
        // A 301 × 301 grid with unit spacing: 1 % of the diagonal (4.24) beats 3 spacings.
        std::vector<Vec3> dense;
        for (int i = 0; i <= 300; ++i) {
            for (int j = 0; j <= 300; ++j) {
                dense.emplace_back(i, j, 0.0);
            }
        }
        QCOMPARE(defaultThinningRadius(dense), 0.01 * std::sqrt(2.0) * 300.0);
        // An 11 × 11 grid: 3 spacings (3) beat 1 % of the diagonal (0.14).
        std::vector<Vec3> sparse;
        for (int i = 0; i <= 10; ++i) {
            for (int j = 0; j <= 10; ++j) {
                sparse.emplace_back(i, j, 0.0);
                sparse.emplace_back(i, j, 0.0); // duplicates do not count as spacing
            }
        }
        QCOMPARE(defaultThinningRadius(sparse), 3.0);
        QCOMPARE(defaultThinningRadius({}), 0.0);
        QCOMPARE(defaultThinningRadius({Vec3(1, 2, 3), Vec3(1, 2, 3)}), 0.0);
    }

    void progressReportsAndCancels() {
        const std::vector<Vec3> points = sphere(200000, 1.0, Vec3());
        std::vector<std::size_t> calls;
        const ThinningResult whole =
            thinReference(points, 0.05, [&calls](std::size_t done, std::size_t total) {
                calls.push_back(done);
                return total == 200000;
            });
        QVERIFY(!whole.cancelled);
        QVERIFY(calls.size() >= 4);
        QCOMPARE(calls.front(), std::size_t{0});
        QCOMPARE(calls.back(), std::size_t{200000});
        QVERIFY(std::is_sorted(calls.begin(), calls.end()));
        const ThinningResult stopped =
            thinReference(points, 0.05, [](std::size_t done, std::size_t) { return done == 0; });
        QVERIFY(stopped.cancelled);
        QVERIFY(stopped.points.size() < whole.points.size());
        QVERIFY(!stopped.points.empty());
    }
};

DEVSURF_REGISTER_TEST(TstThinning);
#include "tst_thinning.moc"
