// The initial strips of §4.2: a flat trapezoid over the PCA plane of points, the cylinder that
// fits them best, and the clusters that split a shape for several strips.

#include "model/reference/distance_report.h"
#include "model/reference/initial_strip.h"
#include "sampled_developability.h"
#include "test_registry.h"

#include <QTest>

#include <cmath>
#include <stdexcept>

using namespace devsurf::model;
using namespace devsurf::model::reference;

namespace {

std::vector<Vec3> grid(const Vec3& origin, const Vec3& along, const Vec3& across, int nu, int nv) {
    std::vector<Vec3> points;
    for (int i = 0; i <= nu; ++i) {
        for (int j = 0; j <= nv; ++j) {
            points.push_back(origin + along * (static_cast<double>(i) / nu) +
                             across * (static_cast<double>(j) / nv));
        }
    }
    return points;
}

} // namespace

class TstInitialStrip : public QObject {
    Q_OBJECT

private slots:
    void flatStripCoversItsPoints() {
        for (double scale : {1e-3, 1.0, 1e3}) {
            const std::vector<Vec3> points = grid(Vec3(5, 10, 0) * scale, Vec3(100, 0, 0.2) * scale,
                                                  Vec3(0, 40, -0.1) * scale, 10, 6);
            const CompositeSurface strip = initialStrip(points, {3, 2, 4}, 0.05);
            QVERIFY(strip.validate().empty());
            QCOMPARE(static_cast<int>(strip.faces().size()), 1);
            const DistanceReport report = measureDistance(strip, points);
            QVERIFY(report.targetToSurface.max < 1e-9 * scale);
            QCOMPARE(report.coverage, 1.0);
            // Larger than the points' extent by the margin: 5 % of 100 and of 40 beyond.
            QVERIFY(report.surfaceToTarget.max > 2.0 * scale);
            QVERIFY(report.surfaceToTarget.max < 6.0 * scale);
        }
    }

    void eachCurveSpansItsHalfOfTheFootprint() {
        // A trapezoid of points in the plane z = 0: 100 mm wide at y = 0, 50 mm at y = 40 (as a
        // cone patch's footprint). Curve a (y < 20) spans the wide half, b the narrow half.
        std::vector<Vec3> points;
        for (int j = 0; j <= 8; ++j) {
            const double y = 5.0 * j;
            const double half = 50.0 - 25.0 * y / 40.0;
            for (int i = 0; i <= 20; ++i) {
                points.emplace_back(-half + 2.0 * half * i / 20.0, y, 0.0);
            }
        }
        const CompositeSurface strip = initialStrip(points, {3, 2, 4}, 0.0);
        QVERIFY(strip.validate().empty());
        // The vertices a0, a1, b1, b0: their extents along the curves (x) on each side (y).
        double wideSide = 0.0, narrowSide = 0.0;
        for (VertexId v = 0; v < 4; ++v) {
            const Vec3 p = strip.position(v);
            QVERIFY(std::abs(p.z) < 1e-9);
            (p.y < 20.0 ? wideSide : narrowSide) += std::abs(p.x);
        }
        // |x| of both ends: the widest point of each half, at y = 0 (50 mm) and at y = 20
        // (37.5 mm); the plain rectangle had 50 on both sides.
        QVERIFY2(std::abs(wideSide - 100.0) < 1e-9, qPrintable(QString::number(wideSide)));
        QVERIFY2(std::abs(narrowSide - 75.0) < 1e-9, qPrintable(QString::number(narrowSide)));
        // It still covers every point, and overhangs the narrow end by half as much.
        const DistanceReport report = measureDistance(strip, points);
        QVERIFY(report.targetToSurface.max < 1e-9);
        QCOMPARE(report.coverage, 1.0);
    }

    void stripOnACylinderRunsAcrossItsRulings() {
        // A patch of the cylinder of radius 100 about the z-axis, ±30° around (105 mm of arc)
        // and 200 mm tall: its longest axis is the cylinder's, along its rulings.
        std::vector<Vec3> points;
        std::vector<Vec3> normals;
        for (int i = 0; i <= 20; ++i) {
            const double phi = (i / 10.0 - 1.0) * 0.5235987755982988;
            for (int j = 0; j <= 40; ++j) {
                points.emplace_back(100 * std::cos(phi), 100 * std::sin(phi), 5.0 * j);
                // Either sign, as a plane fit gives them.
                normals.push_back(Vec3(std::cos(phi), std::sin(phi), 0) * (j % 2 ? 1.0 : -1.0));
            }
        }
        const auto curveDirection = [](const CompositeSurface& strip) {
            const Vec3 a0 = strip.position(0);
            const Vec3 a1 = strip.position(1);
            return (a1 - a0) / (a1 - a0).norm();
        };
        const Vec3 axis(0, 0, 1);
        // Without normals a and b run along the longest axis, across the bend.
        const CompositeSurface plain = initialStrip(points, {3, 2, 4});
        QVERIFY(std::abs(dot(curveDirection(plain), axis)) > 0.99);
        // With them a and b run around the cylinder and the rulings along its axis.
        const CompositeSurface turned = initialStrip(points, normals, {3, 2, 4});
        QVERIFY(turned.validate().empty());
        QVERIFY(std::abs(dot(curveDirection(turned), axis)) < 0.01);
        const DistanceReport report = measureDistance(turned, points);
        // Every point lies over the rectangle, at most the arc's sagitta (13.4 mm) off it.
        QVERIFY(report.targetToSurface.max < 13.4);
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument,
                                 initialStrip(points, {Vec3(1, 0, 0)}, {3, 2, 4}));
    }

    void stripOnASphereKeepsTheLongestAxis() {
        // A cap of the sphere of radius 100, 60 × 30 mm: its normals turn alike in every
        // direction, so they give no ruling direction and the strip is the plain one.
        std::vector<Vec3> points;
        std::vector<Vec3> normals;
        for (int i = -15; i <= 15; ++i) {
            for (int j = -7; j <= 7; ++j) {
                const Vec3 p(2.0 * i, 2.0 * j, 0.0);
                const Vec3 n = Vec3(p.x, p.y, std::sqrt(100.0 * 100.0 - p.squaredNorm())) / 100.0;
                points.push_back(n * 100.0);
                normals.push_back(n);
            }
        }
        const CompositeSurface plain = initialStrip(points, {3, 2, 4});
        const CompositeSurface withNormals = initialStrip(points, normals, {3, 2, 4});
        for (VertexId v = 0; v < 4; ++v) {
            QVERIFY((plain.position(v) - withNormals.position(v)).norm() < 1e-12);
        }
    }

    void refusesPointsWithoutAPlane() {
        const std::vector<Vec3> line = grid(Vec3(0, 0, 0), Vec3(1, 2, 3), Vec3(0, 0, 0), 5, 1);
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, initialStrip(line, {3, 2, 4}));
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument,
                                 initialStrip({Vec3(0, 0, 0), Vec3(1, 0, 0)}, {3, 2, 4}));
        const std::vector<Vec3> plane = grid(Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), 3, 3);
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, initialStrip(plane, {3, 2, 4}, -1.0));
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, clusterPoints(plane, 0));
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, clusterPoints(plane, 6));
    }

    void clustersAreCompactPatches() {
        // Three separate squares of points far apart: three clusters, one per square, whatever
        // the order of the points.
        std::vector<Vec3> points;
        for (const Vec3& origin : {Vec3(0, 0, 0), Vec3(500, 0, 0), Vec3(0, 500, 100)}) {
            const std::vector<Vec3> square = grid(origin, Vec3(40, 0, 0), Vec3(0, 40, 0), 5, 5);
            points.insert(points.end(), square.begin(), square.end());
        }
        const auto clusters = clusterPoints(points, 3);
        QCOMPARE(static_cast<int>(clusters.size()), 3);
        std::size_t total = 0;
        for (const auto& cluster : clusters) {
            QCOMPARE(cluster.size(), std::size_t(36));
            total += cluster.size();
            for (std::size_t i : cluster) {
                QVERIFY((points[i] - points[cluster.front()]).norm() < 60.0);
            }
        }
        QCOMPARE(total, points.size());
        // A long strip of points in two: halves, not interleaved.
        const std::vector<Vec3> line = grid(Vec3(0, 0, 0), Vec3(0, 200, 0), Vec3(10, 0, 0), 20, 4);
        for (const auto& half : clusterPoints(line, 2)) {
            double low = 1e9;
            double high = -1e9;
            for (std::size_t i : half) {
                low = std::min(low, line[i].y);
                high = std::max(high, line[i].y);
            }
            QVERIFY(high - low < 120.0);
        }
    }

    void bandsWhereTheShapeCurvesBothWays() {
        // 80° × 80° of a sphere of radius 100 mm (its normals are the points' directions) in 4
        // groups: compact groups are about as wide as long, bands about twice (four bands
        // cannot all be three times as long as wide on a square).
        std::vector<Vec3> points;
        for (int i = 0; i <= 40; ++i) {
            for (int j = 0; j <= 40; ++j) {
                const double theta = (-40.0 + 2.0 * i) * M_PI / 180.0;
                const double phi = (-40.0 + 2.0 * j) * M_PI / 180.0;
                points.emplace_back(100.0 * std::cos(phi) * std::sin(theta),
                                    100.0 * std::cos(phi) * std::cos(theta), 100.0 * std::sin(phi));
            }
        }
        const std::vector<Vec3> normals = points; // either length
        const auto elongation = [&](const std::vector<std::size_t>& group) {
            std::vector<Vec3> members;
            for (std::size_t i : group) {
                members.push_back(points[i]);
            }
            const PrincipalFrame f = principalFrame(members);
            return (f.high[0] - f.low[0]) / (f.high[1] - f.low[1]);
        };
        const auto compact = clusterPoints(points, normals, 4, 1.0);
        QCOMPARE(compact, clusterPoints(points, 4));
        for (const auto& group : compact) {
            QVERIFY(elongation(group) < 1.5);
        }
        const auto bands = clusterPoints(points, normals, 4, 3.0);
        QCOMPARE(static_cast<int>(bands.size()), 4);
        std::size_t total = 0;
        for (const auto& group : bands) {
            total += group.size();
            QVERIFY2(elongation(group) > 1.7, qPrintable(QString::number(elongation(group))));
        }
        QCOMPARE(total, points.size());
    }

    void compactWhereTheShapeCurvesOneWay() {
        // A circular cylinder (radius 100 about the z-axis, ±60° around, 240 mm high) and a
        // plane: a strip fits any width of them, so the groups stay those of clusterPoints.
        std::vector<Vec3> points;
        std::vector<Vec3> normals;
        for (int i = 0; i <= 40; ++i) {
            const double phi = (2.0 * i / 40 - 1.0) * M_PI / 3.0;
            for (int j = 0; j <= 48; ++j) {
                points.emplace_back(100.0 * std::cos(phi), 100.0 * std::sin(phi), 5.0 * j);
                normals.emplace_back(std::cos(phi), std::sin(phi), 0.0);
            }
        }
        QCOMPARE(clusterPoints(points, normals, 4, 3.0), clusterPoints(points, 4));
        const std::vector<Vec3> plane =
            grid(Vec3(0, 0, 0), Vec3(120, 0, 0), Vec3(0, 120, 0), 24, 24);
        const std::vector<Vec3> up(plane.size(), Vec3(0, 0, 1));
        QCOMPARE(clusterPoints(plane, up, 4, 3.0), clusterPoints(plane, 4));
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, clusterPoints(plane, up, 4, 0.5));
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument,
                                 clusterPoints(plane, std::vector<Vec3>(3, Vec3(0, 0, 1)), 4, 2.0));
    }

    void cylinderStripLiesOnAParabolicCylinder() {
        // Points of the cylinder z = x² / 200 + 0.1 y (a parabola along x, tilted rulings along
        // y), in a frame turned about z: the cylinder start passes through them, is developable
        // (sampled det, from the splines) and reaches no farther than the points.
        const double c = std::cos(0.4);
        const double s = std::sin(0.4);
        std::vector<Vec3> points;
        std::vector<Vec3> normals;
        for (int i = 0; i <= 30; ++i) {
            for (int j = 0; j <= 12; ++j) {
                const double x = -60.0 + 4.0 * i;
                const double y = -40.0 + 80.0 * j / 12;
                const Vec3 n = Vec3(-x / 100.0, -0.1, 1.0);
                points.emplace_back(c * x - s * y, s * x + c * y, x * x / 200.0 + 0.1 * y);
                normals.push_back(Vec3(c * n.x - s * n.y, s * n.x + c * n.y, n.z) / n.norm());
            }
        }
        const CompositeSurface strip = initialCylinderStrip(points, normals, {3, 2, 2}, 0.0);
        QVERIFY(strip.validate().empty());
        QVERIFY(devsurf::test::sampledDevelopability(strip) < 1e-10);
        const DistanceReport report = measureDistance(strip, points);
        QVERIFY2(report.targetToSurface.max < 1e-6,
                 qPrintable(QString::number(report.targetToSurface.max)));
        QCOMPARE(report.coverage, 1.0);
        // Within half a grid cell's diagonal (4 × 6.7 mm) of a point everywhere: no margin.
        QVERIFY(report.surfaceToTarget.max < 4.5);
        // The flat strip over the same points is mm away (the parabola's sag is 18 mm).
        QVERIFY(measureDistance(initialStrip(points, normals, {3, 2, 2}, 0.0), points)
                    .targetToSurface.max > 5.0);
        // Refused as the flat strip: points on a line.
        const std::vector<Vec3> line = grid(Vec3(0, 0, 0), Vec3(1, 2, 3), Vec3(0, 0, 0), 5, 1);
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, initialCylinderStrip(line, {}, {3, 2, 4}));
    }
};

DEVSURF_REGISTER_TEST(TstInitialStrip);
#include "tst_initial_strip.moc"
