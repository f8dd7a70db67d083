#include "folded_strip.h"
#include "solver_test_models.h"

#include "model/examples.h"
#include "solver/quality/quality_measures.h"
#include "solver/quality/shape_change.h"

#include "test_registry.h"

#include <QTest>

#include <cmath>

using namespace devsurf;
using namespace devsurf::solver;
using model::Vec3;

namespace {

// One strip between the segments a(u) = (u, 0, 0) and b(u) = (u, 1, h·u) (degree 1): a
// hyperbolic paraboloid, sampled as a single quad with one sample per interval.
model::CompositeSurface twistedQuad(double h) {
    const model::SplineSpace space{1, 0, 1};
    model::CompositeSurface s;
    const auto a0 = s.addVertex({0, 0, 0});
    const auto a1 = s.addVertex({1, 0, 0});
    const auto b1 = s.addVertex({1, 1, h});
    const auto b0 = s.addVertex({0, 1, 0});
    s.addFace({a0, a1, b1, b0});
    s.setSpline(a0, a1, space, {{0, 0, 0}, {1, 0, 0}});
    s.setSpline(b0, b1, space, {{0, 1, 0}, {1, 1, h}});
    return s;
}

} // namespace

class TstQuality : public QObject {
    Q_OBJECT

private slots:
    void flatExamplesAreExact() {
        for (const char* name : {"sheet", "annulus", "mixed"}) {
            const QualityMeasures q = measureQuality(model::makeExample(name).surfaces.front());
            QVERIFY(q.quads > 0);
            QVERIFY2(q.flatnessMax < 1e-12, name);
            QVERIFY2(q.curvatureMax < 1e-12, name);
            QVERIFY2(q.developabilityMax < 1e-12, name);
        }
    }

    void twistedQuadFlatnessAndDeterminant() {
        for (double h : {1e-3, 0.1, 1.0}) {
            QualityOptions options;
            options.meshSamplesPerInterval = 1;
            const QualityMeasures q = measureQuality(twistedQuad(h), options);
            QCOMPARE(q.quads, 1);
            // Diagonals (0,0,0)-(1,1,h) and (1,0,0)-(0,1,0): distance h / √(2h² + 4); the two
            // shortest edges have length 1.
            QVERIFY(std::abs(q.flatnessMax - h / std::sqrt(2 * h * h + 4)) < 1e-14);
            // det(a − b, a′, b′) = h; |a − b| = √(1 + h²u²), |a′| = 1, |b′| = √(1 + h²); the
            // largest value is at the smallest sample u = 0.5 / 50.
            const double u = 0.5 / 50.0;
            const double expected = h / (std::sqrt(1 + h * h * u * u) * std::sqrt(1 + h * h));
            QVERIFY(std::abs(q.developabilityMax - expected) < 1e-14);
            QCOMPARE(q.developabilitySamples, 50);
        }
    }

    void foldOversFindAPatchFoldedBackOntoItself() {
        const auto folded = foldOvers(test::flatStrip(-150.0));
        QCOMPARE(folded.size(), std::size_t{1});
        QCOMPARE(folded.front().first, model::FaceId{0});
        // b crosses a twice, between the samples u = 1/8 and 2/8 and between 6/8 and 7/8.
        QCOMPARE(folded.front().second, 2);
        QCOMPARE(
            measureShapeChange(test::flatStrip(100.0), test::flatStrip(-150.0)).foldOverPlaces(),
            2);
        QCOMPARE(
            measureShapeChange(test::flatStrip(-150.0), test::flatStrip(100.0)).foldOverPlaces(),
            0);
        // Flat, bent or folded along creases, but never back onto itself.
        QVERIFY(foldOvers(test::flatStrip(100.0)).empty());
        for (const char* name : {"sheet", "annulus", "cylinder", "mixed", "fig6", "fig8"}) {
            QVERIFY2(foldOvers(model::makeExample(name).surfaces.front()).empty(), name);
        }
        QVERIFY(foldOvers(testing::makeGeneralizedCylinder(1.0)).empty());
    }

    void generalizedCylinderIsDevelopable() {
        for (double scale : {1e-3, 1.0, 1e3}) {
            const QualityMeasures q = measureQuality(testing::makeGeneralizedCylinder(scale));
            QVERIFY(q.developabilityMax < 1e-12);
            QVERIFY(q.flatnessMax > 0.0); // sampled quads of a curved cylinder are not flat
        }
    }

    void bentVertexHasGaussCurvature() {
        // Lift the centre vertex of a 2 × 2 sheet: the angle sum there drops below 2π.
        model::CompositeSurface sheet = model::makeExample("sheet", 2).surfaces.front();
        sheet.moveVertex(4, sheet.position(4) + Vec3(0, 0, 40));
        const QualityMeasures q = measureQuality(sheet);
        QVERIFY(q.curvatureMax > 1e-2);
        QVERIFY(q.developabilityMax > 1e-3);
    }
};

DEVSURF_REGISTER_TEST(TstQuality);
#include "tst_quality.moc"
