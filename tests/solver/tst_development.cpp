// The development in the solve (§5, eq. 12): its rows' Jacobians, a flat design staying put, and
// drags that keep the surface isometric to its development, measured from the written-back
// geometry (model::sampleSurface), not from the solver's residuals.

#include "model/bspline_curve.h"
#include "model/composite_surface.h"
#include "model/development.h"
#include "model/examples.h"
#include "model/math_constants.h"
#include "model/sampled_mesh.h"
#include "model/sheet_domain.h"
#include "model/strip.h"
#include "solver/core/guided_projection.h"
#include "solver/formulation/surface_formulation.h"
#include "solver/quality/crease_quality.h"
#include "solver/quality/quality_measures.h"
#include "solver/quality/shape_change.h"
#include "solver/quality/vertex_stars.h"
#include "solver/session/solve_job.h"
#include "solver/session/solve_session.h"
#include "solver/session/verdict.h"
#include "solver_test_drags.h"
#include "solver_test_models.h"
#include "solver_test_problems.h"
#include "test_registry.h"

#include <QtTest>

#include <algorithm>
#include <cmath>
#include <random>

using namespace devsurf;
using model::Vec3;
using solver::testing::Dragged;
using solver::testing::dragInJob;
using solver::testing::dragUp;
using solver::testing::familyRows;
using solver::testing::pairLengthError;

namespace {

constexpr int kSamples = 2; // per spline interval
// How closely a held sheet is kept, relative, pair by pair: the development is a constraint
// judged apart (a sampled mesh matches a developable spline only up to its sampling); the
// verdict allows solver::kKeptSheetTolerance of the extent, these designs keep 1e-6 (0.0003 mm
// over 300 mm).
constexpr double kHeldSheet = 1e-6;

double largestCoordinateChange(const model::CompositeSurface& a, const model::CompositeSurface& b) {
    double worst = 0.0;
    for (const auto& [id, p] : a.vertices()) {
        worst = std::max(worst, model::distance(p, b.position(id)));
    }
    for (const auto& [id, record] : a.edges()) {
        for (std::size_t k = 0; k < record.controlPoints.size(); ++k) {
            worst = std::max(worst,
                             model::distance(record.controlPoints[k], b.edge(id).controlPoints[k]));
        }
    }
    return worst;
}

// The largest |det(a−b, a′, b′)| / (|a−b| |a′| |b′|) over every strip of the design, sampled
// densely with derivatives by central differences: developability measured apart from the
// solver's collocation values and residuals.
double centralDifferenceDevelopability(const model::CompositeSurface& surface) {
    double worst = 0.0;
    const double h = 1e-6;
    for (const model::Strip& strip : model::stripsOf(surface)) {
        for (int i = 1; i < 400; ++i) {
            const double u = i / 400.0;
            const Vec3 a = strip.a.evaluate(u);
            const Vec3 b = strip.b.evaluate(u);
            const Vec3 da = (strip.a.evaluate(u + h) - strip.a.evaluate(u - h)) / (2 * h);
            const Vec3 db = (strip.b.evaluate(u + h) - strip.b.evaluate(u - h)) / (2 * h);
            const double scale = (a - b).norm() * da.norm() * db.norm();
            if (scale > 1e-9) {
                worst = std::max(worst, std::abs(model::det(a - b, da, db)) / scale);
            }
        }
    }
    return worst;
}

// The bounding box in x and y of a design's vertices or of a development.
struct Box {
    model::Vec2 low{1e300, 1e300};
    model::Vec2 high{-1e300, -1e300};
    void add(double x, double y) {
        low = {std::min(low.x, x), std::min(low.y, y)};
        high = {std::max(high.x, x), std::max(high.y, y)};
    }
};
Box boxOf(const model::CompositeSurface& s) {
    Box box;
    for (const auto& [id, p] : s.vertices()) {
        box.add(p.x, p.y);
    }
    return box;
}
Box boxOf(const std::vector<model::Vec2>& points) {
    Box box;
    for (const model::Vec2& p : points) {
        box.add(p.x, p.y);
    }
    return box;
}

// The vertices strictly inside the bounding square of a flat design.
std::vector<model::VertexId> innerVertices(const model::CompositeSurface& s) {
    const Box box = boxOf(s);
    std::vector<model::VertexId> inner;
    for (const auto& [id, p] : s.vertices()) {
        if (p.x > box.low.x + 1e-9 && p.x < box.high.x - 1e-9 && p.y > box.low.y + 1e-9 &&
            p.y < box.high.y - 1e-9) {
            inner.push_back(id);
        }
    }
    return inner;
}

using devsurf::model::kPi;

// The length of a design's rim at height z: its edges whose ends both lie there, rulings
// straight, S-edges as the chords between their samples at kSamples per interval (the sampled
// mesh a sheet is held on): the circumference of the cylinder a tube unrolls onto.
double rimLength(const model::CompositeSurface& s, double z) {
    double length = 0.0;
    for (const auto& [id, record] : s.edges()) {
        if (std::abs(s.position(record.from).z - z) > 1e-9 ||
            std::abs(s.position(record.to).z - z) > 1e-9) {
            continue;
        }
        if (!record.isSpline()) {
            length += model::distance(s.position(record.from), s.position(record.to));
            continue;
        }
        const model::BSplineCurve curve =
            model::BSplineCurve::uniform(record.space, record.controlPoints);
        const int steps = record.space.intervals * kSamples;
        for (int k = 0; k < steps; ++k) {
            length += model::distance(curve.evaluate(static_cast<double>(k) / steps),
                                      curve.evaluate(static_cast<double>(k + 1) / steps));
        }
    }
    return length;
}

solver::FormulationOptions withDevelopment() {
    solver::FormulationOptions options;
    options.developmentSamplesPerInterval = kSamples;
    return options;
}

} // namespace

class TstDevelopment : public QObject {
    Q_OBJECT

private slots:
    void rowsAndJacobians() {
        const model::CompositeSurface sheet = model::makeExample("sheet").surfaces.front();
        const solver::SurfaceFormulation f(sheet, withDevelopment());
        const solver::Problem& problem = f.problem();
        const model::SampledMesh* mesh = f.developmentMesh();
        QVERIFY(mesh != nullptr);
        QCOMPARE(problem.block("development").size, 2 * static_cast<int>(mesh->vertices.size()));
        int pairs = 0;
        for (const auto& face : mesh->faces) {
            pairs += static_cast<int>(face.size() * (face.size() - 1) / 2);
        }
        QCOMPARE(familyRows(problem, "development"), pairs);
        QVERIFY(familyRows(problem, "developmentFairness") > 0);
        std::mt19937 rng(11);
        const std::vector<double> x = solver::testing::randomVector(rng, problem.variableCount());
        const std::string wrong = solver::testing::termWithWrongJacobian(problem, x);
        QVERIFY2(wrong.empty(), wrong.c_str());
        QCOMPARE(familyRows(solver::SurfaceFormulation(sheet, {}).problem(), "development"), 0);
    }

    void flatDesignStaysPut() {
        const model::CompositeSurface sheet = model::makeExample("sheet").surfaces.front();
        const solver::SurfaceFormulation f(sheet, withDevelopment());
        std::vector<double> x = f.initialState();
        solver::Options options;
        options.maxIterations = 10;
        solver::GuidedProjection projection;
        const solver::Summary summary = projection.solve(f.problem(), x, options);
        QVERIFY(summary.succeeded());
        model::CompositeSurface solved = sheet;
        QVERIFY(f.writeBack(x, solved));
        QVERIFY(largestCoordinateChange(sheet, solved) < 1e-9);
        QVERIFY(pairLengthError(solved, f.development(x).vertices) < 1e-12);
    }

    void developmentKeptAcrossEdits() {
        model::CompositeSurface sheet = model::makeExample("sheet").surfaces.front();
        sheet.setKeepsDevelopment(true);
        QVERIFY(sheet.development().empty());
        solver::SolveSession session(sheet, {});
        QVERIFY(session.step(2).succeeded());
        const model::CompositeSurface solved = session.surface();
        QCOMPARE(solved.development().size(),
                 model::sampledVertexCount(solved, model::kDevelopmentSamplesPerInterval));
        QVERIFY(solved.validate().empty());
        QVERIFY(pairLengthError(solved, solved.development()) < 1e-12);
        // A development of the wrong size is a problem validate() names; a change of an
        // edge's orientation (which reorders its samples) empties it, the setting stays.
        model::CompositeSurface damaged = solved;
        std::vector<model::Vec2> shorter = solved.development();
        shorter.pop_back();
        damaged.setDevelopment(shorter);
        QVERIFY(!damaged.validate().empty());
        QCOMPARE(damaged.validate().front().code, model::ProblemCode::DevelopmentSize);
        model::CompositeSurface reversed = solved;
        reversed.reverseEdge(reversed.edges().begin()->first);
        QVERIFY(reversed.development().empty());
        QVERIFY(reversed.keepsDevelopment());
        QVERIFY(!(reversed == solved));
    }

    void impossibleLiftLagsAndKeepsTheSheet() {
        // Four corners of a flat square pinned: no isometric shape lifts its middle. The
        // vertices lag (they do not move), the surface stays developable and isometric to the
        // sheet; without the sheet held, the same drag is taken by stretching it.
        model::CompositeSurface sheet = model::makeExample("sheet").surfaces.front();
        const Box box = boxOf(sheet);
        for (const auto& [id, p] : sheet.vertices()) {
            const bool xEnd = std::abs(p.x - box.low.x) < 1e-9 || std::abs(p.x - box.high.x) < 1e-9;
            const bool yEnd = std::abs(p.y - box.low.y) < 1e-9 || std::abs(p.y - box.high.y) < 1e-9;
            if (xEnd && yEnd) {
                sheet.setPinned(id, true);
            }
        }
        QCOMPARE(static_cast<int>(sheet.pinnedVertices().size()), 4);
        const std::vector<model::VertexId> middle = innerVertices(sheet);
        QCOMPARE(static_cast<int>(middle.size()), 4);
        const Dragged stretched = dragUp(sheet, middle, 60.0);
        QVERIFY(stretched.largestGap < 1e-3); // followed the mouse: the sheet stretched
        QVERIFY(model::unfoldSampledMesh(model::sampleSurface(stretched.surface, kSamples))
                    .maxEdgeLengthError > 1e-3);

        sheet.setKeepsDevelopment(true);
        const Dragged held = dragUp(sheet, middle, 60.0);
        QVERIFY(held.summary.succeeded());
        QVERIFY2(held.largestGap > 59.0, qPrintable(QString::number(held.largestGap)));
        QVERIFY(solver::measureQuality(held.surface).developabilityMax < 1e-8);
        QVERIFY2(
            pairLengthError(held.surface, held.surface.development()) < kHeldSheet,
            qPrintable(QString::number(pairLengthError(held.surface, held.surface.development()))));
        QVERIFY(held.surface.validate().empty());
    }

    void theJobNeverReplaysAHeldSheetStretching() {
        // The same impossible lift through the solve job, lengths Automatic: no replay that
        // stretches the sheet; the assessment says the sheet holds the vertices back.
        model::CompositeSurface sheet = model::makeExample("sheet").surfaces.front();
        const Box box = boxOf(sheet);
        for (const auto& [id, p] : sheet.vertices()) {
            if ((p.x == box.low.x || p.x == box.high.x) &&
                (p.y == box.low.y || p.y == box.high.y)) {
                sheet.setPinned(id, true);
            }
        }
        QVERIFY(!model::keepDevelopment(sheet).has_value());
        const std::vector<model::VertexId> middle = innerVertices(sheet);
        const solver::JobOutcome outcome =
            solver::testing::dragThroughJob(sheet, 20, [&](solver::JobRequest& request, double t) {
                for (model::VertexId v : middle) {
                    request.pulled[0].push_back(
                        {v, false, sheet.position(v) + Vec3(0, 0, 60.0 * t)});
                }
            });
        QVERIFY(outcome.ok);
        const solver::SurfaceAssessment& a = outcome.assessments.front();
        QVERIFY(a.sheetHeld);
        QVERIFY(!a.replay.has_value());
        QVERIFY2(a.largestHandleGap > 59.0, qPrintable(QString::number(a.largestHandleGap)));
        const model::CompositeSurface& result = outcome.surfaces.front();
        QVERIFY(result.development() == sheet.development());
        QVERIFY2(pairLengthError(result, result.development()) < kHeldSheet,
                 qPrintable(QString::number(pairLengthError(result, result.development()))));
        QVERIFY(solver::measureQuality(result).developabilityMax < 1e-8);
        // A cylinder is no flat sheet: keepDevelopment holds it around the cylinder it unrolls
        // from, whose circumference is the length of its rim (measured here on the splines).
        model::CompositeSurface cylinder = model::makeExample("cylinder").surfaces.front();
        QVERIFY(!model::keepDevelopment(cylinder).has_value());
        QVERIFY(cylinder.keepsDevelopment());
        QCOMPARE(cylinder.sheetDomain().shape, model::SheetShape::Cylinder);
        QVERIFY2(std::abs(2.0 * kPi * cylinder.sheetDomain().radius - rimLength(cylinder, 0.0)) <
                     1e-6,
                 qPrintable(QString::number(cylinder.sheetDomain().radius)));
    }

    void theColumnStaysOnItsCylinder() {
        // The paper's Fig. 14: a pleated column keeps its development around a cylinder, the
        // development periodic modulo (2πr, 0). A top vertex lifted 30 mm through the solve
        // job: the column changes (its creases fold less), stays developable, and unrolls, as
        // measured from the geometry by a fresh unfolding, onto the same cylinder.
        const model::CompositeSurface start = model::makeExample("column").surfaces.front();
        QVERIFY(start.validate().empty());
        QVERIFY(start.keepsDevelopment());
        QCOMPARE(start.sheetDomain().shape, model::SheetShape::Cylinder);
        const double circumference = rimLength(start, 0.0);
        QVERIFY2(std::abs(2.0 * kPi * start.sheetDomain().radius - circumference) < 1e-9,
                 qPrintable(QString::number(circumference)));
        QVERIFY2(centralDifferenceDevelopability(start) < 1e-9,
                 qPrintable(QString::number(centralDifferenceDevelopability(start))));
        // The top vertex of a valley (odd index around), unpinned.
        model::VertexId top = model::kInvalidId;
        double highest = -1e300;
        for (const auto& [id, p] : start.vertices()) {
            if (p.z > highest - 1e-9 && std::abs(std::hypot(p.x, p.y) - 70.0) < 1e-9 && p.y > 0.0 &&
                p.x > 0.0) {
                highest = p.z;
                top = id;
            }
        }
        QVERIFY(top != model::kInvalidId);
        const Vec3 target = start.position(top) + Vec3(0.0, 0.0, 30.0);
        const solver::JobOutcome outcome = dragInJob(start, top, target, 20);
        QVERIFY2(outcome.ok, outcome.failure.detail.c_str());
        const model::CompositeSurface& s = outcome.surfaces.front();
        QVERIFY(!outcome.assessments.front().takenBack);
        QVERIFY(outcome.assessments.front().sheetHeld);
        const double rise = s.position(top).z - start.position(top).z;
        QVERIFY2(rise > 15.0, qPrintable(QString::number(rise)));
        const double developability = centralDifferenceDevelopability(s);
        QVERIFY2(developability < 1e-6, qPrintable(QString::number(developability)));
        const solver::CreaseQuality creases = solver::measureCreaseQuality(s);
        QVERIFY2(creases.residualMax < 1e-4, qPrintable(QString::number(creases.residualMax)));
        QVERIFY(solver::foldOvers(s).empty());
        const model::Development unrolled =
            model::unfoldSampledMesh(model::sampleSurface(s, kSamples));
        QCOMPARE(unrolled.components, 1);
        QVERIFY(unrolled.period.has_value());
        const double period = unrolled.period->norm();
        qInfo("rose %.1f mm, fold %.1f°, det %.2g, period %.9g mm of %.9g, closure %.2g mm, "
              "edge error %.2g",
              rise, creases.meanFoldDegrees, developability, period, circumference,
              unrolled.closureError, unrolled.maxEdgeLengthError);
        QVERIFY2(std::abs(period - circumference) < 1e-6 * circumference,
                 qPrintable(QString::number(period - circumference)));
        QVERIFY2(unrolled.closureError < 1e-6, qPrintable(QString::number(unrolled.closureError)));
        QVERIFY2(unrolled.maxEdgeLengthError < 1e-6,
                 qPrintable(QString::number(unrolled.maxEdgeLengthError)));
        // The kept development itself: periodic with the cylinder's period, isometric.
        QVERIFY2(model::keptSheetStretchRelative(s) < kHeldSheet,
                 qPrintable(QString::number(model::keptSheetStretchRelative(s))));
    }

    void fig8LiftFoldsTheSquare() {
        // The paper's Fig. 8, top row: the middle vertices lifted by 20 % of the diameter (85 mm
        // of a 300 mm square's 424 mm), the bottom corners pinned as the example comes, the
        // sheet held on the 300 × 300 mm square. It folds (a free sheet only tilts about the
        // pins: the flat start offers no first-order fold) and stays on the square. Not yet as
        // the paper's: the least curved crease (1.6 mm off its chord) is pulled straight.
        model::CompositeSurface fig8 = model::makeExample("fig8").surfaces.front();
        QVERIFY(!model::keepDevelopment(fig8).has_value());
        model::SheetDomain square;
        square.shape = model::SheetShape::Rectangle;
        square.width = 300.0;
        square.height = 300.0;
        const model::SampledMesh start = model::sampleSurface(fig8, kSamples);
        fig8.setSheetDomain(model::placeDomain(square, start, fig8.development()));
        const std::vector<model::VertexId> middle = innerVertices(fig8);
        QCOMPARE(static_cast<int>(middle.size()), 4);
        const Dragged lifted = dragUp(fig8, middle, 85.0);
        QVERIFY(lifted.summary.succeeded());
        const model::CompositeSurface& s = lifted.surface;
        QVERIFY(s.validate().empty());
        const double developability = solver::measureQuality(s).developabilityMax;
        QVERIFY2(developability < 1e-8, qPrintable(QString::number(developability)));
        const solver::CreaseQuality creases = solver::measureCreaseQuality(s);
        QVERIFY(creases.residualMax < 1e-8);
        QVERIFY2(creases.meanFoldDegrees > 5.0,
                 qPrintable(QString::number(creases.meanFoldDegrees)));
        QVERIFY2(pairLengthError(s, s.development()) < kHeldSheet,
                 qPrintable(QString::number(pairLengthError(s, s.development()))));
        QVERIFY(lifted.smallestRise > 40.0); // as far as the sheet lets it
        QVERIFY(solver::foldOvers(s).empty());
        // The development still lies on the 300 × 300 mm square the design started as.
        const model::SampledMesh mesh = model::sampleSurface(s, kSamples);
        const double gap = model::largestDomainGap(s.sheetDomain(), mesh, s.development());
        QVERIFY2(gap < 1e-6, qPrintable(QString::number(gap)));
        const Box sheet = boxOf(s.development());
        QVERIFY(std::abs(sheet.high.x - sheet.low.x - 300.0) < 1e-6);
        QVERIFY(std::abs(sheet.high.y - sheet.low.y - 300.0) < 1e-6);
    }

    void fig13FoldsTheDiskOnItsSheet() {
        // The paper's Fig. 13: the disk with one curved crease, held on its circle, the crease's
        // middle and the rim below it pinned as the example comes. The rim point above them is
        // pulled 60 mm up and 60 mm over in 100 moves through the solve job, as the Drag tool
        // does: the disk folds along its crease (its rulings move in the sheet), stays
        // developable, and its development stays the 150 mm disk.
        const model::CompositeSurface start = model::makeExample("fig13").surfaces.front();
        QVERIFY(start.keepsDevelopment());
        QCOMPARE(start.sheetDomain().shape, model::SheetShape::Disk);
        const model::VertexId top = solver::testing::fig13Top(start);
        QVERIFY(top != model::kInvalidId);
        const Vec3 target = start.position(top) + Vec3(0.0, -60.0, 60.0);
        const solver::JobOutcome outcome = dragInJob(start, top, target, 100);
        QVERIFY2(outcome.ok, outcome.failure.detail.c_str());
        const model::CompositeSurface& s = outcome.surfaces.front();
        QVERIFY(s.validate().empty());
        QVERIFY(outcome.assessments.front().sheetHeld);
        const double developability = centralDifferenceDevelopability(s);
        QVERIFY2(developability < 1e-6, qPrintable(QString::number(developability)));
        const solver::CreaseQuality creases = solver::measureCreaseQuality(s);
        QVERIFY2(creases.residualMax < 1e-4, qPrintable(QString::number(creases.residualMax)));
        // Measured 53°; flat (0°) when the development is fixed instead of confined.
        QVERIFY2(creases.meanFoldDegrees > 30.0,
                 qPrintable(QString::number(creases.meanFoldDegrees)));
        QVERIFY(model::distance(s.position(top), start.position(top)) > 40.0);
        QVERIFY2(pairLengthError(s, s.development()) < kHeldSheet,
                 qPrintable(QString::number(pairLengthError(s, s.development()))));
        QVERIFY(solver::foldOvers(s).empty());
        const double gap = model::largestDomainGap(
            s.sheetDomain(), model::sampleSurface(s, kSamples), s.development());
        qInfo("fold %.1f°, det %.2g, crease residual %.2g, on the circle to %.2g mm",
              creases.meanFoldDegrees, developability, creases.residualMax, gap);
        QVERIFY2(gap < 1e-4, qPrintable(QString::number(gap))); // measured 2e-6 mm
        QCOMPARE(s.sheetDomain().radius, 150.0);
    }

    void aTorusHasNoOneSheetButIsReadyToCut() {
        // The paper's Fig. 15b: a torus of cone bands has local conditions only. It cannot hold
        // a sheet; Solve leaves it where it is and judges it ready to cut, its development
        // measured on the pieces of its cutting pattern (one per band), not on one unfolding
        // that cannot close up.
        model::CompositeSurface torus = model::makeExample("torus").surfaces.front();
        const auto refused = model::keepDevelopment(torus);
        QVERIFY(refused && refused->code == model::ProblemCode::NotOneSheet);
        QVERIFY2(centralDifferenceDevelopability(torus) < 1e-9,
                 qPrintable(QString::number(centralDifferenceDevelopability(torus))));
        double defect = 0.0;
        for (const solver::VertexAngleDefect& star : solver::vertexAngleDefects(torus)) {
            defect = std::max(defect, star.defect);
        }
        QVERIFY2(defect < 1e-9, qPrintable(QString::number(defect)));
        solver::JobRequest request;
        request.surfaces = {torus};
        const solver::JobOutcome outcome = solver::SolveJob().run(request);
        QVERIFY2(outcome.ok, outcome.failure.detail.c_str());
        const solver::SurfaceAssessment& a = outcome.assessments.front();
        QVERIFY(a.overlapping.empty());
        QVERIFY(a.foldOvers.empty());
        QVERIFY2(a.isometryMm >= 0.0 && a.isometryMm < 1e-6,
                 qPrintable(QString::number(a.isometryMm)));
        QVERIFY(a.sheetExtent > 100.0 && a.sheetExtent < 1000.0); // a band, not the torus unrolled
        QCOMPARE(solver::verdictOf(outcome).kind, solver::VerdictKind::ReadyToCut);
        QVERIFY(largestCoordinateChange(torus, outcome.surfaces.front()) < 1e-6);
    }

    void theFoldedRingIsReadyToCutFromItsSheet() {
        // fig12, a ring folded exactly along concentric curved creases, holding its lobed ring
        // of a sheet (an outline): developable and folded as built (sampled independently);
        // Solve leaves it where it is and judges it ready to cut, neither overlapping itself
        // nor off isometric by more than the splines' fine sampling allows (its pattern is laid
        // onto the kept sheet, the curves between its samples turning 0.004 rad further
        // around than the sheet: 0.0047 mm measured).
        const model::CompositeSurface ring = model::makeExample("fig12").surfaces.front();
        QVERIFY2(centralDifferenceDevelopability(ring) < 1e-8,
                 qPrintable(QString::number(centralDifferenceDevelopability(ring))));
        solver::JobRequest request;
        request.surfaces = {ring};
        const solver::JobOutcome outcome = solver::SolveJob().run(request);
        QVERIFY2(outcome.ok, outcome.failure.detail.c_str());
        const solver::SurfaceAssessment& a = outcome.assessments.front();
        QVERIFY(a.overlapping.empty());
        QVERIFY(a.foldOvers.empty());
        QVERIFY2(a.isometryMm >= 0.0 && a.isometryMm < 0.01,
                 qPrintable(QString::number(a.isometryMm)));
        QCOMPARE(solver::verdictOf(outcome).kind, solver::VerdictKind::ReadyToCut);
        const model::CompositeSurface& solved = outcome.surfaces.front();
        QVERIFY(largestCoordinateChange(ring, solved) < 1e-3);
        QVERIFY2(model::keptSheetStretch(solved) < 1e-6,
                 qPrintable(QString::number(model::keptSheetStretch(solved))));
        const double gap = model::largestDomainGap(
            solved.sheetDomain(), model::sampleSurface(solved, kSamples), solved.development());
        QVERIFY2(gap < 1e-6, qPrintable(QString::number(gap)));
    }
};

DEVSURF_REGISTER_TEST(TstDevelopment);

#include "tst_development.moc"
