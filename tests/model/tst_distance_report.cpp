#include "model/examples.h"
#include "model/math_constants.h"
#include "model/model_error.h"
#include "model/reference/distance_report.h"
#include "model/reference/initial_strip.h"
#include "model/reference/surface_samples.h"
#include "model/strip.h"
#include "surface_transform.h"
#include "test_registry.h"

#include <QTest>

#include <array>
#include <cmath>
#include <random>
#include <stdexcept>

using namespace devsurf::model;
using namespace devsurf::model::reference;

namespace {

using devsurf::model::kPi;

Vec3 unit(const Vec3& v) {
    return v / v.norm();
}

// The unit normal s_u × s_v of a strip at (u,v).
Vec3 stripNormal(const Strip& strip, double u, double v) {
    const Vec3 au = strip.a.derivative(u, 1);
    const Vec3 bu = strip.isCone() ? Vec3() : strip.b.derivative(u, 1);
    return unit(cross(au * (1.0 - v) + bu * v, strip.bPoint(u) - strip.aPoint(u)));
}

// A cone over a quarter circle of radius 100 in z = 0, apex 80 above its centre.
CompositeSurface quarterCone() {
    CompositeSurface s;
    const VertexId apex = s.addVertex({0, 0, 80});
    const VertexId p0 = s.addVertex({100, 0, 0});
    const VertexId p1 = s.addVertex({0, 100, 0});
    s.addFace({apex, p0, p1});
    const SplineSpace space{3, 2, 4};
    // Control points of the clamped cubic at the Greville abscissae of the quarter circle.
    const std::vector<double> knots = space.knots(false);
    std::vector<Vec3> points;
    for (int i = 0; i < space.controlPointCount(false); ++i) {
        const double t = (knots[i + 1] + knots[i + 2] + knots[i + 3]) / 3.0;
        points.emplace_back(100 * std::cos(kPi / 2 * t), 100 * std::sin(kPi / 2 * t), 0.0);
    }
    points.front() = s.position(p0);
    points.back() = s.position(p1);
    s.setSpline(p0, p1, space, points);
    return s;
}

// Points of a strip offset along its normal by known distances: (u,v) in the middle of the
// strip, where no other strip comes closer than the foot.
struct Offsets {
    std::vector<Vec3> points;
    std::vector<double> distances;
};

Offsets offsetsFrom(const std::vector<Strip>& strips, const std::vector<double>& gaps,
                    unsigned seed) {
    std::mt19937 random(seed);
    std::uniform_real_distribution<double> inner(0.2, 0.8);
    Offsets offsets;
    for (std::size_t i = 0; i < gaps.size(); ++i) {
        const Strip& strip = strips[i % strips.size()];
        const double u = inner(random);
        const double v = inner(random);
        offsets.points.push_back(strip.point(u, v) + stripNormal(strip, u, v) * gaps[i]);
        offsets.distances.push_back(std::abs(gaps[i]));
    }
    return offsets;
}

// Independent samples of every strip (n × n grid) and the largest distance from a point of a
// strip to its nearest sample (half the longest cell diagonal, plus the chord's sag margin).
struct BruteForce {
    std::vector<Vec3> samples;
    double spacing = 0.0;
};

BruteForce bruteForceSamples(const std::vector<Strip>& strips, int n) {
    BruteForce bf;
    for (const Strip& strip : strips) {
        for (int i = 0; i <= n; ++i) {
            for (int j = 0; j <= n; ++j) {
                bf.samples.push_back(strip.point(double(i) / n, double(j) / n));
                if (i > 0 && j > 0) {
                    const double diagonal =
                        std::max(distance(strip.point(double(i) / n, double(j) / n),
                                          strip.point(double(i - 1) / n, double(j - 1) / n)),
                                 distance(strip.point(double(i - 1) / n, double(j) / n),
                                          strip.point(double(i) / n, double(j - 1) / n)));
                    bf.spacing = std::max(bf.spacing, diagonal);
                }
            }
        }
    }
    return bf;
}

double nearestByBruteForce(const std::vector<Vec3>& points, const Vec3& q) {
    double best = INFINITY;
    for (const Vec3& p : points) {
        best = std::min(best, (p - q).squaredNorm());
    }
    return std::sqrt(best);
}

// The nearest-rank 95th percentile.
double percentile95(std::vector<double> values) {
    std::sort(values.begin(), values.end());
    const auto rank = static_cast<std::size_t>(std::ceil(0.95 * values.size()));
    return values[rank - 1];
}

} // namespace

class TstDistanceReport : public QObject {
    Q_OBJECT
private slots:
    void targetToSurfaceIsExact_data() {
        QTest::addColumn<QString>("shape");
        QTest::addColumn<double>("scale");
        for (const char* shape : {"cylinder", "cone"}) {
            for (double scale : {1e-3, 1.0, 1e3}) {
                QTest::newRow(qPrintable(QString("%1 %2").arg(shape).arg(scale)))
                    << QString(shape) << scale;
            }
        }
    }
    void targetToSurfaceIsExact() {
        QFETCH(QString, shape);
        QFETCH(double, scale);
        CompositeSurface surface =
            shape == "cylinder" ? makeExample("cylinder").surfaces.front() : quarterCone();
        devsurf::test::transformSurface(surface, [scale](const Vec3& p) { return p * scale; });
        const std::vector<Strip> strips = stripsOf(surface);
        std::vector<double> gaps;
        for (int i = 0; i < 60; ++i) {
            gaps.push_back((i % 2 ? 1.0 : -1.0) * (0.5 + 0.25 * i) * scale); // ±0.5 … ±15.25
        }
        const Offsets target = offsetsFrom(strips, gaps, 11);
        const DistanceReport report = measureDistance(surface, target.points, {0.0, 8});
        QCOMPARE(report.targetDistances.size(), target.points.size());
        const BruteForce bf = bruteForceSamples(strips, 150);
        for (std::size_t i = 0; i < target.points.size(); ++i) {
            const double d = report.targetDistances[i];
            QVERIFY2(std::abs(d - target.distances[i]) <= 1e-6 * target.distances[i],
                     qPrintable(QString("%1: %2 instead of %3")
                                    .arg(i)
                                    .arg(d, 0, 'g', 17)
                                    .arg(target.distances[i], 0, 'g', 17)));
            // Brute force over independent samples: never closer, and at most their spacing
            // farther.
            const double sampled = nearestByBruteForce(bf.samples, target.points[i]);
            QVERIFY(d <= sampled + 1e-9 * scale);
            QVERIFY(d >= sampled - bf.spacing);
        }
        double sum = 0.0;
        for (double d : target.distances) {
            sum += d;
        }
        const double mean = sum / static_cast<double>(target.distances.size());
        QVERIFY(std::abs(report.targetToSurface.mean - mean) <= 1e-6 * mean);
        QVERIFY(std::abs(report.targetToSurface.max - 15.25 * scale) <= 1e-6 * 15.25 * scale);
        const double p95 = percentile95(target.distances);
        QVERIFY(std::abs(report.targetToSurface.percentile95 - p95) <= 1e-6 * p95);
        QVERIFY(std::abs(report.targetToSurface.maxPercent -
                         100.0 * report.targetToSurface.max / report.diagonal) < 1e-12);
    }

    void everyFaceTypeIsMeasured() {
        // mixed holds a planar face, an SRSR strip, an SRS strip and a cone, all in z = 0:
        // a point at height h above any point of it is exactly |h| away.
        const CompositeSurface surface = makeExample("mixed").surfaces.front();
        std::mt19937 random(5);
        std::uniform_real_distribution<double> height(-30.0, 30.0);
        std::uniform_real_distribution<double> weight(0.0, 1.0);
        std::vector<Vec3> onSurface;
        for (int k = 0; k < 10; ++k) {
            for (const Strip& strip : stripsOf(surface)) {
                onSurface.push_back(strip.point(weight(random), weight(random)));
            }
            for (const auto& [face, loop] : surface.faces()) {
                if (surface.faceType(face) == FaceType::Planar) {
                    const Vec3 a = surface.position(loop[0]);
                    const double s = weight(random);
                    const double t = weight(random) * (1.0 - s);
                    onSurface.push_back(a + (surface.position(loop[1]) - a) * s +
                                        (surface.position(loop[2]) - a) * t);
                }
            }
        }
        std::vector<Vec3> target;
        std::vector<double> expected;
        for (const Vec3& p : onSurface) {
            const double h = height(random);
            target.push_back(p + Vec3(0, 0, h));
            expected.push_back(std::abs(h));
        }
        const DistanceReport report = measureDistance(surface, target);
        for (std::size_t i = 0; i < target.size(); ++i) {
            QVERIFY2(std::abs(report.targetDistances[i] - expected[i]) <= 1e-9 * expected[i],
                     qPrintable(QString("%1: %2 instead of %3")
                                    .arg(i)
                                    .arg(report.targetDistances[i])
                                    .arg(expected[i])));
        }
        bool types[5] = {};
        for (const SurfacePiece& piece : sampleDensely({surface}, 4).pieces) {
            types[static_cast<int>(surface.faceType(piece.face))] = true;
        }
        QVERIFY(types[1] && types[2] && types[3] && types[4]);
    }

    void surfaceToTargetMatchesBruteForce() {
        // The target: a cylinder 4 mm outside the example's, sampled on a coarser grid.
        const CompositeSurface surface = makeExample("cylinder").surfaces.front();
        const std::vector<Strip> strips = stripsOf(surface);
        std::vector<Vec3> target;
        for (const Strip& strip : strips) {
            for (int i = 0; i <= 20; ++i) {
                for (int j = 0; j <= 10; ++j) {
                    const double u = i / 20.0;
                    const double v = j / 10.0;
                    target.push_back(strip.point(u, v) + stripNormal(strip, u, v) * 4.0);
                }
            }
        }
        const DistanceReport report = measureDistance(surface, target, {5.0, 16});
        QCOMPARE(report.coverage, 1.0);
        QCOMPARE(report.tolerance, 5.0);
        // Independent: every point of a fine grid on the surface (their cells all of about
        // the same area on a cylinder) to its nearest target point.
        const BruteForce bf = bruteForceSamples(strips, 120);
        double largest = 0.0;
        double sum = 0.0;
        for (const Vec3& p : bf.samples) {
            const double d = nearestByBruteForce(target, p);
            largest = std::max(largest, d);
            sum += d;
        }
        const double mean = sum / static_cast<double>(bf.samples.size());
        // The distance to the target moves by at most the distance moved on the surface.
        const double slack = report.surfaceSpacing + bf.spacing;
        QVERIFY2(std::abs(report.surfaceToTarget.max - largest) <= slack,
                 qPrintable(QString("%1 vs %2").arg(report.surfaceToTarget.max).arg(largest)));
        QVERIFY2(std::abs(report.surfaceToTarget.mean - mean) <= slack,
                 qPrintable(QString("%1 vs %2").arg(report.surfaceToTarget.mean).arg(mean)));
        QVERIFY(report.surfaceToTarget.max > 4.0);
        QVERIFY(report.surfaceToTarget.mean >= 4.0 && report.surfaceToTarget.mean < 4.0 + slack);
        QVERIFY(report.surfaceToTarget.percentile95 <= report.surfaceToTarget.max);
        QVERIFY(report.surfaceToTarget.percentile95 >= report.surfaceToTarget.mean - 1e-12);
        QVERIFY(std::abs(report.surfaceToTarget.meanPercent -
                         100.0 * report.surfaceToTarget.mean / report.diagonal) < 1e-12);
        QVERIFY(std::abs(report.hausdorff() -
                         std::max(report.surfaceToTarget.max, report.targetToSurface.max)) == 0.0);
    }

    void surfaceToTargetIsWeightedByArea() {
        // The cone s(u,v) = (1−v) a(u) + v apex has |s_u × s_v| = (1−v) |a′ × (apex − a)|: over
        // its area, v averages ∫v(1−v) / ∫(1−v) = 1/3, so its height (80 v) averages 80/3,
        // where a mean over its (u,v) grid would give 40. The target: a fine grid 10 below.
        const CompositeSurface surface = quarterCone();
        std::vector<Vec3> target;
        for (int i = 0; i <= 220; ++i) {
            for (int j = 0; j <= 220; ++j) {
                target.emplace_back(-5.0 + 0.5 * i, -5.0 + 0.5 * j, -10.0);
            }
        }
        const DistanceReport report = measureDistance(surface, target, {1.0, 16});
        const double mean = 10.0 + 80.0 / 3.0;
        QVERIFY2(std::abs(report.surfaceToTarget.mean - mean) < 0.005 * mean,
                 qPrintable(QString::number(report.surfaceToTarget.mean)));
        QVERIFY(std::abs(report.surfaceToTarget.max - 90.0) < 1e-3);
        QCOMPARE(report.coverage, 0.0);
    }

    void coverageCountsPointsWithinTolerance() {
        const CompositeSurface surface = makeExample("cylinder").surfaces.front();
        const std::vector<Strip> strips = stripsOf(surface);
        std::vector<double> gaps;
        for (int i = 0; i < 40; ++i) {
            // Half within 1 mm, half 30 mm or more away.
            gaps.push_back(i % 2 ? 0.9 * std::sin(i) : 30.0 + i);
        }
        const Offsets target = offsetsFrom(strips, gaps, 17);
        const DistanceReport report = measureDistance(surface, target.points, {1.0, 8});
        QCOMPARE(report.coverage, 0.5);
        const DistanceReport loose = measureDistance(surface, target.points, {100.0, 8});
        QCOMPARE(loose.coverage, 1.0);
        // The default tolerance is 1 % of the target's diagonal.
        const DistanceReport byDefault = measureDistance(surface, target.points);
        QCOMPARE(byDefault.tolerance, 0.01 * byDefault.diagonal);
    }

    void refusesWhatItCannotMeasure() {
        const CompositeSurface surface = makeExample("sheet").surfaces.front();
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, measureDistance(surface, {}));
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument,
                                 measureDistance(surface, {Vec3(NAN, 0, 0)}));
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument,
                                 measureDistance(std::vector<CompositeSurface>{}, {Vec3()}));
        QVERIFY_THROWS_EXCEPTION(ModelError, measureDistance(surface, {Vec3()}, {0.0, 0}));
        // Two surfaces: the distance is to the nearer one.
        CompositeSurface lifted = surface;
        devsurf::test::transformSurface(lifted, [](const Vec3& p) { return p + Vec3(0, 0, 10); });
        const DistanceReport report =
            measureDistance(std::vector<CompositeSurface>{surface, lifted}, {Vec3(150, 150, 7)});
        QVERIFY(std::abs(report.targetDistances.front() - 3.0) < 1e-9);
    }

    void manyPointsAreMeasuredInParallel() {
        // 3,600 points 6 mm above and below the flat 300 × 300 mm sheet: more than 1,024 per
        // thread on two cores, so the measurement runs in threads (the test command runs this
        // under ThreadSanitizer). Every point is exactly 6 mm away, whichever thread took it.
        const CompositeSurface surface = makeExample("sheet").surfaces.front();
        std::vector<Vec3> target;
        for (int i = 0; i < 60; ++i) {
            for (int j = 0; j < 60; ++j) {
                target.emplace_back(15.0 + 4.5 * i, 15.0 + 4.5 * j, (i + j) % 2 ? 6.0 : -6.0);
            }
        }
        const DistanceReport report = measureDistance(surface, target, {1.0, 4});
        QCOMPARE(report.targetDistances.size(), target.size());
        for (std::size_t i = 0; i < target.size(); ++i) {
            QVERIFY2(std::abs(report.targetDistances[i] - 6.0) < 1e-9,
                     qPrintable(QString::number(i)));
        }
        QVERIFY(std::abs(report.targetToSurface.mean - 6.0) < 1e-9);
        QCOMPARE(report.coverage, 0.0);
    }

    void aSetCancelFlagStopsTheMeasurement() {
        const CompositeSurface surface = makeExample("sheet").surfaces.front();
        const std::vector<Vec3> target{Vec3(10, 20, 5), Vec3(150, 150, -3)};
        std::atomic<bool> cancel{false};
        DistanceOptions options;
        options.cancel = &cancel;
        // Not set: the same report as without a flag.
        const DistanceReport measured = measureDistance(surface, target, options);
        QCOMPARE(measured.targetDistances, measureDistance(surface, target).targetDistances);
        cancel = true;
        QVERIFY_THROWS_EXCEPTION(DistanceCancelled, measureDistance(surface, target, options));
    }

    void surfaceToAMeshIsToItsTriangles() {
        // The square [0, 100]² of z = 0 as two triangles on its four corners, and a flat strip
        // over [10, 90]² one mm above it: every surface point is 1 mm from the mesh, while its
        // nearest corner is at least 14 mm away.
        const std::vector<Vec3> corners = {Vec3(0, 0, 0), Vec3(100, 0, 0), Vec3(100, 100, 0),
                                           Vec3(0, 100, 0)};
        const std::vector<std::array<int, 3>> triangles = {{0, 1, 2}, {0, 2, 3}};
        std::vector<Vec3> grid;
        for (int i = 0; i <= 8; ++i) {
            for (int j = 0; j <= 8; ++j) {
                grid.emplace_back(10.0 + 10.0 * i, 10.0 + 10.0 * j, 1.0);
            }
        }
        const CompositeSurface strip = initialStrip(grid, {3, 2, 2}, 0.0);
        DistanceOptions options;
        options.triangles = &triangles;
        const DistanceReport mesh = measureDistance(strip, corners, options);
        QVERIFY(std::abs(mesh.surfaceToTarget.mean - 1.0) < 1e-9);
        QVERIFY(std::abs(mesh.surfaceToTarget.max - 1.0) < 1e-9);
        const DistanceReport vertices = measureDistance(strip, corners);
        QVERIFY(vertices.surfaceToTarget.mean > 14.0);
        // Target → surface is over the target points either way.
        QCOMPARE(mesh.targetToSurface.mean, vertices.targetToSurface.mean);
        const std::vector<std::array<int, 3>> broken = {{0, 1, 4}};
        options.triangles = &broken;
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, measureDistance(strip, corners, options));
    }
};

DEVSURF_REGISTER_TEST(TstDistanceReport);
#include "tst_distance_report.moc"
