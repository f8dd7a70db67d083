// Joining strips (§4.2, "Composite"): two surfaces side by side in one, and two boundary edges
// welded into one shared edge.

#include "model/model_error.h"
#include "model/strip_joining.h"
#include "model/topology_edits.h"
#include "test_registry.h"

#include "model/bspline_curve.h"

#include <QTest>

#include <cmath>

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

    void mergesTheTwoPartsOfASplitStripBack_data() {
        QTest::addColumn<int>("breakpoint");
        QTest::newRow("2 + 2 intervals") << 2;
        QTest::newRow("1 + 3 intervals") << 1;
    }

    void mergesTheTwoPartsOfASplitStripBack() {
        // A curved strip in S(4, 3, 2), cut at a ruling (exactly: two uniform pieces) and merged
        // again: the joined control sequences are the original ones.
        QFETCH(int, breakpoint);
        CompositeSurface strip;
        const SplineSpace space{3, 2, 4};
        std::vector<Vec3> a, b;
        for (int i = 0; i < space.controlPointCount(false); ++i) {
            a.emplace_back(25.0 * i, 3.0 * (i % 3), 0.4 * i * i);
            b.emplace_back(25.0 * i + 2.0, 40.0 + (i % 2), 5.0 - 0.3 * i);
        }
        const VertexId v0 = strip.addVertex(a.front());
        const VertexId v1 = strip.addVertex(a.back());
        const VertexId v2 = strip.addVertex(b.back());
        const VertexId v3 = strip.addVertex(b.front());
        const FaceId face = strip.addFace({v0, v1, v2, v3});
        strip.setSpline(v0, v1, space, a);
        strip.setSpline(v3, v2, space, b);
        QVERIFY(strip.validate().empty());
        const CompositeSurface split = splitAtRuling(strip, face, breakpoint);
        QCOMPARE(split.faces().size(), std::size_t(2));
        EdgeId ruling = kInvalidId;
        for (const auto& [id, record] : split.edges()) {
            if (!record.isSpline() && split.facesOfEdge(id).size() == 2) {
                ruling = id;
            }
        }
        QVERIFY(ruling != kInvalidId);
        const CompositeSurface merged = mergeStrips(split, ruling);
        QVERIFY(merged.validate().empty());
        QCOMPARE(merged.faces().size(), std::size_t(1));
        QCOMPARE(merged.vertices().size(), std::size_t(4));
        int curves = 0;
        for (const auto& [id, record] : merged.edges()) {
            if (!record.isSpline()) {
                continue;
            }
            ++curves;
            QCOMPARE(record.space, space);
            // The original curve with these ends, in the orientation they run.
            std::vector<Vec3> original = record.controlPoints.front() == a.front() ? a
                                         : record.controlPoints.front() == a.back()
                                             ? std::vector<Vec3>(a.rbegin(), a.rend())
                                         : record.controlPoints.front() == b.front()
                                             ? b
                                             : std::vector<Vec3>(b.rbegin(), b.rend());
            for (std::size_t i = 0; i < original.size(); ++i) {
                QVERIFY((record.controlPoints[i] - original[i]).norm() < 1e-9);
            }
        }
        QCOMPARE(curves, 2);
        // A boundary ruling has a strip on one side only.
        EdgeId boundary = kInvalidId;
        for (const auto& [id, record] : merged.edges()) {
            boundary = record.isSpline() ? boundary : id;
        }
        try {
            mergeStrips(merged, boundary);
            QFAIL("a boundary ruling was merged");
        } catch (const ModelError& error) {
            QCOMPARE(error.problem().code, ProblemCode::MergeNeedsStrips);
        }
    }

    void weldsTwoStripsEndToEndAndMergesThem() {
        // The end ruling of one strip meets the start ruling of the other: welded, then merged
        // into one strip of 2 + 2 intervals whose curves pass through the welded vertices.
        const CompositeSurface one = flatStrip(Vec3(0, 0, 0), Vec3(100, 0, 0), Vec3(0, 40, 0), 2);
        const CompositeSurface two =
            flatStrip(Vec3(100.5, 0, 0), Vec3(100, 0, 0), Vec3(0, 40, 0), 2);
        const SurfacesSideBySide both = placeSideBySide(one, two);
        const Weld weld = weldEdges(both.surface, edgeNear(both.surface, Vec3(100, 20, 0), false),
                                    edgeNear(both.surface, Vec3(100.5, 20, 0), false));
        const CompositeSurface merged = mergeStrips(weld.surface, weld.shared);
        QVERIFY(merged.validate().empty());
        QCOMPARE(merged.faces().size(), std::size_t(1));
        for (const auto& [id, record] : merged.edges()) {
            if (record.isSpline()) {
                QCOMPARE(record.space.intervals, 4);
                const BSplineCurve curve =
                    BSplineCurve::uniform(record.space, record.controlPoints);
                // Straight along x from 0 to 200.5, through x = 100.25 at the weld.
                for (int i = 0; i <= 20; ++i) {
                    const Vec3 p = curve.evaluate(i / 20.0);
                    QVERIFY(std::abs(p.z) < 1e-12);
                    QVERIFY(std::abs(p.y) < 1e-9 || std::abs(p.y - 40.0) < 1e-9);
                }
                QVERIFY(std::abs(curve.evaluate(0.5).x - 100.25) < 0.2);
            }
        }
    }
};

DEVSURF_REGISTER_TEST(TstStripJoining);
#include "tst_strip_joining.moc"
