// Strips trimmed back where they overhang their reference shape: the overhang of a point, the
// trim judged on a strip, and the trimmed strip on the surface it was cut from.

#include "model/example_shapes.h"
#include "model/reference/distance_report.h"
#include "model/reference/initial_strip.h"
#include "model/reference/strip_trim.h"
#include "model/strip.h"
#include "sampled_developability.h"
#include "test_registry.h"

#include <QTest>

#include <cmath>
#include <stdexcept>

using namespace devsurf::model;
using namespace devsurf::model::reference;

namespace {

// Points every `step` mm over [0, width] × [0, height] of the plane z = 0.
std::vector<Vec3> planeGrid(double width, double height, double step) {
    std::vector<Vec3> points;
    for (int i = 0; i * step <= width + 1e-9; ++i) {
        for (int j = 0; j * step <= height + 1e-9; ++j) {
            points.emplace_back(i * step, j * step, 0.0);
        }
    }
    return points;
}

// Points of the cylinder z = x² / 200 over [−60, 60] × [−40, 40], with their normals.
void parabolicCylinder(std::vector<Vec3>& points, std::vector<Vec3>& normals) {
    for (int i = 0; i <= 30; ++i) {
        for (int j = 0; j <= 16; ++j) {
            const double x = -60.0 + 4.0 * i;
            const double y = -40.0 + 5.0 * j;
            points.emplace_back(x, y, x * x / 200.0);
            normals.push_back(Vec3(-x / 100.0, 0.0, 1.0) / Vec3(-x / 100.0, 0.0, 1.0).norm());
        }
    }
}

} // namespace

class TstStripTrim : public QObject {
    Q_OBJECT

private slots:
    void overhangIsOffTheShapeNotBetweenItsPoints() {
        std::vector<Vec3> points = planeGrid(100, 100, 5);
        const OverhangMeasure overhang(points, std::vector<Vec3>(points.size(), Vec3(0, 0, -1)),
                                       5.0);
        // Over the gap between four points, 3 mm above the plane: 3 mm off it.
        QVERIFY(std::abs(overhang(Vec3(52.5, 52.5, 3.0)) - 3.0) < 1e-12);
        // 20 mm beyond its edge: 15 mm beyond the spacing; and 4 mm above that.
        QVERIFY(std::abs(overhang(Vec3(120, 50, 0)) - 15.0) < 1e-12);
        QVERIFY(std::abs(overhang(Vec3(120, 50, 4)) - std::hypot(15.0, 4.0)) < 1e-12);
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, OverhangMeasure({}, {}, 1.0));
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, OverhangMeasure(points, {}, 1.0));
        QVERIFY_THROWS_EXCEPTION(
            std::invalid_argument,
            OverhangMeasure(points, std::vector<Vec3>(points.size(), Vec3(0, 0, 1)), -1.0));
    }

    void aStripIsTrimmedBackToThePointsItLiesOn() {
        // A flat strip over 160 × 40 mm, the shape only its first 100 mm: the 60 mm beyond are
        // cut, to the step, and nothing else.
        const std::vector<Vec3> shape = planeGrid(100, 40, 2.5);
        const OverhangMeasure overhang(shape, std::vector<Vec3>(shape.size(), Vec3(0, 0, 1)), 2.5);
        const CompositeSurface strip = initialStrip(planeGrid(160, 40, 2.5), {3, 2, 2}, 0.0);
        QVERIFY(measureDistance(strip, shape).surfaceToTarget.max > 55.0);
        const std::optional<StripTrim> trim = overhangTrim(strip, overhang, 1.0);
        QVERIFY(trim && trim->trims());
        QCOMPARE(trim->u1 - trim->u0, 20.0 / 32.0); // 100 of 160 mm
        QCOMPARE(trim->kept(), 20.0 / 32.0);
        QCOMPARE(trim->w0[0], 0.0);
        QCOMPARE(trim->w0[1], 0.0);
        QCOMPARE(trim->w1[0], 1.0);
        QCOMPARE(trim->w1[1], 1.0);
        const CompositeSurface trimmed = trimmedStrip(strip, *trim);
        QVERIFY(trimmed.validate().empty());
        QCOMPARE(trimmed.name(), strip.name());
        const DistanceReport report = measureDistance(trimmed, shape);
        QVERIFY2(report.surfaceToTarget.max < 2.0,
                 qPrintable(QString::number(report.surfaceToTarget.max)));
        QVERIFY(report.targetToSurface.max < 1e-9);
        QCOMPARE(report.coverage, 1.0);
        // Over its points only, the strip stays whole; a tolerance beyond any overhang too.
        QVERIFY(!overhangTrim(initialStrip(shape, {3, 2, 2}, 0.0), overhang, 1.0)->trims());
        QVERIFY(!overhangTrim(strip, overhang, 100.0)->trims());
    }

    void aCornerOffTheShapeIsCutAskew() {
        // The shape is the strip's footprint but for the triangle beyond the line from
        // (100, 40) to (160, 0): the trim cuts a corner, not the whole end of the strip.
        std::vector<Vec3> shape;
        for (const Vec3& p : planeGrid(160, 40, 2.5)) {
            if (p.x <= 100.0 + 1e-9 || p.y <= 40.0 * (160.0 - p.x) / 60.0 + 1e-9) {
                shape.push_back(p);
            }
        }
        const OverhangMeasure overhang(shape, std::vector<Vec3>(shape.size(), Vec3(0, 0, 1)), 2.5);
        const CompositeSurface strip = initialStrip(planeGrid(160, 40, 2.5), {3, 2, 2}, 0.0);
        const std::optional<StripTrim> trim = overhangTrim(strip, overhang, 1.0);
        QVERIFY(trim && trim->trims());
        QVERIFY(trim->w0[0] != trim->w0[1] || trim->w1[0] != trim->w1[1]);
        const DistanceReport before = measureDistance(strip, shape);
        const DistanceReport after = measureDistance(trimmedStrip(strip, *trim), shape);
        QVERIFY2(
            after.surfaceToTarget.max < 0.5 * before.surfaceToTarget.max,
            qPrintable(
                QString("%1 %2").arg(after.surfaceToTarget.max).arg(before.surfaceToTarget.max)));
        // More of the shape kept than by cutting the whole end back to x = 100 (4000 of the
        // 5200 mm² of the shape, 0.77).
        QVERIFY2(after.coverage > 0.8, qPrintable(QString::number(after.coverage)));
    }

    void aTrimAcrossKeepsTheSurfaceExactly() {
        std::vector<Vec3> points;
        std::vector<Vec3> normals;
        parabolicCylinder(points, normals);
        const CompositeSurface strip = initialCylinderStrip(points, normals, {3, 2, 2}, 0.0);
        const Strip whole = stripOfFace(strip, strip.faces().begin()->first);
        // Evenly across: the same rulings, exactly developable, its corners where they were.
        StripTrim even;
        even.w0[0] = even.w0[1] = 0.25;
        even.w1[0] = even.w1[1] = 0.75;
        const CompositeSurface band = trimmedStrip(strip, even);
        QVERIFY(band.validate().empty());
        QVERIFY(devsurf::test::sampledDevelopability(band) < 1e-10);
        const Strip cut = stripOfFace(band, band.faces().begin()->first);
        for (double t : {0.0, 0.3, 1.0}) {
            QVERIFY(distance(cut.point(t, 0.0), whole.point(t, 0.25)) < 1e-9);
            QVERIFY(distance(cut.point(t, 1.0), whole.point(t, 0.75)) < 1e-9);
        }
        // Along and askew: on the surface it was cut from, to the fit's accuracy.
        StripTrim askew;
        askew.u0 = 0.25;
        askew.u1 = 0.875;
        askew.w1[1] = 0.5;
        const CompositeSurface askewPart = trimmedStrip(strip, askew);
        const Strip part = stripOfFace(askewPart, askewPart.faces().begin()->first);
        QVERIFY(distance(part.point(0.0, 0.0), whole.point(0.25, 0.0)) < 1e-3);
        QVERIFY(distance(part.point(1.0, 1.0), whole.point(0.875, 0.5)) < 1e-3);
        for (double t = 0.0; t <= 1.0; t += 0.125) {
            for (double w : {0.0, 0.5, 1.0}) {
                const Vec3 p = part.point(t, w);
                QVERIFY2(std::abs(p.z - p.x * p.x / 200.0) < 1e-3, qPrintable(QString::number(t)));
            }
        }
        // Refused: an empty trim, one outside the strip, a surface of two strips.
        StripTrim empty;
        empty.u1 = 0.0;
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, trimmedStrip(strip, empty));
        StripTrim outside;
        outside.w1[0] = 1.5;
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, trimmedStrip(strip, outside));
    }

    void onlyAStripIsTrimmed() {
        // The sheet example (several strips in one surface): no trim, and trimming refused.
        const CompositeSurface two = example_shapes::makeSheet(2);
        QVERIFY(two.faces().size() > 1);
        const std::vector<Vec3> shape = planeGrid(100, 40, 5);
        const OverhangMeasure overhang(shape, std::vector<Vec3>(shape.size(), Vec3(0, 0, 1)), 5.0);
        QVERIFY(!overhangTrim(two, overhang, 1.0));
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, trimmedStrip(two, StripTrim{}));
    }
};

DEVSURF_REGISTER_TEST(TstStripTrim);
#include "tst_strip_trim.moc"
