// Creases confined to curves drawn in the sheet (§5, Fig. 12, 13): the curves' geometry, which
// creases a drawing holds, the rows' Jacobians, a Solve that moves the creases' development
// onto their curves and a fold that keeps it there, measured from the written-back geometry
// (model::sampleSurface) and from curves computed here, not from the solver's residuals.

#include "model/bspline_curve.h"
#include "model/composite_surface.h"
#include "model/development.h"
#include "model/examples.h"
#include "model/math_constants.h"
#include "model/sampled_mesh.h"
#include "model/sheet_creases.h"
#include "model/sheet_domain.h"
#include "sampled_developability.h"
#include "solver/formulation/surface_formulation.h"
#include "solver/quality/crease_quality.h"
#include "solver/quality/shape_change.h"
#include "solver/session/solve_session.h"
#include "solver_test_drags.h"
#include "solver_test_models.h"
#include "solver_test_problems.h"
#include "test_registry.h"

#include <QtTest>

#include <cmath>
#include <random>
#include <set>

using namespace devsurf;
using model::SheetDomain;
using model::SheetShape;
using model::Vec2;

namespace {

constexpr int kSamples = model::kDevelopmentSamplesPerInterval;

// A circle of radius r about the origin as a closed crease curve of `n` points (as a drawn
// circle is read: kCreaseCurveTolerance gives about 800 at these radii).
SheetDomain::Curve circle(double r, int n = 800) {
    SheetDomain::Curve curve;
    curve.closed = true;
    for (int i = 0; i < n; ++i) {
        const double t = 2.0 * model::kPi * i / n;
        curve.points.emplace_back(r * std::cos(t), r * std::sin(t));
    }
    return curve;
}

// The radius of an S-edge's ring in the annulus example, which is centred at the origin (its
// first vertex's distance from there, rounded to the 25 mm steps of the example's rings).
double ringOf(const model::CompositeSurface& s, model::EdgeId edge) {
    const model::Vec3 p = s.position(s.edges().at(edge).from);
    return 25.0 * std::round(std::hypot(p.x, p.y) / 25.0);
}

// The annulus example (rings at 100, 125, ..., 250 mm) holding its sheet on an annulus of radii
// 100 and 250 mm, with crease curves drawn at radii 130 and 205 mm: near the rings at 125 and
// 200 mm, which lie nearer them than every other ring.
model::CompositeSurface annulusWithCreaseCurves() {
    model::CompositeSurface s = model::makeExample("annulus").surfaces.front();
    if (model::keepDevelopment(s)) {
        return {};
    }
    SheetDomain domain;
    domain.shape = SheetShape::Annulus;
    domain.innerRadius = 100.0;
    domain.radius = 250.0;
    const model::SampledMesh mesh = model::sampleSurface(s, kSamples);
    domain = model::placeDomain(domain, mesh, s.development());
    domain.creaseCurves = {circle(130.0), circle(205.0)};
    domain.creaseCurveOf = model::assignCreasesToCurves(domain, s, mesh, s.development());
    s.setSheetDomain(domain);
    return s;
}

// The largest distance of the development of a held crease sample from its circle, computed
// from the radii alone.
double largestOffCircle(const model::CompositeSurface& s) {
    const model::SampledMesh mesh = model::sampleSurface(s, kSamples);
    const SheetDomain& d = s.sheetDomain();
    double worst = 0.0;
    for (const model::SampledMesh::Polyline& line : mesh.splineEdges) {
        const auto it = d.creaseCurveOf.find(line.edge);
        if (it == d.creaseCurveOf.end()) {
            continue;
        }
        const double r = it->second == 0 ? 130.0 : 205.0;
        for (int v : line.vertices) {
            const double at = (s.development()[static_cast<std::size_t>(v)] - d.centre).norm();
            worst = std::max(worst, std::abs(at - r));
        }
    }
    return worst;
}

// fig13's crease as the example draws it, y = 40 (1 − (x/150)²) in the sheet, plus `wave` mm
// of sin(πx/150) (1 − (x/150)²), read as a drawn polyline of 0.5 mm chords would be.
double fig13Crease(double x, double wave) {
    const double u = x / 150.0;
    return 40.0 * (1.0 - u * u) + wave * std::sin(model::kPi * u) * (1.0 - u * u);
}

model::CompositeSurface fig13HoldingItsCreaseOn(double wave) {
    model::CompositeSurface s = model::makeExample("fig13").surfaces.front();
    SheetDomain d = s.sheetDomain();
    SheetDomain::Curve curve;
    for (int i = 0; i <= 600; ++i) {
        const double x = -150.0 + 0.5 * i;
        curve.points.emplace_back(x, fig13Crease(x, wave));
    }
    d.creaseCurves = {curve};
    const model::SampledMesh mesh = model::sampleSurface(s, kSamples);
    d.creaseCurveOf = model::assignCreasesToCurves(d, s, mesh, s.development());
    s.setSheetDomain(d);
    return s;
}

// The largest distance (mm, along y) of a held crease's development from fig13Crease.
double largestOffDrawnCrease(const model::CompositeSurface& s, double wave) {
    const SheetDomain& d = s.sheetDomain();
    double worst = 0.0;
    for (const model::SampledMesh::Polyline& line : model::sampleSurface(s, kSamples).splineEdges) {
        if (d.creaseCurveOf.count(line.edge) == 0) {
            continue;
        }
        for (int v : line.vertices) {
            const Vec2 p = s.development()[static_cast<std::size_t>(v)] - d.centre;
            worst = std::max(worst, std::abs(p.y - fig13Crease(p.x, wave)));
        }
    }
    return worst;
}

} // namespace

class TstSheetCreases : public QObject {
    Q_OBJECT

private slots:
    void openCurvesGoOnAlongTheirEnds() {
        SheetDomain d;
        d.shape = SheetShape::Disk;
        d.radius = 100.0;
        d.centre = {10.0, 0.0};
        d.angle = 0.5 * model::kPi; // the curve's frame turned a quarter
        d.creaseCurves = {{{{0, 0}, {10, 0}, {20, 5}}, false}};
        const std::vector<model::DomainLoop> loops = model::creaseCurveLoops(d);
        QCOMPARE(static_cast<int>(loops.size()), 1);
        QVERIFY(loops[0].open);
        QVERIFY((loops[0].polygon[1] - Vec2(10.0, 10.0)).norm() < 1e-12);
        // Before the first point the foot lies on the first side's line, not at its end.
        const model::DomainFoot before = model::footPoint(loops[0], {13.0, -20.0});
        QVERIFY2((before.point - Vec2(10.0, -20.0)).norm() < 1e-12,
                 qPrintable(QString("%1 %2").arg(before.point.x).arg(before.point.y)));
        QVERIFY(std::abs(std::abs(before.normal.x) - 1.0) < 1e-12);
        // Between the ends it is the nearest point of the polyline.
        QVERIFY((model::footPoint(loops[0], {7.0, 5.0}).point - Vec2(10.0, 5.0)).norm() < 1e-12);

        // A drawing's curves seen from above: a closed one loses its repeated point.
        const std::vector<model::ReferenceCurve> drawn = {
            {"LINE 1", "", {{0, 0, 5}, {10, 0, 5}}},
            {"CIRCLE 2", "", {{1, 0, 0}, {0, 1, 0}, {-1, 0, 0}, {0, -1, 0}, {1, 0, 0}}},
            {"POINT 3", "", {{4, 4, 4}}}};
        const auto curves = model::sheetCurvesFromAbove(drawn, {-5.0, 1.0});
        QCOMPARE(static_cast<int>(curves.size()), 2);
        QVERIFY(!curves[0].closed);
        QVERIFY(curves[0].points[1] == Vec2(5.0, 1.0));
        QVERIFY(curves[1].closed);
        QCOMPARE(static_cast<int>(curves[1].points.size()), 4);

        // A crease on a curve that is not there, or a curve of one point, is a problem.
        d.creaseCurveOf = {{3, 1}};
        QCOMPARE(model::domainProblem(d)->count, 4LL);
        d.creaseCurveOf = {{3, 0}};
        QVERIFY(!model::domainProblem(d).has_value());
        d.creaseCurves[0].points.resize(1);
        QCOMPARE(model::domainProblem(d)->count, 4LL);
    }

    void drawingHoldsTheCreasesNearItsCurves() {
        const model::CompositeSurface s = annulusWithCreaseCurves();
        QVERIFY(s.keepsDevelopment());
        QVERIFY(s.validate().empty());
        // The eight arcs of the ring at 125 mm go to the circle at 130, those of the ring at
        // 200 to the circle at 205; no other ring, and no rim (a boundary, not a crease).
        std::map<int, std::set<double>> ringsOf;
        for (const auto& [edge, curve] : s.sheetDomain().creaseCurveOf) {
            QVERIFY(s.facesOfEdge(edge).size() == 2);
            ringsOf[curve].insert(ringOf(s, edge));
        }
        QCOMPARE(static_cast<int>(s.sheetDomain().creaseCurveOf.size()), 16);
        QVERIFY(ringsOf[0] == std::set<double>{125.0});
        QVERIFY(ringsOf[1] == std::set<double>{200.0});
    }

    void creasesAsTheyLieBecomeTheirCurves() {
        // fig8 on its 300 × 300 mm square: its two creases (three S-edges each, continuing one
        // another) become two open curves through where they lie; the annulus's five rings
        // become five closed ones. Checked against the splines evaluated densely (flat designs
        // lie in their development as they lie in the xy-plane).
        for (const char* name : {"fig8", "annulus"}) {
            model::CompositeSurface s = model::makeExample(name).surfaces.front();
            QVERIFY(!model::keepDevelopment(s).has_value());
            const model::SampledMesh mesh = model::sampleSurface(s, kSamples);
            SheetDomain shape;
            shape.shape = std::string(name) == "fig8" ? SheetShape::Rectangle : SheetShape::Annulus;
            shape.width = shape.height = 300.0;
            shape.innerRadius = 100.0;
            shape.radius = 250.0;
            SheetDomain d = model::placeDomain(shape, mesh, s.development());
            d.creaseCurves =
                model::sheetFrameCurves(d, model::creaseCurvesAsTheyLie(s, s.development()));
            const bool isFig8 = std::string(name) == "fig8";
            QCOMPARE(static_cast<int>(d.creaseCurves.size()), isFig8 ? 2 : 5);
            std::vector<Vec2> dense; // every crease spline, 2000 points per edge
            int creases = 0;
            for (const auto& [id, record] : s.edges()) {
                if (!record.isSpline() || s.facesOfEdge(id).size() != 2) {
                    continue;
                }
                ++creases;
                const model::BSplineCurve curve =
                    model::BSplineCurve::uniform(record.space, record.controlPoints);
                for (int i = 0; i <= 2000; ++i) {
                    const model::Vec3 p = curve.evaluate(i / 2000.0);
                    dense.emplace_back(p.x, p.y);
                }
            }
            double worst = 0.0;
            for (const model::DomainLoop& loop : model::creaseCurveLoops(d)) {
                QCOMPARE(loop.open, isFig8);
                for (const Vec2& p : loop.polygon) {
                    double nearest = 1e300;
                    for (const Vec2& q : dense) {
                        nearest = std::min(nearest, (p - q).norm());
                    }
                    worst = std::max(worst, nearest);
                }
            }
            // Within the spacing of the dense samples (at most 0.3 mm apart).
            QVERIFY2(worst < 0.2, qPrintable(QString::number(worst)));
            d.creaseCurveOf = model::assignCreasesToCurves(d, s, mesh, s.development());
            QCOMPARE(static_cast<int>(d.creaseCurveOf.size()), creases);
            const double gap = model::largestCreaseCurveGap(d, mesh, s.development());
            QVERIFY2(gap < 1e-6, qPrintable(QString::number(gap)));
        }
        // None for a design without creases: one cone.
        const model::CompositeSurface cone = solver::testing::makeCone();
        const model::Development flat =
            model::unfoldSampledMesh(model::sampleSurface(cone, kSamples));
        QVERIFY(model::creaseCurvesAsTheyLie(cone, flat.vertices).empty());
    }

    void creaseRowsHoldEverySampleOnce() {
        const model::CompositeSurface s = annulusWithCreaseCurves();
        solver::FormulationOptions options;
        options.developmentSamplesPerInterval = kSamples;
        options.developmentStart = s.development();
        options.developmentDomain = s.sheetDomain();
        const int rows = solver::testing::familyRows(
            solver::SurfaceFormulation(s, options).problem(), "developmentDomain");
        SheetDomain withoutCurves = s.sheetDomain();
        withoutCurves.creaseCurves.clear();
        withoutCurves.creaseCurveOf.clear();
        options.developmentDomain = withoutCurves;
        const int boundaryRows = solver::testing::familyRows(
            solver::SurfaceFormulation(s, options).problem(), "developmentDomain");
        // 16 arcs of 7 samples, their ends shared around each ring: 8 × 6 per ring.
        QCOMPARE(rows - boundaryRows, 2 * 8 * 6);
    }

    void smoothCurvesTurnTheirNormalsGradually() {
        // The tangent-line row of a drawn curve must not jump where a point crosses a polygon
        // vertex (its iteration alternated between two sides otherwise): just before and just
        // after a vertex of a 12-gon the normals agree, on the polygon's sides they are the
        // sides' own only at the sides' middles.
        SheetDomain d;
        d.shape = SheetShape::Disk;
        d.radius = 100.0;
        d.creaseCurves = {circle(50.0, 12)};
        const model::DomainLoop loop = model::creaseCurveLoops(d).front();
        QVERIFY(loop.smooth);
        const Vec2 vertex = loop.polygon[1];
        const Vec2 tangent = loop.polygon[2] - loop.polygon[0];
        const Vec2 before = model::footPoint(loop, vertex - tangent * 1e-7).normal;
        const Vec2 after = model::footPoint(loop, vertex + tangent * 1e-7).normal;
        QVERIFY2((before - after).norm() < 1e-6,
                 qPrintable(QString::number((before - after).norm())));
        // At the vertex the normal points along the radius (the mean of the two sides').
        QVERIFY(std::abs(std::abs(model::dot2(before, vertex * (1.0 / 50.0))) - 1.0) < 1e-6);
        // The residual is the distance along that normal: zero on the polygon.
        const model::DomainFoot on =
            model::footPoint(loop, (loop.polygon[3] + loop.polygon[4]) * 0.5);
        QVERIFY((on.point - (loop.polygon[3] + loop.polygon[4]) * 0.5).norm() < 1e-12);
    }

    void solveMovesTheCreasesOntoTheirCurves() {
        // The rings at 125 and 200 mm are drawn 5 mm farther out: Solve (as the application
        // runs it) moves their development onto the circles, the rims onto the sheet's, the
        // design staying flat and isometric to its development.
        const model::CompositeSurface start = annulusWithCreaseCurves();
        const double before = largestOffCircle(start);
        QVERIFY2(before > 4.0, qPrintable(QString::number(before)));
        solver::SessionOptions solve;
        solve.stopResidual = solver::kSolveStopResidual;
        solver::SolveSession session(start, {}, solve);
        const solver::Summary summary = session.step(solver::kSolveIterations);
        QVERIFY(summary.succeeded());
        const model::CompositeSurface& s = session.surface();
        QVERIFY(s.validate().empty());
        const double off = largestOffCircle(s);
        // Within the chords of the 800-gon drawn (205 mm · (1 − cos 0.225°) = 1.6e-3 mm).
        QVERIFY2(off < 2e-3, qPrintable(QString::number(off)));
        QVERIFY(summary.toleranceReached);
        const double gap = model::largestCreaseCurveGap(
            s.sheetDomain(), model::sampleSurface(s, kSamples), s.development());
        QVERIFY2(gap < 1e-8 * 500.0, qPrintable(QString::number(gap)));
        const double isometry = solver::testing::pairLengthError(s, s.development());
        QVERIFY2(isometry < 1e-10, qPrintable(QString::number(isometry)));
        double height = 0.0;
        for (const auto& [id, p] : s.vertices()) {
            height = std::max(height, std::abs(p.z));
        }
        QVERIFY2(height < 1e-6, qPrintable(QString::number(height)));
    }

    void curvedFoldTakesTheShapeOfItsDrawnCurve() {
        // fig13 (a disk with one curved crease, y = 40 (1 − (x/150)²), held on its disk) with
        // the crease drawn 5 mm wavier: y + 5 sin(πx/150) (1 − (x/150)²). Solve moves every
        // sample of the six crease segments onto the drawn curve (distance computed here from
        // the formula), the disk staying flat and isometric to its development.
        const model::CompositeSurface s = fig13HoldingItsCreaseOn(5.0);
        QVERIFY(s.keepsDevelopment() && !s.development().empty());
        QCOMPARE(static_cast<int>(s.sheetDomain().creaseCurveOf.size()), 6);
        solver::SessionOptions solve;
        solve.stopResidual = solver::kSolveStopResidual;
        solver::SolveSession session(s, {}, solve);
        const solver::Summary summary = session.step(solver::kSolveIterations);
        QVERIFY(summary.succeeded() && summary.toleranceReached);
        const model::CompositeSurface& solved = session.surface();
        const double worst = largestOffDrawnCrease(solved, 5.0);
        // Within the drawn polyline's chords (0.5 mm apart: under 1e-4 mm from the formula)
        // and the slope's share of a vertical offset.
        QVERIFY2(worst < 1e-3, qPrintable(QString::number(worst)));
        const double isometry = solver::testing::pairLengthError(solved, solved.development());
        QVERIFY2(isometry < 1e-10, qPrintable(QString::number(isometry)));
    }

    void foldsWithItsCreaseHeldOnItsCurve_data() {
        QTest::addColumn<double>("wave");
        QTest::newRow("its own parabola") << 0.0;
        QTest::newRow("5 mm wavier") << 5.0;
    }

    void foldsWithItsCreaseHeldOnItsCurve() {
        // fig13 with its crease held on a curve drawn in the sheet, the rim point above the
        // pinned middle pulled 60 mm up and 60 mm over in 20 moves through the solve job (as
        // `devsurf-cli drag` does; each move then jumps 4.2 mm, split by kMoveStepLimit):
        // the disk folds along the crease as it does with the crease free (measured 53.6° and
        // 53.8°; folded over in 4 places before the long moves were split), the crease stays
        // on its curve and the development on the disk, isometric, measured from the geometry.
        QFETCH(double, wave);
        model::CompositeSurface s = fig13HoldingItsCreaseOn(wave);
        const model::VertexId top = solver::testing::fig13Top(s);
        QVERIFY(top != model::kInvalidId);
        {
            solver::SessionOptions solve;
            solve.stopResidual = solver::kSolveStopResidual;
            solver::SolveSession session(s, {}, solve);
            QVERIFY(session.step(solver::kSolveIterations).toleranceReached);
            s = session.surface();
        }
        const model::Vec3 target = s.position(top) + model::Vec3(0.0, -60.0, 60.0);
        const solver::JobOutcome outcome = solver::testing::dragInJob(s, top, target, 20);
        QVERIFY2(outcome.ok, outcome.failure.detail.c_str());
        const solver::SurfaceAssessment& a = outcome.assessments.front();
        QVERIFY(!a.takenBack);
        const model::CompositeSurface& folded = outcome.surfaces.front();
        const double developability = test::sampledDevelopability(folded);
        const solver::CreaseQuality creases = solver::measureCreaseQuality(folded);
        const double offCurve = largestOffDrawnCrease(folded, wave);
        const double isometry = solver::testing::pairLengthError(folded, folded.development());
        const double gap = model::largestDomainGap(
            folded.sheetDomain(), model::sampleSurface(folded, kSamples), folded.development());
        qInfo("fold %.1f°, risen %.1f mm, det %.2g, crease residual %.2g, %.2g mm off its curve, "
              "isometric to %.2g, on the circle to %.2g mm",
              creases.meanFoldDegrees, folded.position(top).z - s.position(top).z, developability,
              creases.residualMax, offCurve, isometry, gap);
        QVERIFY2(creases.meanFoldDegrees > 45.0,
                 qPrintable(QString::number(creases.meanFoldDegrees)));
        QVERIFY(folded.position(top).z - s.position(top).z > 30.0);
        QVERIFY(solver::foldOvers(folded).empty());
        QVERIFY2(developability < 1e-5, qPrintable(QString::number(developability)));
        QVERIFY2(offCurve < 1e-3, qPrintable(QString::number(offCurve)));
        QVERIFY2(isometry < 1e-6, qPrintable(QString::number(isometry)));
        QVERIFY2(gap < 1e-4, qPrintable(QString::number(gap)));
    }
};

DEVSURF_REGISTER_TEST(TstSheetCreases);
#include "tst_sheet_creases.moc"
