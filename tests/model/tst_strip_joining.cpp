// Joining strips (§4.2, "Composite"): two surfaces side by side in one, and two boundary edges
// welded into one shared edge.

#include "model/model_error.h"
#include "model/strip_joining.h"
#include "test_registry.h"

#include <QTest>

using namespace devsurf::model;

namespace {

// A flat SRSR strip: curves from origin along `along` and from origin + across, rulings along
// `across`, each curve in S(intervals, 3, 2). `turned`: the face loop runs the other way.
CompositeSurface flatStrip(const Vec3& origin, const Vec3& along, const Vec3& across, int intervals,
                           bool turned = false) {
    CompositeSurface s;
    const VertexId v0 = s.addVertex(origin);
    const VertexId v1 = s.addVertex(origin + along);
    const VertexId v2 = s.addVertex(origin + along + across);
    const VertexId v3 = s.addVertex(origin + across);
    s.addFace(turned ? std::vector<VertexId>{v0, v3, v2, v1}
                     : std::vector<VertexId>{v0, v1, v2, v3});
    const SplineSpace space{3, 2, intervals};
    const int n = space.controlPointCount(false);
    auto line = [n](const Vec3& a, const Vec3& b) {
        std::vector<Vec3> points;
        for (int i = 0; i < n; ++i) {
            points.push_back(a + (b - a) * (static_cast<double>(i) / (n - 1)));
        }
        return points;
    };
    s.setSpline(v0, v1, space, line(origin, origin + along));
    s.setSpline(v3, v2, space, line(origin + across, origin + along + across));
    return s;
}

// The S-edge (or R-edge with `spline` false) of `surface` whose midpoint is nearest `point`.
EdgeId edgeNear(const CompositeSurface& surface, const Vec3& point, bool spline = true) {
    EdgeId best = kInvalidId;
    double distance = 1e300;
    for (const auto& [id, record] : surface.edges()) {
        const Vec3 middle = (surface.position(record.from) + surface.position(record.to)) * 0.5;
        if (record.isSpline() == spline && (middle - point).norm() < distance) {
            distance = (middle - point).norm();
            best = id;
        }
    }
    return best;
}

// The S-edges starting at height y.
std::vector<EdgeId> curvesAt(const CompositeSurface& surface, double y) {
    std::vector<EdgeId> curves;
    for (const auto& [id, record] : surface.edges()) {
        if (record.isSpline() && surface.position(record.from).y == y) {
            curves.push_back(id);
        }
    }
    return curves;
}

ProblemCode refusal(const CompositeSurface& surface, EdgeId a, EdgeId b) {
    try {
        weldEdges(surface, a, b);
    } catch (const ModelError& error) {
        return error.problem().code;
    }
    return ProblemCode::Internal;
}

} // namespace

class TstStripJoining : public QObject {
    Q_OBJECT

private slots:
    void sideBySideKeepsBothParts() {
        const CompositeSurface one = flatStrip(Vec3(0, 0, 0), Vec3(100, 0, 0), Vec3(0, 40, 0), 2);
        CompositeSurface two = flatStrip(Vec3(0, 50, 0), Vec3(100, 0, 0), Vec3(0, 40, 0), 3);
        two.setPinned(two.vertices().begin()->first, true);
        two.setName("strip 2");
        const SurfacesSideBySide both = placeSideBySide(one, two);
        QVERIFY(both.surface.validate().empty());
        QCOMPARE(both.surface.faces().size(), std::size_t(2));
        QCOMPARE(both.surface.vertices().size(), std::size_t(8));
        QCOMPARE(both.surface.pinnedVertices().size(), std::size_t(1));
        for (const auto& [id, record] : two.edges()) {
            const EdgeRecord& copy = both.surface.edge(both.edgeOfSecond.at(id));
            QCOMPARE(copy.label, record.label);
            QCOMPARE(copy.space, record.space);
            QVERIFY(copy.controlPoints == record.controlPoints);
        }
        QCOMPARE(both.surface.name(), std::string("strip 2"));
    }

    void weldsTwoCurvesIntoOneSharedCurve_data() {
        QTest::addColumn<bool>("turned");
        QTest::addColumn<int>("intervals");
        QTest::newRow("same orientation") << false << 2;
        QTest::newRow("turned over") << true << 2;
        QTest::newRow("refined to 4 intervals") << false << 4;
    }

    void weldsTwoCurvesIntoOneSharedCurve() {
        // Strip 2 starts 1 mm above strip 1's upper curve and runs the other way along x.
        QFETCH(bool, turned);
        QFETCH(int, intervals);
        const CompositeSurface one = flatStrip(Vec3(0, 0, 0), Vec3(100, 0, 0), Vec3(0, 40, 0), 2);
        const CompositeSurface two =
            flatStrip(Vec3(100, 40, 1), Vec3(-100, 0, 0), Vec3(0, 40, 0), intervals, turned);
        const SurfacesSideBySide both = placeSideBySide(one, two);
        const EdgeId upper = edgeNear(both.surface, Vec3(50, 40, 0));
        const EdgeId lower = edgeNear(both.surface, Vec3(50, 40, 1));
        QVERIFY(upper != lower);
        const Weld weld = weldEdges(both.surface, upper, lower);
        const std::vector<Problem> problems = weld.surface.validate();
        QVERIFY2(problems.empty(), problems.empty() ? "" : technicalKey(problems.front()).c_str());
        QVERIFY(weld.reversed);
        // Refined, strip 1's straight curve has unevenly spaced control points.
        QVERIFY(intervals == 2 ? weld.gap == 1.0 : weld.gap > 1.0 && weld.gap < 5.0);
        QCOMPARE(weld.flipped, !turned);
        QCOMPARE(weld.surface.vertices().size(), std::size_t(6));
        QCOMPARE(weld.surface.faces().size(), std::size_t(2));
        QCOMPARE(weld.surface.edges().size(), std::size_t(7));
        QCOMPARE(weld.edgeOf.size(), std::size_t(8));
        QCOMPARE(weld.edgeOf.at(upper), weld.shared);
        QCOMPARE(weld.edgeOf.at(lower), weld.shared);
        const EdgeRecord& shared = weld.surface.edge(weld.shared);
        QVERIFY(shared.isSpline());
        QCOMPARE(weld.surface.facesOfEdge(weld.shared).size(), std::size_t(2));
        QCOMPARE(shared.space.intervals, intervals);
        // The mean of the two curves: on y = 40, half a millimetre up.
        for (const Vec3& p : shared.controlPoints) {
            QCOMPARE(p.y, 40.0);
            QCOMPARE(p.z, 0.5);
        }
        // The other curves of the refined strip follow the shared one's space.
        for (const auto& [id, record] : weld.surface.edges()) {
            if (record.isSpline()) {
                QCOMPARE(record.space.intervals, intervals);
            }
        }
        // Both faces keep their S-edges: one shared curve, two boundary curves.
        int curves = 0;
        for (const auto& [id, record] : weld.surface.edges()) {
            curves += record.isSpline() ? 1 : 0;
        }
        QCOMPARE(curves, 3);
    }

    void weldsTwoRulingsEndToEnd() {
        const CompositeSurface one = flatStrip(Vec3(0, 0, 0), Vec3(100, 0, 0), Vec3(0, 40, 0), 2);
        const CompositeSurface two =
            flatStrip(Vec3(100.5, 0, 0), Vec3(100, 0, 0), Vec3(0, 40, 0), 2);
        const SurfacesSideBySide both = placeSideBySide(one, two);
        const EdgeId end = edgeNear(both.surface, Vec3(100, 20, 0), false);
        const EdgeId start = edgeNear(both.surface, Vec3(100.5, 20, 0), false);
        const Weld weld = weldEdges(both.surface, end, start);
        QVERIFY(weld.surface.validate().empty());
        QCOMPARE(weld.gap, 0.5);
        QVERIFY(!weld.flipped);
        QVERIFY(!weld.surface.edge(weld.shared).isSpline());
        QCOMPARE(weld.surface.facesOfEdge(weld.shared).size(), std::size_t(2));
        QCOMPARE(weld.surface.position(weld.surface.edge(weld.shared).from).x, 100.25);
        // The curves meeting at the merged vertices end there.
        for (const auto& [id, record] : weld.surface.edges()) {
            if (record.isSpline()) {
                QVERIFY(record.controlPoints.front() == weld.surface.position(record.from));
                QVERIFY(record.controlPoints.back() == weld.surface.position(record.to));
            }
        }
    }

    void refusesWhatCannotBeWelded() {
        const CompositeSurface one = flatStrip(Vec3(0, 0, 0), Vec3(100, 0, 0), Vec3(0, 40, 0), 2);
        // 6 mm apart: beyond 5 % of 100 mm.
        const SurfacesSideBySide far =
            placeSideBySide(one, flatStrip(Vec3(0, 46, 0), Vec3(100, 0, 0), Vec3(0, 40, 0), 2));
        const EdgeId upper = edgeNear(far.surface, Vec3(50, 40, 0));
        const EdgeId lower = edgeNear(far.surface, Vec3(50, 46, 0));
        QCOMPARE(refusal(far.surface, upper, lower), ProblemCode::EdgesTooFarApart);
        QCOMPARE(refusal(far.surface, upper, edgeNear(far.surface, Vec3(100, 66, 0), false)),
                 ProblemCode::WeldNeedsBoundaryEdges);
        QCOMPARE(refusal(far.surface, upper, upper), ProblemCode::WeldNeedsBoundaryEdges);
        QCOMPARE(refusal(far.surface, upper, edgeNear(far.surface, Vec3(50, 0, 0))),
                 ProblemCode::WeldNeedsBoundaryEdges); // the same face
        // 2 and 3 intervals have no common refinement by knot insertion.
        const SurfacesSideBySide spaces =
            placeSideBySide(one, flatStrip(Vec3(0, 40, 0), Vec3(100, 0, 0), Vec3(0, 40, 0), 3));
        const std::vector<EdgeId> middle = curvesAt(spaces.surface, 40.0);
        QCOMPARE(middle.size(), std::size_t(2));
        QCOMPARE(refusal(spaces.surface, middle[0], middle[1]), ProblemCode::CurveSpaceDiffers);
        // A shared edge is no boundary any more.
        const SurfacesSideBySide near =
            placeSideBySide(one, flatStrip(Vec3(0, 40, 0), Vec3(100, 0, 0), Vec3(0, 40, 0), 2));
        const std::vector<EdgeId> joint = curvesAt(near.surface, 40.0);
        QCOMPARE(joint.size(), std::size_t(2));
        const Weld weld = weldEdges(near.surface, joint[0], joint[1]);
        QCOMPARE(weld.gap, 0.0);
        QCOMPARE(refusal(weld.surface, weld.shared, edgeNear(weld.surface, Vec3(50, 0, 0))),
                 ProblemCode::WeldNeedsBoundaryEdges);
    }
};

DEVSURF_REGISTER_TEST(TstStripJoining);
#include "tst_strip_joining.moc"
