// Crease conditions (docs/math.md §5): a curved fold built by reflection satisfies (7) and stays
// put under it; perturbed, the solver restores (7), measured from the geometry alone.

#include "model/bspline_curve.h"
#include "model/composite_surface.h"
#include "model/examples.h"
#include "model/model_error.h"
#include "solver/formulation/perturbation.h"
#include "solver/formulation/surface_formulation.h"
#include "solver/quality/crease_quality.h"
#include "solver/quality/quality_measures.h"
#include "solver/quality/shape_change.h"
#include "solver/quality/vertex_stars.h"
#include "solver/session/solve_session.h"
#include "solver_test_problems.h"
#include "test_registry.h"

#include <QtTest>

#include <cmath>
#include <functional>
#include <map>
#include <random>

using namespace devsurf;
using model::Vec3;
using solver::testing::familyRows;
using solver::testing::largestMove;

namespace {

// The parabolic cylinder z = y² / 200 (rulings along x), cut by the plane x − z = 0 (normal
// m = (1, 0, −1)/√2): the crease c(y) = (y²/200, y, y²/200), y ∈ [−50, 50], lies in the plane.
// The left strip runs from the crease 50 mm towards −x along the rulings; the right strip is
// the part that continued towards +x, reflected in the plane. Reflecting one side of a surface
// in a plane through the crease folds it along that (planar) curve: the plane is the crease's
// osculating plane and bisects the two tangent planes, which is (7). Cubic Bézier curves
// (degree 3, one interval) represent the parabolas exactly.
Vec3 crease(double y) {
    return {y * y / 200.0, y, y * y / 200.0};
}

Vec3 reflect(const Vec3& p) {
    const Vec3 m = Vec3(1, 0, -1) / std::sqrt(2.0);
    return p - m * (2.0 * dot(p, m));
}

// Cubic Bézier control points of a quadratic curve given at t = 0, ½, 1.
std::vector<Vec3> cubicOfQuadratic(const Vec3& p0, const Vec3& pm, const Vec3& p1) {
    const Vec3 q = pm * 2.0 - (p0 + p1) * 0.5; // the quadratic's middle control point
    return {p0, p0 / 3.0 + q * (2.0 / 3.0), q * (2.0 / 3.0) + p1 / 3.0, p1};
}

model::CompositeSurface curvedFold(model::CreaseCondition condition) {
    model::CompositeSurface s;
    s.setName("curved fold");
    const Vec3 away(50, 0, 0);
    auto curve = [&](const std::function<Vec3(const Vec3&)>& f) {
        return cubicOfQuadratic(f(crease(-50)), f(crease(0)), f(crease(50)));
    };
    const std::vector<Vec3> c = curve([](const Vec3& p) { return p; });
    const std::vector<Vec3> a = curve([&](const Vec3& p) { return p - away; });
    const std::vector<Vec3> b = curve([&](const Vec3& p) { return reflect(p + away); });
    const model::VertexId c0 = s.addVertex(c.front());
    const model::VertexId c1 = s.addVertex(c.back());
    const model::VertexId a0 = s.addVertex(a.front());
    const model::VertexId a1 = s.addVertex(a.back());
    const model::VertexId b0 = s.addVertex(b.front());
    const model::VertexId b1 = s.addVertex(b.back());
    s.addFace({a0, c0, c1, a1});
    s.addFace({c1, c0, b0, b1});
    const model::SplineSpace space{3, 2, 1};
    const model::EdgeId edge = s.setSpline(c0, c1, space, c);
    s.setSpline(a0, a1, space, a);
    s.setSpline(b0, b1, space, b);
    s.setCreaseCondition(edge, condition);
    return s;
}

double diameterOf(const model::CompositeSurface& s) {
    return solver::surfaceDiameter(s);
}

// The centroid of the vertices' positions in `surface`.
Vec3 centroidOf(const model::CompositeSurface& surface, const std::vector<model::VertexId>& ids) {
    Vec3 centre(0, 0, 0);
    for (model::VertexId v : ids) {
        centre = centre + surface.position(v) * (1.0 / static_cast<double>(ids.size()));
    }
    return centre;
}

// p turned by `angle` (radians) about the vertical through `centre`.
Vec3 turnedAboutVertical(const Vec3& p, const Vec3& centre, double angle) {
    const Vec3 d = p - centre;
    return centre + Vec3(d.x * std::cos(angle) - d.y * std::sin(angle),
                         d.x * std::sin(angle) + d.y * std::cos(angle), d.z);
}

} // namespace

class TstCreaseConditions : public QObject {
    Q_OBJECT

private slots:
    void reflectedFoldSatisfiesTheCurvedFoldCondition() {
        const model::CompositeSurface fold = curvedFold(model::CreaseCondition::CurvedFold);
        QVERIFY(fold.validate().empty());
        // Developable as built (both strips are pieces of a cylinder) and really folded.
        QVERIFY(solver::measureQuality(fold).developabilityMax < 1e-12);
        const solver::CreaseQuality quality = solver::measureCreaseQuality(fold);
        QCOMPARE(quality.creases, 1);
        QVERIFY2(quality.residualMax < 1e-12, qPrintable(QString::number(quality.residualMax)));
        QVERIFY(quality.meanFoldDegrees > 10.0);
        // The same shape is no geodesic: the measure can fail.
        const solver::CreaseQuality geodesic =
            solver::measureCreaseQuality(curvedFold(model::CreaseCondition::Geodesic));
        QVERIFY(geodesic.residualMax > 0.1);
    }

    void everyTermsJacobianMatchesFiniteDifferences_data() {
        QTest::addColumn<int>("condition");
        QTest::newRow("curved fold") << static_cast<int>(model::CreaseCondition::CurvedFold);
        QTest::newRow("geodesic") << static_cast<int>(model::CreaseCondition::Geodesic);
    }

    void everyTermsJacobianMatchesFiniteDifferences() {
        QFETCH(int, condition);
        const solver::SurfaceFormulation f(
            curvedFold(static_cast<model::CreaseCondition>(condition)), {});
        const solver::Problem& problem = f.problem();
        std::mt19937 rng(11);
        const std::vector<double> x = solver::testing::randomVector(rng, problem.variableCount());
        QVERIFY(problem.findFamily("creaseConditions") >= 0);
        for (int t = 0; t < problem.termCount(); ++t) {
            const solver::Term& term = problem.term(t);
            const double error = solver::testing::jacobianError(
                solver::testing::analyticJacobian(term, x),
                solver::testing::finiteDifferenceJacobian(term, x, 1e-6));
            QVERIFY2(error < 1e-6, term.typeName());
        }
    }

    void curvedFoldStaysPutWithoutPins() {
        const model::CompositeSurface fold = curvedFold(model::CreaseCondition::CurvedFold);
        solver::SolveSession session(fold, {});
        QVERIFY(session.step(10).succeeded());
        const double move = largestMove(fold, session.surface());
        QVERIFY2(move <= 1e-6 * diameterOf(fold), qPrintable(QString::number(move)));
    }

    void perturbedFoldIsRestored() {
        // Noise breaks (7); ten iterations with the condition restore it (three vertices
        // pinned), while the same solve without the condition leaves the crease as it is.
        double withCondition = 0.0;
        double without = 0.0;
        for (const model::CreaseCondition condition :
             {model::CreaseCondition::CurvedFold, model::CreaseCondition::None}) {
            model::CompositeSurface fold = curvedFold(condition);
            const std::vector<model::VertexId> pins{0, 2, 3};
            solver::perturbSurface(fold, 0.002 * diameterOf(fold), 7, pins);
            for (model::VertexId v : pins) {
                fold.setPinned(v, true);
            }
            solver::SolveSession session(fold, {});
            QVERIFY(session.step(10).succeeded());
            const model::CompositeSurface solved = session.surface();
            QVERIFY(solver::measureQuality(solved).developabilityMax < 1e-8);
            model::CompositeSurface measured = solved;
            measured.setCreaseCondition(measured.edgeBetween(0, 1),
                                        model::CreaseCondition::CurvedFold);
            const double residual = solver::measureCreaseQuality(measured).residualMax;
            (condition == model::CreaseCondition::None ? without : withCondition) = residual;
        }
        qInfo("curved-fold residual after 10 iterations: %.2e with the condition, %.2e without",
              withCondition, without);
        QVERIFY(withCondition < 1e-6);
        QVERIFY(without > 100.0 * withCondition);
    }

    void foldShakenByOnePercentIsRestored() {
        // Noise of 1 % of the diameter, 20 seeds, as perturbedFoldIsRestored: every seed
        // reaches det 1e-8 and the crease condition 1e-8 in 10 iterations. Measured: before
        // Solve damped length changes on rough starts (kRoughSolveLengthDamping), 4 seeds
        // ended above (up to 1.3e-6); since, the worst is 2.6e-9.
        for (unsigned seed = 1; seed <= 20; ++seed) {
            model::CompositeSurface fold = curvedFold(model::CreaseCondition::CurvedFold);
            const std::vector<model::VertexId> pins{0, 2, 3};
            solver::perturbSurface(fold, 0.01 * diameterOf(fold), seed, pins);
            for (model::VertexId v : pins) {
                fold.setPinned(v, true);
            }
            solver::SolveSession session(fold, {});
            QVERIFY(session.step(10).succeeded());
            const double det = solver::measureQuality(session.surface()).developabilityMax;
            const double crease = solver::measureCreaseQuality(session.surface()).residualMax;
            QVERIFY2(
                det < 1e-8 && crease < 1e-8,
                qPrintable(QString("seed %1: det %2, crease %3").arg(seed).arg(det).arg(crease)));
        }
    }

    void conditionsWhereTheyCannotApplyAreRefused() {
        // A boundary curve is not a crease (the model refuses it): a sentence naming the edge.
        // "Straight when unfolded" is solved (tst_smooth_straight) and accepted here.
        model::CompositeSurface boundary = curvedFold(model::CreaseCondition::None);
        const model::EdgeId edge = boundary.edgeBetween(2, 3);
        boundary.setCreaseCondition(edge, model::CreaseCondition::CurvedFold);
        try {
            solver::SolveSession session(boundary, {});
            QFAIL("a condition that cannot be imposed was accepted");
        } catch (const model::ModelError& error) {
            QCOMPARE(error.problem().code, model::ProblemCode::ConditionNotShared);
            QCOMPARE(error.problem().edge, edge);
        }
        solver::SolveSession straight(curvedFold(model::CreaseCondition::Straight), {});
        QVERIFY(straight.formulation().problem().hasBlock("osculatingNormals"));
    }

    void fig8LiftedFoldsAlongItsCurvedCreases() {
        // The scripted drag of the paper's Fig. 8 as devsurf-cli drag replays it: the four
        // interior vertices lifted by 85 mm (20 % of the diameter) in 20 moves of one
        // iteration, then 10 more, with the session's defaults (vertex developability on); the
        // two pinned corners stay. Measured from the geometry: every strip developable, the
        // curved-fold condition held, the angles at the four crease vertices sum to 2π, the
        // sheet really folds, no ruling collapsed. (Measured: det 5e-15, fold residual 4e-15,
        // angle defect 0, mean fold 17.5°, shortest ruling 0.78 of its length, slowest speed
        // 0.66, dragged vertices within 5e-14 mm of their targets. Without vertex
        // developability: defect 4.3e-2 rad, shortest ruling 0.23.)
        const model::CompositeSurface start = model::makeExample("fig8").surfaces[0];
        const std::vector<model::VertexId> lifted{5, 6, 9, 10};
        const model::CompositeSurface result =
            dragFig8(start, lifted, [&](model::VertexId v, double t) {
                return start.position(v) + Vec3(0, 0, 85.0 * t);
            });
        for (model::VertexId v : lifted) {
            QVERIFY(std::abs(result.position(v).z - 85.0) < 1e-3);
        }
        checkFig8(start, result, 10.0);
    }

    void fig8RotatedKeepsItsCreaseVerticesDevelopable() {
        // The same drag turning the four interior vertices by 30° about the vertical through
        // their centroid. The sheet stays flat (an in-plane motion keeps every condition, and
        // nothing breaks the symmetry), so only the shape is checked: without vertex
        // developability the stars folded over themselves (angle defect 1.6 rad). (Measured:
        // det 0, defect 0, mean fold 2.1°, shortest ruling 0.45, slowest speed 0.64.)
        const model::CompositeSurface start = model::makeExample("fig8").surfaces[0];
        const std::vector<model::VertexId> turned{5, 6, 9, 10};
        const Vec3 centre = centroidOf(start, turned);
        const model::CompositeSurface result =
            dragFig8(start, turned, [&](model::VertexId v, double t) {
                return turnedAboutVertical(start.position(v), centre, t * std::acos(-1.0) / 6.0);
            });
        checkFig8(start, result, 0.0);
    }

    void fig8LiftedThenRotatedStaysFolded() {
        // The paper's bottom row of Fig. 8: the lifted sheet's four interior vertices turned
        // by 30° about the vertical through their centroid, as a second drag. (Measured: det
        // 1.4e-15, crease residual 1.8e-13, defect 1.8e-15, mean fold 37°, shortest ruling
        // 0.63 and slowest speed 0.47 of the lifted sheet's.)
        const model::CompositeSurface flat = model::makeExample("fig8").surfaces[0];
        const std::vector<model::VertexId> moved{5, 6, 9, 10};
        const model::CompositeSurface lifted =
            dragFig8(flat, moved, [&](model::VertexId v, double t) {
                return flat.position(v) + Vec3(0, 0, 85.0 * t);
            });
        const Vec3 centre = centroidOf(lifted, moved);
        const model::CompositeSurface result =
            dragFig8(lifted, moved, [&](model::VertexId v, double t) {
                return turnedAboutVertical(lifted.position(v), centre, t * std::acos(-1.0) / 6.0);
            });
        for (model::VertexId v : moved) {
            const Vec3 expected =
                turnedAboutVertical(lifted.position(v), centre, std::acos(-1.0) / 6.0);
            QVERIFY((result.position(v) - expected).norm() < 1e-3);
        }
        checkFig8(lifted, result, 10.0);
    }

private:
    // Replays a drag of `dragged` along target(v, t), t = 1/20 … 1 (one iteration each), then
    // 10 more iterations, through a SolveSession with its defaults.
    static model::CompositeSurface
    dragFig8(const model::CompositeSurface& start, const std::vector<model::VertexId>& dragged,
             const std::function<Vec3(model::VertexId, double)>& target) {
        std::vector<solver::VertexHandle> pulled;
        for (model::VertexId v : dragged) {
            pulled.push_back({v, false, start.position(v)});
        }
        solver::SolveSession session(start, pulled);
        const int moves = 20;
        for (int k = 1; k <= moves; ++k) {
            for (model::VertexId v : dragged) {
                if (!session.setHandleTarget(v, target(v, static_cast<double>(k) / moves))) {
                    return start;
                }
            }
            if (!session.step(1).succeeded()) {
                return start;
            }
        }
        return session.step(10).succeeded() ? session.surface() : start;
    }

    static void checkFig8(const model::CompositeSurface& start,
                          const model::CompositeSurface& result, double minimumFoldDegrees) {
        QVERIFY(!(result == start));
        for (model::VertexId v : result.pinnedVertices()) {
            QVERIFY(result.position(v) == start.position(v));
        }
        const solver::QualityMeasures quality = solver::measureQuality(result);
        QVERIFY2(quality.developabilityMax < 1e-8,
                 qPrintable(QString::number(quality.developabilityMax)));
        const solver::CreaseQuality creases = solver::measureCreaseQuality(result);
        QCOMPARE(creases.creases, 6);
        QVERIFY2(creases.residualMax < 1e-8, qPrintable(QString::number(creases.residualMax)));
        QVERIFY2(creases.meanFoldDegrees >= minimumFoldDegrees,
                 qPrintable(QString::number(creases.meanFoldDegrees)));
        const auto defects = solver::vertexAngleDefects(result);
        QCOMPARE(static_cast<int>(defects.size()), 4);
        for (const solver::VertexAngleDefect& d : defects) {
            QVERIFY2(d.defect <= 1e-6,
                     qPrintable(QString("vertex %1: angle defect %2").arg(d.vertex).arg(d.defect)));
        }
        const solver::ShapeChange change = solver::measureShapeChange(start, result);
        QVERIFY2(change.shortestRuling > 0.25, qPrintable(QString::number(change.shortestRuling)));
        QVERIFY2(change.slowestSpeed > 0.1, qPrintable(QString::number(change.slowestSpeed)));
    }
};

DEVSURF_REGISTER_TEST(TstCreaseConditions);
#include "tst_crease_conditions.moc"
