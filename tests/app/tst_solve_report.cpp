// The Solver panel's report of a result (SolveController::reportOf): fold-overs, overlapping
// developments and drags replayed letting the sheet stretch, with the patches to check.
#include "folded_strip.h"
#include "main_window.h"
#include "model/document/document.h"
#include "model/document/selection.h"
#include "panels/solver_panel.h"
#include "solve_controller.h"
#include "solver/quality/shape_change.h"
#include "solver/worker/solver_worker.h"
#include "test_registry.h"
#include "workspace.h"

#include <QPushButton>
#include <QRegularExpression>
#include <QTest>

#include <set>

using namespace devsurf;

namespace {

// A result of one iteration that reached the tolerance on `surface`, as the worker hands it over.
// Measured as the solve job measures a settled result (fold-overs from the geometry).
solver::SolveResult solvedResult(const model::CompositeSurface& surface) {
    solver::SolveResult result;
    solver::JobOutcome& outcome = result.outcome;
    outcome.ok = true;
    outcome.settled = true;
    outcome.assessments.resize(1);
    solver::SurfaceAssessment& a = outcome.assessments[0];
    a.solved = true;
    a.measured = true;
    a.summary.iterations.resize(1);
    a.summary.iterationsCompleted = 1;
    a.summary.toleranceReached = true;
    a.foldOvers = solver::foldOvers(surface);
    outcome.surfaces = {surface};
    return result;
}

} // namespace

class TstSolveReport : public QObject {
    Q_OBJECT

private slots:
    void aResultThatFoldsOverOntoItselfIsReportedWithItsPatches() {
        app::MainWindow window;
        solver::SolveResult result = solvedResult(test::flatStrip(-150.0));
        const app::SolveReport folded = window.solveController()->reportOf(result, "Drag 1 vertex");
        QCOMPARE(folded.foldedOver, QList<int>{0});
        // (English plural forms apply once the application's translators are installed.)
        QVERIFY2(folded.status.contains(QRegularExpression(QStringLiteral(
                     "1 patch(\\(es\\) fold over onto themselves| folds over onto itself)"))) &&
                     folded.status.contains(QStringLiteral("overlaps itself: 0")),
                 qPrintable(folded.status));
        // The Solver panel's button selects the patch (face 0 of surface 0) in the views.
        window.workspace()->newFromExample(QStringLiteral("sheet"), 0);
        const std::set<document::Pick> patch{{document::Pick::Kind::Face, 0, 0}};
        QVERIFY(folded.patchesToCheck == patch);
        window.solverPanel()->showReport(folded);
        QPushButton* select = window.solverPanel()->selectPatchesButton();
        QVERIFY(select->isEnabled());
        select->click();
        QVERIFY(window.workspace()->selection()->picks() == patch);

        result = solvedResult(test::flatStrip(100.0));
        const app::SolveReport flat = window.solveController()->reportOf(result, "Drag 1 vertex");
        QVERIFY(flat.foldedOver.isEmpty() && flat.patchesToCheck.empty());
        QVERIFY2(!flat.status.contains(QStringLiteral("fold over")), qPrintable(flat.status));
        window.solverPanel()->showReport(flat);
        QVERIFY(!select->isEnabled());
    }

    void aResultWhoseDevelopmentOverlapsItselfIsReportedWithItsPatches() {
        // Every condition holds and no patch folds over, but the development overlaps itself
        // at patches 1 and 2 (as the worker measures for a final result): said in the status
        // and selectable, like a fold-over.
        app::MainWindow window;
        window.workspace()->newFromExample(QStringLiteral("sheet"), 0);
        solver::SolveResult result =
            solvedResult(window.workspace()->document()->project().surfaces.front());
        result.outcome.assessments[0].overlapping = {1, 2};
        const app::SolveReport report = window.solveController()->reportOf(result, "Solve");
        QVERIFY(report.foldedOver.isEmpty());
        QCOMPARE(report.overlapping, (QList<int>{1, 2}));
        QVERIFY2(report.status.contains(QStringLiteral("development overlaps itself")) &&
                     report.status.contains(QStringLiteral("(1, 2)")) &&
                     report.status.contains(QStringLiteral("cannot be cut from one sheet")),
                 qPrintable(report.status));
        const std::set<document::Pick> patches{{document::Pick::Kind::Face, 0, 1},
                                               {document::Pick::Kind::Face, 0, 2}};
        QVERIFY(report.patchesToCheck == patches);
        window.solverPanel()->showReport(report);
        QPushButton* select = window.solverPanel()->selectPatchesButton();
        QVERIFY(select->isEnabled());
        select->click();
        QVERIFY(window.workspace()->selection()->picks() == patches);

        result.outcome.assessments[0].overlapping.clear();
        const app::SolveReport clean = window.solveController()->reportOf(result, "Solve");
        QVERIFY(clean.overlapping.isEmpty() && clean.patchesToCheck.empty());
        QVERIFY2(!clean.status.contains(QStringLiteral("overlaps")), qPrintable(clean.status));
    }

    void aDragReplayedStretchingSaysWhyKeepingLengthsFailed() {
        // Lengths While Dragging ▸ Automatic: the worker lists a surface whose drag it replayed
        // stretching, with what went wrong keeping lengths; the report says so in those words.
        app::MainWindow window;
        window.workspace()->newFromExample(QStringLiteral("sheet"), 0);
        solver::SolveResult result =
            solvedResult(window.workspace()->document()->project().surfaces.front());
        solver::DragOutcome kept;
        kept.residual = 10 * solver::kDragConvergedResidual;
        kept.foldOverPlaces = 2;
        kept.overlapping = {3};
        result.outcome.assessments[0].replay = solver::LengthsReplay{kept, {}, true};
        const app::SolveReport report =
            window.solveController()->reportOf(result, "Drag 4 vertices");
        QVERIFY2(
            report.status.contains(QRegularExpression(QStringLiteral(
                "keeping lengths failed \\(no convergence, residual 1\\.0e-03, folded over in 2 "
                "place(\\(s\\)|s), a development overlapping itself\\), so the drag was "
                "replayed letting the sheet stretch"))),
            qPrintable(report.status));
        result.outcome.assessments[0].replay.reset();
        const app::SolveReport plain =
            window.solveController()->reportOf(result, "Drag 4 vertices");
        QVERIFY2(!plain.status.contains(QStringLiteral("replayed")), qPrintable(plain.status));
    }
};

DEVSURF_REGISTER_TEST(TstSolveReport);
#include "tst_solve_report.moc"
