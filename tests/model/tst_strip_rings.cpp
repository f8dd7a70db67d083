// Rings laid one after another around a shape that closes around an axis
// (model/reference/strip_rings.h): which shapes close around an axis, and how near and how
// developable the rings lie as laid.

#include "model/pattern/cutting_pattern.h"
#include "model/project.h"
#include "model/reference/distance_report.h"
#include "model/reference/strip_rings.h"
#include "model/reference/thinning.h"
#include "model/strip_joining.h"
#include "sampled_developability.h"
#include "test_registry.h"

#include <QTest>

#include <cmath>
#include <map>
#include <stdexcept>

using namespace devsurf::model;
using namespace devsurf::model::reference;
using devsurf::test::sampledDevelopability;

namespace {

constexpr double kPi = 3.141592653589793;

struct Cloud {
    std::vector<Vec3> points;
    std::vector<Vec3> normals;
};

// The open tube of radius 100 about the z-axis from z = −120 to 120, its normals flipping sign
// from point to point (a scan's normals need not agree).
Cloud tube() {
    Cloud c;
    for (int j = 0; j <= 48; ++j) {
        for (int i = 0; i < 126; ++i) {
            const double phi = 2 * kPi * i / 126;
            c.points.emplace_back(100 * std::cos(phi), 100 * std::sin(phi), -120.0 + 5.0 * j);
            c.normals.push_back(Vec3(std::cos(phi), std::sin(phi), 0) * (i % 2 ? 1.0 : -1.0));
        }
    }
    return c;
}

// How many edges two faces share, and how many border one face only, of each kind.
struct EdgeCount {
    int sharedCurves = 0;
    int boundaryCurves = 0;
    int boundaryRulings = 0;
    bool sharedWithoutCondition = true;
};

EdgeCount countEdges(const CompositeSurface& s) {
    std::map<EdgeId, int> facesOf;
    for (const auto& [face, loop] : s.faces()) {
        (void)loop;
        for (EdgeId edge : s.faceEdges(face)) {
            ++facesOf[edge];
        }
    }
    EdgeCount count;
    for (const auto& [edge, record] : s.edges()) {
        if (facesOf[edge] == 2 && record.isSpline()) {
            ++count.sharedCurves;
            count.sharedWithoutCondition &= record.condition == CreaseCondition::None;
        } else if (facesOf[edge] == 1) {
            ++(record.isSpline() ? count.boundaryCurves : count.boundaryRulings);
        }
    }
    return count;
}

} // namespace

class TstStripRings : public QObject {
    Q_OBJECT

private slots:
    void ringsAroundATube() {
        const Cloud c = tube();
        const std::optional<Vec3> axis = tubeAxis(c.points, c.normals, 5.0);
        QVERIFY(axis.has_value());
        QVERIFY(std::abs(axis->z) > 0.999);
        const CompositeSurface rings = initialStripRings(c.points, c.normals, 5.0, 4, {3, 2, 4});
        QVERIFY(rings.validate().empty());
        QCOMPARE(static_cast<int>(rings.faces().size()), 4 * kRingSectors);
        QCOMPARE(static_cast<int>(surfaceParts(rings).size()), 1);
        // Three closed curves shared (of kRingSectors arcs each) and free to kink; open only at
        // the two end curves: no ruling is a boundary.
        const EdgeCount edges = countEdges(rings);
        QCOMPARE(edges.sharedCurves, 3 * kRingSectors);
        QVERIFY(edges.sharedWithoutCondition);
        QCOMPARE(edges.boundaryCurves, 2 * kRingSectors);
        QCOMPARE(edges.boundaryRulings, 0);
        const double off = measureDistance(rings, c.points).targetToSurface.max;
        qInfo("tube: four rings as laid, %.3g mm from it at most", off);
        QVERIFY2(off < 0.05, qPrintable(QString::number(off)));
        QVERIFY(sampledDevelopability(rings) < 1e-9);
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument,
                                 initialStripRings(c.points, c.normals, 5.0, 0, {3, 2, 4}));
    }

    void ringsOverAThinnedTube() {
        // The same tube thinned as the approximation thins it: the kept points and their PCA
        // normals no longer lie evenly around, yet the rings stay on the tube.
        const Cloud c = tube();
        const ThinningResult thinned = thinReference(c.points, 15.0);
        std::vector<Vec3> points;
        std::vector<Vec3> normals;
        for (const ThinnedPoint& p : thinned.points) {
            points.push_back(p.position);
            normals.push_back(p.normal);
        }
        const CompositeSurface rings = initialStripRings(points, normals, 15.0, 8, {3, 2, 4});
        const double off = measureDistance(rings, c.points).targetToSurface.max;
        qInfo("thinned tube: eight rings as laid, %.3g mm from it at most", off);
        QVERIFY2(off < 0.5, qPrintable(QString::number(off)));
        QVERIFY(sampledDevelopability(rings) < 1e-9);
        // Given the whole tube, the rings end at its rims (fitted 5 % beyond them, then
        // shortened along their cones), not ρ beyond.
        const CompositeSurface rimmed =
            initialStripRings(points, normals, 15.0, 8, {3, 2, 4}, kRingMargin, c.points);
        double low = 1e300;
        double high = -1e300;
        for (const auto& [vertex, position] : rimmed.vertices()) {
            (void)vertex;
            low = std::min(low, position.z);
            high = std::max(high, position.z);
        }
        QVERIFY2(std::abs(low + 120.0) < 1e-6 && std::abs(high - 120.0) < 1e-6,
                 qPrintable(QString("%1 %2").arg(low).arg(high)));
        QVERIFY(measureDistance(rimmed, c.points).targetToSurface.max < 0.5);
        QVERIFY(sampledDevelopability(rimmed) < 1e-9);
    }

    void aroundAnAxisOrNot() {
        // Half the tube is a patch: it does not close around.
        const Cloud whole = tube();
        Cloud half;
        for (std::size_t i = 0; i < whole.points.size(); ++i) {
            if (whole.points[i].x > 0.0) {
                half.points.push_back(whole.points[i]);
                half.normals.push_back(whole.normals[i]);
            }
        }
        QVERIFY(!tubeAxis(half.points, half.normals, 5.0));
        // A torus (R 100, r 30) about the z-axis: around that axis every angle sees two layers,
        // its inner and outer side; around an axis in its plane the slabs do not close around.
        Cloud torus;
        for (int i = 0; i < 120; ++i) {
            const double phi = 2 * kPi * i / 120;
            for (int j = 0; j < 40; ++j) {
                const double psi = 2 * kPi * j / 40;
                const Vec3 n(std::cos(psi) * std::cos(phi), std::cos(psi) * std::sin(phi),
                             std::sin(psi));
                torus.points.push_back(Vec3(100 * std::cos(phi), 100 * std::sin(phi), 0) +
                                       n * 30.0);
                torus.normals.push_back(n);
            }
        }
        QVERIFY(!tubeAxis(torus.points, torus.normals, 5.0));
        // Two tubes side by side: no one centre line in their slabs.
        Cloud pair;
        for (const double shift : {-150.0, 150.0}) {
            for (std::size_t i = 0; i < whole.points.size(); ++i) {
                pair.points.push_back(whole.points[i] + Vec3(shift, 0, 0));
                pair.normals.push_back(whole.normals[i]);
            }
        }
        QVERIFY(!tubeAxis(pair.points, pair.normals, 5.0));
        QVERIFY(!tubeAxis(whole.points, {}, 5.0));
        QVERIFY(!tubeAxis(whole.points, whole.normals, 0.0));
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument,
                                 initialStripRings(torus.points, torus.normals, 5.0, 4, {3, 2, 4}));
    }

    void ringsAroundAShortWideTubeAVaseAndASphere() {
        // A tube shorter than it is wide (its axis the points' shortest principal axis), a vase
        // of elliptic section on a tilted axis, a sphere: each thinned as the approximation
        // thins it, the rings as laid near it.
        struct Shape {
            const char* name;
            std::vector<Vec3> points;
            Vec3 axis;
            double bound;
        };
        std::vector<Shape> shapes;
        Shape squat{"short wide tube", {}, Vec3(0, 0, 1), 0.05};
        for (int j = 0; j <= 20; ++j) {
            for (int i = 0; i < 150; ++i) {
                const double phi = 2 * kPi * i / 150;
                squat.points.emplace_back(120 * std::cos(phi), 120 * std::sin(phi), -50.0 + 5 * j);
            }
        }
        shapes.push_back(squat);
        const double tilt = 0.4;
        Shape vase{"vase", {}, Vec3(0, -std::sin(tilt), std::cos(tilt)), 3.0};
        for (int j = 0; j <= 60; ++j) {
            const double z = -150.0 + 5 * j;
            const double size = 80 + 25 * std::sin(z / 50);
            for (int i = 0; i < 120; ++i) {
                const double phi = 2 * kPi * i / 120;
                const double x = size * std::cos(phi);
                const double y = 0.7 * size * std::sin(phi);
                vase.points.emplace_back(x, std::cos(tilt) * y - std::sin(tilt) * z,
                                         std::sin(tilt) * y + std::cos(tilt) * z);
            }
        }
        shapes.push_back(vase);
        Shape sphere{"sphere", {}, Vec3(), 12.0};
        for (int i = 0; i < 4000; ++i) {
            const double z = 1 - 2 * (i + 0.5) / 4000;
            const double r = std::sqrt(1 - z * z);
            const double phi = kPi * (3 - std::sqrt(5.0)) * i;
            sphere.points.emplace_back(100 * r * std::cos(phi), 100 * r * std::sin(phi), 100 * z);
        }
        shapes.push_back(sphere);
        for (const Shape& shape : shapes) {
            const double rho = 15.0;
            const ThinningResult thinned = thinReference(shape.points, rho);
            std::vector<Vec3> points;
            std::vector<Vec3> normals;
            for (const ThinnedPoint& p : thinned.points) {
                points.push_back(p.position);
                normals.push_back(p.normal);
            }
            const std::optional<Vec3> axis = tubeAxis(points, normals, rho);
            QVERIFY2(axis.has_value(), shape.name);
            const CompositeSurface rings = initialStripRings(points, normals, rho, 8, {3, 2, 4});
            QVERIFY(rings.validate().empty());
            const double off = measureDistance(rings, shape.points).targetToSurface.max;
            qInfo("%s: axis (%.3f, %.3f, %.3f), eight rings as laid, %.3g mm from it at most, det "
                  "%.2g",
                  shape.name, axis->x, axis->y, axis->z, off, sampledDevelopability(rings));
            if (shape.axis.norm() > 0) {
                QVERIFY(std::abs(dot(*axis, shape.axis)) > 0.999);
            }
            QVERIFY2(off < shape.bound, qPrintable(QString::number(off)));
            QVERIFY(sampledDevelopability(rings) < 1e-9);
        }
    }

    void ringsAroundASphereAreCutOneToAPiece() {
        // Rings of cones of different angles around a sphere do not develop as one sheet:
        // joined, the pattern would overlap itself or not close up. Cut along their shared
        // curves, each ring is one exact annular sector.
        std::vector<Vec3> points;
        std::vector<Vec3> normals;
        for (int i = 1; i < 30; ++i) {
            const double theta = kPi * i / 30;
            for (int j = 0; j < 60; ++j) {
                const double phi = 2 * kPi * j / 60;
                const Vec3 n(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi),
                             std::cos(theta));
                points.push_back(n * 100.0);
                normals.push_back(n);
            }
        }
        Project project;
        project.addSurface(initialStripRings(points, normals, 8.0, 5, {3, 2, 4}));
        const CuttingPattern pattern = buildCuttingPattern(project);
        QCOMPARE(pattern.pieces.size(), std::size_t(5));
        QVERIFY(pattern.overlaps.empty());
        for (const PatternPiece& piece : pattern.pieces) {
            QCOMPARE(piece.faces.size(), std::size_t(kRingSectors));
            QVERIFY2(piece.maxIsometryError < 1e-6,
                     qPrintable(QString::number(piece.maxIsometryError)));
        }
    }
};

DEVSURF_REGISTER_TEST(TstStripRings);
#include "tst_strip_rings.moc"
