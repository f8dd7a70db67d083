// Smooth rulings taken from the model (docs/math.md §3) and the crease condition "straight when
// unfolded" (docs/math.md §5), measured from the geometry alone.

#include "model/bspline_curve.h"
#include "model/composite_surface.h"
#include "model/strip.h"
#include "solver/core/guided_projection.h"
#include "solver/formulation/perturbation.h"
#include "solver/formulation/surface_formulation.h"
#include "solver/quality/crease_quality.h"
#include "solver/quality/quality_measures.h"
#include "solver_test_models.h"
#include "solver_test_problems.h"
#include "test_registry.h"

#include <QtTest>

#include <cmath>
#include <random>

using namespace devsurf;
using model::Vec3;
using solver::testing::familyRows;
using solver::testing::largestMove;

namespace {

// Rotation of p about the line x = 100, y arbitrary (z = 0), by `angle`.
Vec3 rotateAboutRuling(const Vec3& p, double angle) {
    const double dx = p.x - 100.0;
    return {100.0 + dx * std::cos(angle) - p.z * std::sin(angle), p.y,
            dx * std::sin(angle) + p.z * std::cos(angle)};
}

// Two flat strips 0 ≤ x ≤ 100 and 100 ≤ x ≤ 200 (0 ≤ y ≤ 100) sharing the ruling x = 100; the
// second is folded about that ruling by `fold`. Its S-edges are gently curved in their plane.
model::CompositeSurface makeFoldedPair(double fold) {
    const model::SplineSpace space{3, 2, 2};
    model::CompositeSurface s;
    const model::VertexId a0 = s.addVertex({0, 0, 0});
    const model::VertexId a1 = s.addVertex({100, 0, 0});
    const model::VertexId a2 = s.addVertex(rotateAboutRuling({200, 0, 0}, fold));
    const model::VertexId b0 = s.addVertex({0, 100, 0});
    const model::VertexId b1 = s.addVertex({100, 100, 0});
    const model::VertexId b2 = s.addVertex(rotateAboutRuling({200, 100, 0}, fold));
    s.addFace({a0, a1, b1, b0});
    s.addFace({a1, a2, b2, b1});
    auto curve = [&](model::VertexId from, model::VertexId to, double y, bool rotated) {
        std::vector<Vec3> points = solver::testing::lineControls(
            space, {rotated ? 100.0 : 0.0, y, 0}, {rotated ? 200.0 : 100.0, y, 0});
        for (std::size_t i = 1; i + 1 < points.size(); ++i) {
            points[i].y += (y > 50 ? -4.0 : 4.0) * (i % 2 == 0 ? 1.0 : -0.5);
        }
        for (Vec3& p : points) {
            p = rotated ? rotateAboutRuling(p, fold) : p;
        }
        s.setSpline(from, to, space, points);
    };
    curve(a0, a1, 0, false);
    curve(b0, b1, 100, false);
    curve(a1, a2, 0, true);
    curve(b1, b2, 100, true);
    return s;
}

// The angle between the two faces' normals a′ × (b − a) along the shared ruling (a′ taken in the
// direction of increasing x on both sides), from the curves alone.
double foldAtRuling(const model::CompositeSurface& s) {
    const Vec3 ruling = s.position(4) - s.position(1);
    const model::EdgeRecord& left = s.edge(s.edgeBetween(0, 1));
    const model::EdgeRecord& right = s.edge(s.edgeBetween(1, 2));
    const Vec3 tl = model::BSplineCurve::uniform(left.space, left.controlPoints).derivative(1.0, 1);
    const Vec3 tr =
        model::BSplineCurve::uniform(right.space, right.controlPoints).derivative(0.0, 1);
    const Vec3 nl = cross(tl, ruling);
    const Vec3 nr = cross(tr, ruling);
    return std::atan2(cross(nl, nr).norm(), dot(nl, nr));
}

model::CompositeSurface solved(const model::CompositeSurface& start,
                               const std::vector<model::VertexId>& fixed, int iterations,
                               double* residual = nullptr) {
    solver::FormulationOptions options;
    for (model::VertexId v : fixed) {
        options.handles.push_back({v, true, {}});
    }
    const solver::SurfaceFormulation f(start, options);
    std::vector<double> x = f.initialState();
    solver::Options solverOptions;
    solverOptions.maxIterations = iterations;
    solver::GuidedProjection projection;
    const solver::Summary summary = projection.solve(f.problem(), x, solverOptions);
    model::CompositeSurface out = start;
    if (!summary.succeeded() || !f.writeBack(x, out)) {
        return start;
    }
    if (residual) {
        *residual = summary.finalMaxConstraintResidual;
    }
    return out;
}

// A generalised cylinder over the cubic curve c(t) (in the plane z = z(t)) split along c: three
// translates c − d, c, c + d with d = (0, 0, 60) along the rulings. With a planar c in z = 0 the
// crease is a normal section, a geodesic of both strips: straight when unfolded. `tilt` lifts
// c to z = tilt · x, which makes it no geodesic.
model::CompositeSurface makeSplitCylinder(double tilt, model::CreaseCondition condition) {
    const model::SplineSpace space{3, 2, 1};
    std::vector<Vec3> c{{0, 0, 0}, {40, 30, 0}, {80, -25, 0}, {120, 10, 0}};
    for (Vec3& p : c) {
        p.z = tilt * p.x;
    }
    const Vec3 d(0, 0, 60);
    model::CompositeSurface s;
    auto translated = [&](double k) {
        std::vector<Vec3> points;
        for (const Vec3& p : c) {
            points.push_back(p + d * k);
        }
        return points;
    };
    const model::VertexId l0 = s.addVertex(c.front() - d);
    const model::VertexId l1 = s.addVertex(c.back() - d);
    const model::VertexId c0 = s.addVertex(c.front());
    const model::VertexId c1 = s.addVertex(c.back());
    const model::VertexId u0 = s.addVertex(c.front() + d);
    const model::VertexId u1 = s.addVertex(c.back() + d);
    s.addFace({l0, l1, c1, c0});
    s.addFace({c0, c1, u1, u0});
    s.setSpline(l0, l1, space, translated(-1.0));
    const model::EdgeId crease = s.setSpline(c0, c1, space, translated(0.0));
    s.setSpline(u0, u1, space, translated(1.0));
    s.setCreaseCondition(crease, condition);
    return s;
}

// A flat sheet split by a straight crease (the middle curve of two strips).
model::CompositeSurface makeSplitSheet() {
    model::CompositeSurface s = solver::testing::makeTwoStrips(2);
    s.setCreaseCondition(s.edgeBetween(2, 3), model::CreaseCondition::Straight);
    return s;
}

} // namespace

class TstSmoothStraight : public QObject {
    Q_OBJECT

private slots:
    void smoothRulingsComeFromTheModel() {
        model::CompositeSurface folded = makeFoldedPair(0.5);
        QVERIFY(folded.validate().empty());
        QVERIFY(solver::measureQuality(folded).developabilityMax < 1e-12);
        const model::EdgeId ruling = folded.edgeBetween(1, 4);
        QCOMPARE(familyRows(solver::SurfaceFormulation(folded, {}).problem(), "smoothRulings"), 0);
        folded.setSmooth(ruling, true);
        QCOMPARE(familyRows(solver::SurfaceFormulation(folded, {}).problem(), "smoothRulings"), 3);
        // Listed in the options as well: imposed once.
        solver::FormulationOptions both;
        both.smoothRulings = {ruling};
        QCOMPARE(familyRows(solver::SurfaceFormulation(folded, both).problem(), "smoothRulings"),
                 3);

        // Solved with the first strip's outer ruling and one more vertex fixed: the fold of
        // 0.5 rad at the ruling is removed; without the mark the design (valid as it is) stays.
        const std::vector<model::VertexId> fixed{0, 3, 1};
        double residual = 0.0;
        const model::CompositeSurface smooth = solved(folded, fixed, 20, &residual);
        model::CompositeSurface sharpStart = folded;
        sharpStart.setSmooth(ruling, false);
        const model::CompositeSurface sharp = solved(sharpStart, fixed, 20);
        const double det = solver::measureQuality(smooth).developabilityMax;
        qInfo("fold at the ruling: %.3e rad smooth (det %.1e, residual %.1e), %.3e rad sharp "
              "(start 0.5)",
              foldAtRuling(smooth), det, residual, foldAtRuling(sharp));
        QVERIFY2(foldAtRuling(smooth) < 1e-6, qPrintable(QString::number(foldAtRuling(smooth))));
        QVERIFY(det < 1e-8);
        QVERIFY(std::abs(foldAtRuling(sharp) - 0.5) < 1e-6);
    }

    void straightCreaseJacobiansMatchFiniteDifferences() {
        const solver::SurfaceFormulation f(makeSplitCylinder(0.3, model::CreaseCondition::Straight),
                                           {});
        const solver::Problem& problem = f.problem();
        QVERIFY(problem.hasBlock("osculatingNormals"));
        QVERIFY(familyRows(problem, "creaseConditions") > 0);
        std::mt19937 rng(17);
        const std::vector<double> x = solver::testing::randomVector(rng, problem.variableCount());
        for (int t = 0; t < problem.termCount(); ++t) {
            const solver::Term& term = problem.term(t);
            const double error = solver::testing::jacobianError(
                solver::testing::analyticJacobian(term, x),
                solver::testing::finiteDifferenceJacobian(term, x, 1e-6));
            QVERIFY2(error < 1e-6, term.typeName());
        }
    }

    void straightCreasesThatAreStraightStayPut_data() {
        QTest::addColumn<int>("which");
        QTest::newRow("flat sheet, straight crease") << 0;
        QTest::newRow("cylinder, normal section") << 1;
    }

    void straightCreasesThatAreStraightStayPut() {
        QFETCH(int, which);
        const model::CompositeSurface surface =
            which == 0 ? makeSplitSheet()
                       : makeSplitCylinder(0.0, model::CreaseCondition::Straight);
        QVERIFY(surface.validate().empty());
        QVERIFY(solver::measureQuality(surface).developabilityMax < 1e-12);
        const solver::CreaseQuality quality = solver::measureCreaseQuality(surface);
        QCOMPARE(quality.creases, 1);
        QVERIFY(quality.residualMax < 1e-12);
        const model::CompositeSurface out = solved(surface, {}, 10);
        const double move = largestMove(surface, out);
        QVERIFY2(move <= 1e-6 * solver::surfaceDiameter(surface),
                 qPrintable(QString::number(move)));
    }

    void tiltedCreaseIsMadeStraight() {
        // The tilted section is no geodesic: the measure sees it, and the condition makes it
        // one (three vertices of the lower strip fixed).
        const model::CompositeSurface tilted =
            makeSplitCylinder(0.3, model::CreaseCondition::Straight);
        const double before = solver::measureCreaseQuality(tilted).residualMax;
        QVERIFY(before > 0.05);
        const model::CompositeSurface out = solved(tilted, {0, 1, 2}, 20);
        const double after = solver::measureCreaseQuality(out).residualMax;
        const double det = solver::measureQuality(out).developabilityMax;
        qInfo("straight-when-unfolded residual: %.3e at the start, %.3e after 20 iterations "
              "(det %.1e)",
              before, after, det);
        QVERIFY2(after < 1e-6, qPrintable(QString::number(after)));
        QVERIFY(det < 1e-8);
        // Without the condition the tilted crease stays as it is (a valid design).
        const model::CompositeSurface free =
            solved(makeSplitCylinder(0.3, model::CreaseCondition::None), {0, 1, 2}, 20);
        model::CompositeSurface measured = free;
        measured.setCreaseCondition(measured.edgeBetween(2, 3), model::CreaseCondition::Straight);
        QVERIFY(solver::measureCreaseQuality(measured).residualMax > 0.05);
    }

    void curvedFoldResidualPerCrease() {
        // Per crease, whatever its condition: the flat split sheet is trivially a curved fold
        // (straight crease); the tilted section of the unfolded cylinder is not (its osculating
        // plane does not bisect the tangent planes, which coincide).
        const auto sheet = solver::curvedFoldResiduals(makeSplitSheet());
        QCOMPARE(static_cast<int>(sheet.size()), 1);
        QVERIFY(sheet.front().max < 1e-12);
        const auto cylinder =
            solver::curvedFoldResiduals(makeSplitCylinder(0.3, model::CreaseCondition::None));
        QCOMPARE(static_cast<int>(cylinder.size()), 1);
        QVERIFY2(cylinder.front().max > 0.05, qPrintable(QString::number(cylinder.front().max)));
        QVERIFY(cylinder.front().mean > 0.0 && cylinder.front().mean <= cylinder.front().max);
    }
};

DEVSURF_REGISTER_TEST(TstSmoothStraight);
#include "tst_smooth_straight.moc"
