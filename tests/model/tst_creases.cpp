// The creases of a surface: left and right faces, which strip curve, normal orientation and
// mountain/valley, checked on a hand-built surface whose answer is known from its geometry.

#include "model/composite_surface.h"
#include "model/creases.h"
#include "model/sampled_mesh.h"
#include "model/strip.h"
#include "straight_control_points.h"
#include "test_registry.h"

#include <QtTest>

#include <cmath>

using namespace devsurf::model;

namespace {

// Two strips meeting along the crease p0 = (0,0,0) → p1 = (100,0,0): face "north" towards +y,
// face "south" towards −y, both loops counter-clockwise seen from +z (the normal side). The far
// curves are lifted by `lift` in z (north) and `lift` (south), so lift > 0 makes both faces rise
// towards the normal side: a valley; lift < 0 a mountain. `forward` stores the crease as
// p0 → p1 (north on its left) or p1 → p0 (south on its left).
struct TwoStrips {
    CompositeSurface surface;
    FaceId north = kInvalidId;
    FaceId south = kInvalidId;
    EdgeId crease = kInvalidId;
};

TwoStrips twoStrips(double lift, bool forward) {
    TwoStrips t;
    CompositeSurface& s = t.surface;
    const VertexId p0 = s.addVertex({0, 0, 0});
    const VertexId p1 = s.addVertex({100, 0, 0});
    const VertexId q0 = s.addVertex({0, 50, lift});
    const VertexId q1 = s.addVertex({100, 50, lift});
    const VertexId r0 = s.addVertex({0, -50, lift});
    const VertexId r1 = s.addVertex({100, -50, lift});
    t.north = s.addFace({p0, p1, q1, q0});
    t.south = s.addFace({p1, p0, r0, r1});
    const SplineSpace space{3, 2, 2};
    auto spline = [&](VertexId a, VertexId b) {
        return s.setSpline(
            a, b, space, devsurf::test::straightControlPoints(space, s.position(a), s.position(b)));
    };
    t.crease = forward ? spline(p0, p1) : spline(p1, p0);
    spline(q0, q1);
    spline(r1, r0);
    return t;
}

double centroidY(const CompositeSurface& s, FaceId face) {
    double y = 0.0;
    for (VertexId v : s.faceLoop(face)) {
        y += s.position(v).y;
    }
    return y / static_cast<double>(s.faceLoop(face).size());
}

} // namespace

class TstCreases : public QObject {
    Q_OBJECT

private slots:
    void leftAndRightFollowTheGeometry_data() {
        QTest::addColumn<bool>("forward");
        QTest::newRow("stored p0 to p1") << true;
        QTest::newRow("stored p1 to p0") << false;
    }

    void leftAndRightFollowTheGeometry() {
        QFETCH(bool, forward);
        const TwoStrips t = twoStrips(0.0, forward);
        QVERIFY(t.surface.validate().empty());
        const std::vector<Strip> strips = stripsOf(t.surface);
        const auto creases = creasesOf(t.surface, strips, sampleSurface(t.surface, 4));
        QCOMPARE(creases.size(), std::size_t(1));
        const Crease& crease = creases.front();
        QCOMPARE(crease.edge, t.crease);
        // Walking the edge from → to, seen from +z, the left face lies on the side of
        // z × direction.
        const EdgeRecord& record = t.surface.edge(crease.edge);
        const Vec3 direction = t.surface.position(record.to) - t.surface.position(record.from);
        const Vec3 leftward = cross(Vec3(0, 0, 1), direction);
        QVERIFY(leftward.y * centroidY(t.surface, crease.left.face) > 0.0);
        QVERIFY(leftward.y * centroidY(t.surface, crease.right.face) < 0.0);
        QCOMPARE(crease.left.face, forward ? t.north : t.south);

        for (const CreaseSide* side : {&crease.left, &crease.right}) {
            QVERIFY(side->strip != CreaseSide::kNoStrip);
            const Strip& strip = strips[side->strip];
            QCOMPARE(strip.face, side->face);
            // The named curve is the crease, and `reversed` says which end it starts at.
            const BSplineCurve& curve = side->sideA ? strip.a : strip.b;
            const Vec3 start = curve.evaluate(0.0);
            const Vec3 expected = t.surface.position(side->reversed ? record.to : record.from);
            QVERIFY((start - expected).norm() < 1e-12);
            QVERIFY(std::abs(curve.evaluate(0.5).y) < 1e-12);
            // Flipping as told orients the strip's normal a′ × (b − a) to +z.
            Vec3 n = cross(strip.a.derivative(0.5, 1), strip.bPoint(0.5) - strip.aPoint(0.5));
            if (side->flipNormal) {
                n = n * -1.0;
            }
            QVERIFY(n.z > 0.0);
        }
        QCOMPARE(crease.assignment, FoldAssignment::Flat);
        QCOMPARE(std::string(foldAssignmentLetter(crease.assignment)), std::string("F"));
    }

    void mountainValleyAndFlat_data() {
        QTest::addColumn<double>("lift");
        QTest::addColumn<bool>("forward");
        QTest::addColumn<QString>("letter");
        QTest::newRow("rising, forward") << 20.0 << true << "V";
        QTest::newRow("rising, backward") << 20.0 << false << "V";
        QTest::newRow("sinking, forward") << -20.0 << true << "M";
        QTest::newRow("sinking, backward") << -20.0 << false << "M";
        QTest::newRow("flat") << 0.0 << true << "F";
    }

    void mountainValleyAndFlat() {
        QFETCH(double, lift);
        QFETCH(bool, forward);
        QFETCH(QString, letter);
        const TwoStrips t = twoStrips(lift, forward);
        QVERIFY(t.surface.validate().empty());
        const auto creases = creasesOf(t.surface, stripsOf(t.surface), sampleSurface(t.surface, 4));
        QCOMPARE(creases.size(), std::size_t(1));
        const Crease& crease = creases.front();
        QCOMPARE(QString::fromLatin1(foldAssignmentLetter(crease.assignment)), letter);
        // Each face turns by atan(lift / 50) out of the plane: the fold angle is twice that.
        const double expected = 2.0 * std::atan(std::abs(lift) / 50.0) * 180.0 / M_PI;
        QVERIFY2(std::abs(std::abs(crease.foldAngleDegrees) - expected) < 1e-9,
                 qPrintable(QString::number(crease.foldAngleDegrees)));
        QVERIFY(std::abs(crease.maxFoldAngleDegrees - expected) < 1e-9);
        QVERIFY((lift > 0.0) == (crease.foldAngleDegrees < -kFlatFoldDegrees));
    }
};

DEVSURF_REGISTER_TEST(TstCreases);
#include "tst_creases.moc"
