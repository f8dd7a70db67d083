#include "model/examples.h"
#include "model/pattern/cutting_pattern.h"
#include "model/strip.h"
#include "solver/formulation/perturbation.h"
#include "solver/quality/crease_quality.h"
#include "solver/quality/quality_measures.h"
#include "solver/quality/shape_change.h"
#include "solver/session/crease_drag.h"
#include "solver/session/solve_session.h"

#include "test_registry.h"

#include <QTest>

#include <cmath>
#include <cstring>
#include <limits>
#include <stdexcept>

using namespace devsurf;
using namespace devsurf::solver;

namespace {

using Points = std::vector<ControlPointHandle>;

constexpr model::EdgeId kCrease = 2; // fig6: the curved crease from vertex 2 to vertex 3

model::CompositeSurface fig6() {
    return model::makeExample("fig6").surfaces.front();
}

// fig6 folded along its crease: its free edge (vertices 4 and 5) lifted 60 mm keeping lengths.
model::CompositeSurface foldedFig6() {
    const model::CompositeSurface flat = fig6();
    SolveSession session(flat, {{4, false, flat.position(4)}}, keepLengthsSessionOptions());
    for (int k = 1; k <= 20; ++k) {
        session.setHandleTarget(4, flat.position(4) + model::Vec3{0.0, 0.0, 3.0 * k});
        session.step(1);
    }
    session.settle();
    session.step(20);
    return session.surface();
}

// The distance from p to the nearest ruling line (through a(u) and b(u), extended) of strip.
double distanceToRulings(const model::Strip& strip, const model::Vec3& p) {
    double nearest = std::numeric_limits<double>::infinity();
    constexpr int kSamples = 20000;
    const double begin = strip.a.domainBegin();
    const double end = strip.a.domainEnd();
    for (int i = 0; i <= kSamples; ++i) {
        const double u = begin + (end - begin) * i / kSamples;
        const model::Vec3 a = strip.aPoint(u);
        const model::Vec3 r = strip.bPoint(u) - a;
        const model::Vec3 q = p - a;
        nearest = std::min(nearest, (q - r * (dot(q, r) / dot(r, r))).norm());
    }
    return nearest;
}

// Replays a crease drag as the Drag tool does: `moves` evenly spaced handle positions with one
// iteration each, then ten more after the release.
model::CompositeSurface dragCrease(const model::CompositeSurface& surface, model::EdgeId edge,
                                   const model::Vec3& by, int moves = 20) {
    const CreaseDrag drag(surface, edge);
    SolveSession session(surface, drag.vertexHandles({}, true), drag.controlPointHandles({}, true),
                         creaseDragSessionOptions());
    for (int k = 1; k <= moves; ++k) {
        const model::Vec3 delta = by * (static_cast<double>(k) / moves);
        for (const VertexHandle& h : drag.vertexHandles(delta, true)) {
            if (!session.setHandleTarget(h.vertex, h.target)) {
                throw std::runtime_error("a vertex handle was not accepted");
            }
        }
        for (const ControlPointHandle& h : drag.controlPointHandles(delta, true)) {
            if (!session.setControlPointTarget(h.edge, h.index, h.target)) {
                throw std::runtime_error("a control-point handle was not accepted");
            }
        }
        if (!session.step(1).succeeded()) {
            throw std::runtime_error("an iteration failed");
        }
    }
    session.settle();
    if (!session.step(10).succeeded()) {
        throw std::runtime_error("the final iterations failed");
    }
    return session.surface();
}

} // namespace

class TstCreaseDragSession : public QObject {
    Q_OBJECT

private slots:
    void theCreaseSlidesWithinTheFlatSheet() {
        const model::CompositeSurface surface = fig6();
        const CreaseDrag drag(surface, kCrease);
        // The sheet lies in z = 0: the normal is ±z and sliding drops the z component.
        QVERIFY(std::abs(std::abs(drag.normal().z) - 1.0) < 1e-12);
        const model::Vec3 slid = drag.displacement({1.0, 2.0, 3.0}, true);
        QVERIFY((slid - model::Vec3{1.0, 2.0, 0.0}).norm() < 1e-12);
        const model::Vec3 free = drag.displacement({1.0, 2.0, 3.0}, false);
        QVERIFY((free - model::Vec3{1.0, 2.0, 3.0}).norm() == 0.0);
        // Sliding, the points move along the strips' rulings, which run along y: the motion
        // along the crease (x) moves nothing. On an axis, every point moves by the motion.
        const std::vector<model::Vec3> sliding = drag.pointDisplacements({1.0, 2.0, 3.0}, true);
        const std::vector<model::Vec3> onAxis = drag.pointDisplacements({1.0, 2.0, 3.0}, false);
        QCOMPARE(sliding.size(), surface.edge(kCrease).controlPoints.size());
        QCOMPARE(onAxis.size(), sliding.size());
        for (std::size_t i = 0; i < sliding.size(); ++i) {
            const model::Vec3 along = sliding[i];
            QVERIFY2((along - model::Vec3{0.0, 2.0, 0.0}).norm() < 1e-9,
                     qPrintable(QString::number((along - model::Vec3{0.0, 2.0, 0.0}).norm())));
            QVERIFY(onAxis[i] == free);
        }
        // Both ends (unpinned) and every interior control point are pulled.
        QCOMPARE(drag.vertices().size(), std::size_t{2});
        QCOMPARE(drag.controlPointHandles({}, true).size(),
                 surface.edge(kCrease).controlPoints.size() - 2);
    }

    void aDraggedCreaseReachesItsTargetAndTheSurfaceStaysDevelopable() {
        const model::CompositeSurface surface = fig6();
        const model::Vec3 by{0.0, 30.0, 10.0}; // the 10 mm out of the sheet are dropped
        const model::CompositeSurface result = dragCrease(surface, kCrease, by);
        const auto& from = surface.edge(kCrease).controlPoints;
        const auto& to = result.edge(kCrease).controlPoints;
        // Its rulings are parallel to y, so every point moves by the motion. The interior points
        // are an energy, and the weak pull of the design towards the press holds them back by
        // about a thousandth of the motion (creaseDragSessionOptions).
        for (std::size_t i = 0; i < to.size(); ++i) {
            const model::Vec3 expected = from[i] + model::Vec3{0.0, 30.0, 0.0};
            QVERIFY2((to[i] - expected).norm() < 0.05,
                     qPrintable(QString::number((to[i] - expected).norm())));
        }
        // Measured from the geometry: developable, flat, no strip collapsed.
        const QualityMeasures quality = measureQuality(result);
        QVERIFY2(quality.developabilityMax <= 1e-8,
                 qPrintable(QString::number(quality.developabilityMax)));
        for (const auto& [id, p] : result.vertices()) {
            QVERIFY(std::abs(p.z) < 1e-6);
        }
        const ShapeChange change = measureShapeChange(surface, result);
        QVERIFY2(change.shortestRuling >= 0.25, qPrintable(QString::number(change.shortestRuling)));
        QVERIFY2(change.slowestSpeed >= 0.1, qPrintable(QString::number(change.slowestSpeed)));
        // The pinned corners stay bit for bit.
        QVERIFY(!surface.pinnedVertices().empty());
        for (model::VertexId v : surface.pinnedVertices()) {
            const model::Vec3 a = surface.position(v);
            const model::Vec3 b = result.position(v);
            QVERIFY(std::memcmp(&a, &b, sizeof a) == 0);
        }
    }

    void aCreaseWithPinnedEndsStillMovesItsControlPoints() {
        model::CompositeSurface surface = fig6();
        const model::EdgeRecord& crease = surface.edge(kCrease);
        surface.setPinned(crease.from, true);
        surface.setPinned(crease.to, true);
        const CreaseDrag drag(surface, kCrease);
        QVERIFY(drag.vertices().empty());
        const model::CompositeSurface result = dragCrease(surface, kCrease, {0.0, 10.0, 0.0});
        QVERIFY(result.position(crease.from) == surface.position(crease.from));
        const model::Vec3 middle = result.edge(kCrease).controlPoints[3];
        QVERIFY((middle - surface.edge(kCrease).controlPoints[3]).norm() > 5.0);
        QVERIFY(measureQuality(result).developabilityMax <= 1e-8);
    }

    void aFoldedCreaseSlidesAlongTheRulingsOfTheStripItLeaves() {
        // The crease of a folded design slides 15 mm: its strips cannot follow a crease
        // translated as a whole, so its points move along the rulings of the strip they leave,
        // which grows along them; the other strip folds about the new crease.
        const model::CompositeSurface folded = foldedFig6();
        const double foldBefore = measureCreaseQuality(folded).meanFoldDegrees;
        QVERIFY2(foldBefore > 10.0, qPrintable(QString::number(foldBefore)));
        const model::CompositeSurface result = dragCrease(folded, kCrease, {0.0, 15.0, 0.0});
        // Measured from the geometry: developable, folded as before along a curved fold, no
        // strip collapsed.
        const QualityMeasures quality = measureQuality(result);
        QVERIFY2(quality.developabilityMax <= 1e-8,
                 qPrintable(QString::number(quality.developabilityMax)));
        const CreaseQuality crease = measureCreaseQuality(result);
        QVERIFY2(crease.residualMax <= 1e-6, qPrintable(QString::number(crease.residualMax)));
        QVERIFY2(std::abs(crease.meanFoldDegrees - foldBefore) < 1.0,
                 qPrintable(QString::number(crease.meanFoldDegrees)));
        const ShapeChange change = measureShapeChange(folded, result);
        QVERIFY2(change.shortestRuling >= 0.5, qPrintable(QString::number(change.shortestRuling)));
        QVERIFY2(change.slowestSpeed >= 0.5, qPrintable(QString::number(change.slowestSpeed)));
        // The new crease lies on the ruling lines of one of its strips at the start, at least
        // 10 mm from the old crease.
        const model::EdgeRecord& before = folded.edge(kCrease);
        const model::EdgeRecord& after = result.edge(kCrease);
        const model::BSplineCurve oldCurve =
            model::BSplineCurve::uniform(before.space, before.controlPoints);
        const model::BSplineCurve newCurve =
            model::BSplineCurve::uniform(after.space, after.controlPoints);
        double offRulings = 0.0;
        double closest = std::numeric_limits<double>::infinity();
        constexpr int kSamples = 16;
        for (int i = 0; i <= kSamples; ++i) {
            const model::Vec3 p =
                newCurve.evaluate(newCurve.domainBegin() +
                                  (newCurve.domainEnd() - newCurve.domainBegin()) * i / kSamples);
            double nearest = std::numeric_limits<double>::infinity();
            for (model::FaceId face : folded.facesOfEdge(kCrease)) {
                nearest = std::min(nearest, distanceToRulings(model::stripOfFace(folded, face), p));
            }
            offRulings = std::max(offRulings, nearest);
            for (int j = 0; j <= 1000; ++j) {
                closest = std::min(
                    closest,
                    (oldCurve.evaluate(oldCurve.domainBegin() +
                                       (oldCurve.domainEnd() - oldCurve.domainBegin()) * j / 1000) -
                     p)
                        .norm());
            }
        }
        qInfo("new crease: %.3g mm off the rulings, at least %.3g mm from the old crease",
              offRulings, closest);
        QVERIFY2(offRulings < 0.1, qPrintable(QString::number(offRulings)));
        QVERIFY2(closest > 10.0, qPrintable(QString::number(closest)));
    }

    void aSlideStopsBeforeTheStripItEntersTurnsInsideOut() {
        // fig6's crease slid 150 mm up its 100 mm strip: it stops where that strip keeps 30 %
        // of its width, rather than crossing the far curve and folding the strip onto itself.
        const model::CompositeSurface surface = fig6();
        const CreaseDrag drag(surface, kCrease);
        QCOMPARE(drag.reach({0.0, 10.0, 0.0}, true), 1.0);
        const double reach = drag.reach({0.0, 150.0, 0.0}, true);
        QVERIFY2(reach > 0.2 && reach < 0.6, qPrintable(QString::number(reach)));
        QCOMPARE(drag.reach({0.0, 150.0, 0.0}, false), 1.0); // an axis the designer chose
        const model::Vec3 limit = drag.pointDisplacements({0.0, 150.0 * reach, 0.0}, true).at(3);
        QVERIFY((drag.pointDisplacements({0.0, 300.0, 0.0}, true).at(3) - limit).norm() < 1e-9);
        const model::CompositeSurface result = dragCrease(surface, kCrease, {0.0, 150.0, 0.0});
        QVERIFY(measureQuality(result).developabilityMax <= 1e-8);
        const ShapeChange change = measureShapeChange(surface, result);
        QVERIFY2(change.shortestRuling >= 0.25 && change.shortestRuling < 0.4,
                 qPrintable(QString::number(change.shortestRuling)));
        QCOMPARE(change.foldOverPlaces(), 0);
        QVERIFY(model::selfOverlappingPatches(result).empty());
        QVERIFY(measureCreaseQuality(result).meanFoldDegrees < 1.0);
    }

    void onlyCreasesCanBeDragged() {
        const model::CompositeSurface surface = fig6();
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, CreaseDrag(surface, 0)); // boundary
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, CreaseDrag(surface, 1)); // a ruling
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, CreaseDrag(surface, 999));
        auto refusal = [&surface](model::EdgeId edge) {
            try {
                CreaseDrag drag(surface, edge);
            } catch (const CreaseDragRefused& refused) {
                return refused.edge() == edge ? static_cast<int>(refused.reason()) : -1;
            }
            return -2;
        };
        QCOMPARE(refusal(0), static_cast<int>(CreaseDragRefusal::NotACrease));
        QCOMPARE(refusal(1), static_cast<int>(CreaseDragRefusal::NotACrease));
        QCOMPARE(refusal(999), static_cast<int>(CreaseDragRefusal::NoSuchEdge));
        // A control point that is not interior, or of an edge that has none, is refused.
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument,
                                 SolveSession(surface, {}, Points{{kCrease, 0, {}}}));
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument,
                                 SolveSession(surface, {}, Points{{1, 1, {}}}));
        QVERIFY_THROWS_EXCEPTION(
            std::invalid_argument,
            SolveSession(surface, {}, Points{{kCrease, 1, {std::nan(""), 0, 0}}}));
        SolveSession session(surface, {},
                             Points{{kCrease, 1, surface.edge(kCrease).controlPoints[1]}});
        QVERIFY(!session.setControlPointTarget(kCrease, 2, {}));
        QVERIFY(!session.setControlPointTarget(kCrease, 1, {std::nan(""), 0.0, 0.0}));
        QVERIFY(session.setControlPointTarget(kCrease, 1, {}));
    }
};

DEVSURF_REGISTER_TEST(TstCreaseDragSession);
#include "tst_crease_drag.moc"
