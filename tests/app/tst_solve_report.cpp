// The Solver panel's report of a result (SolveController::reportOf): fold-overs, overlapping
// developments, drags replayed letting the sheet stretch and settlings that stalled, with the
// patches to check.
#include "folded_strip.h"
#include "main_window.h"
#include "model/document/commands/move_vertices_command.h"
#include "model/document/document.h"
#include "model/document/selection.h"
#include "panels/solver_panel.h"
#include "solve_controller.h"
#include "solver/quality/shape_change.h"
#include "solver/worker/solver_worker.h"
#include "test_registry.h"
#include "window_test_support.h"
#include "workspace.h"

#include <QPushButton>
#include <QTemporaryDir>
#include <QTest>
#include <QUndoStack>

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
    void aDragFollowedPartOfTheWaySaysHowFarAndWhy() {
        // A release that would have folded over, followed instead to a state a quarter of the
        // way: the status says the share, the lag and what the whole drag would have broken.
        solver::SolveResult result = solvedResult(test::flatStrip(100.0));
        solver::SurfaceAssessment refused;
        refused.solved = true;
        refused.measured = true;
        refused.foldOvers = {{0, 2}};
        solver::SurfaceAssessment& a = result.outcome.assessments[0];
        a.takenBack = std::make_shared<const solver::SurfaceAssessment>(refused);
        a.followed = 0.25;
        a.largestHandleGap = 12.5;
        const app::SolveReport report =
            app::SolveController::reportOf(result, QStringLiteral("Drag 1 vertex"));
        const QString why = app::SolveController::takenBackText(refused);
        QVERIFY2(!why.isEmpty() && report.status.contains(why), qPrintable(report.status));
        QVERIFY2(report.status.contains(QStringLiteral("25")), qPrintable(report.status));
        QVERIFY2(report.status.contains(QStringLiteral("12.5")), qPrintable(report.status));
        // The Solver panel's table lists the iterations that settled the state kept, not the
        // refused release's.
        refused.summary.iterations.resize(5);
        a.takenBack = std::make_shared<const solver::SurfaceAssessment>(refused);
        const app::SolveReport partway =
            app::SolveController::reportOf(result, QStringLiteral("Drag 1 vertex"));
        QCOMPARE(partway.summaries.size(), std::size_t(1));
        QCOMPARE(partway.summaries.front().iterations.size(), a.summary.iterations.size());
        // Taken back whole (followed 0), it says so instead, and lists the refused release.
        a.followed = 0.0;
        const app::SolveReport whole =
            app::SolveController::reportOf(result, QStringLiteral("Drag 1 vertex"));
        QVERIFY(whole.status != report.status && whole.status.contains(why));
        QCOMPARE(whole.summaries.front().iterations.size(), std::size_t(5));
    }

    void aResultThatFoldsOverOntoItselfIsReportedWithItsPatches() {
        app::MainWindow window;
        solver::SolveResult result = solvedResult(test::flatStrip(-150.0));
        const app::SolveReport folded = window.solveController()->reportOf(result, "Drag 1 vertex");
        QCOMPARE(folded.foldedOver, QList<int>{0});
        QCOMPARE(folded.outcome.assessments.front().foldOvers.size(), std::size_t(1));
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
        // The fold-over is said in the status: it is longer than the one without, by a clause
        // naming patch 0.
        QVERIFY2(folded.status.size() > flat.status.size() && !flat.status.isEmpty(),
                 qPrintable(folded.status));
        QVERIFY(folded.status.startsWith(flat.status.chopped(1))); // without the full stop
        QVERIFY(folded.status.mid(flat.status.size() - 1).contains(QStringLiteral("0")));
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
        QVERIFY2(report.status.contains(QStringLiteral("1, 2")), qPrintable(report.status));
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
        // The overlap is said in a clause of its own after the clean result's status.
        QVERIFY(!clean.status.isEmpty());
        QVERIFY2(report.status.startsWith(clean.status.chopped(1)) &&
                     report.status.size() > clean.status.size(),
                 qPrintable(report.status));
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
        // The status says what went wrong keeping lengths: the residual, the places folded over
        // and the overlap, each in the words of problemsText().
        const QString problems = app::SolveController::problemsText(kept);
        QVERIFY(!problems.isEmpty());
        QVERIFY2(problems.contains(QStringLiteral("1.0e-03")) &&
                     problems.contains(QStringLiteral("2")),
                 qPrintable(problems));
        solver::DragOutcome residualOnly = kept;
        residualOnly.foldOverPlaces = 0;
        residualOnly.overlapping.clear();
        const QString residualText = app::SolveController::problemsText(residualOnly);
        QVERIFY(!residualText.isEmpty() && problems.startsWith(residualText));
        QVERIFY(problems.size() > residualText.size());
        QVERIFY2(report.status.contains(problems), qPrintable(report.status));
        result.outcome.assessments[0].replay.reset();
        const app::SolveReport plain =
            window.solveController()->reportOf(result, "Drag 4 vertices");
        QVERIFY2(!plain.status.contains(problems), qPrintable(plain.status));
        QVERIFY(report.status.startsWith(plain.status.chopped(1)));
    }

    void aStalledSettlingSaysWhenItStopped() {
        // A held settling that stopped before its limit (SolveSession::stalled) says after how
        // many iterations and why, instead of "iteration limit reached"; one that reached the
        // tolerance still says so.
        solver::SolveResult result = solvedResult(test::flatStrip(100.0));
        solver::SurfaceAssessment& a = result.outcome.assessments[0];
        a.summary.toleranceReached = false;
        a.summary.status = solver::Status::IterationLimit;
        app::MainWindow window;
        const QString limit = window.solveController()->reportOf(result, "Drag 1 vertex").status;
        a.stalledAfter = 38;
        const QString stalled = window.solveController()->reportOf(result, "Drag 1 vertex").status;
        // In the language the tests run in (English, German).
        const QString limitReached = app::SolveController::tr("iteration limit reached");
        QVERIFY2(limit.contains(limitReached), qPrintable(limit));
        QVERIFY2(stalled.contains(QStringLiteral("38")) && !stalled.contains(limitReached),
                 qPrintable(stalled));
        a.summary.toleranceReached = true;
        const QString reached = window.solveController()->reportOf(result, "Drag 1 vertex").status;
        QVERIFY2(reached.contains(app::SolveController::tr("tolerance reached")) &&
                     !reached.contains(QStringLiteral("38")),
                 qPrintable(reached));
    }
};

DEVSURF_REGISTER_TEST(TstSolveReport);

// The Solver panel shows the design on screen: a new or opened design, an edit, undo or redo
// leave no report of another state behind.
class TstSolverPanelFollows : public QObject {
    Q_OBJECT

    // Lifts a vertex of the annulus and solves it: one "Solve" step with its report.
    static bool liftAndSolve(app::MainWindow& window) {
        document::Document* doc = window.workspace()->document();
        doc->undoStack()->push(document::MoveVerticesCommand::createTranslation(
                                   *doc, 0, {21}, model::Vec3(0.0, 0.0, 5.0))
                                   .takeCommand()
                                   .release());
        window.action(QStringLiteral("actionSolve"))->trigger();
        test::waitForSolve(window);
        return window.solveController()->lastEnding() == app::SolveController::Ending::Solved &&
               doc->undoStack()->count() == 2 && window.solverPanel()->hasReport();
    }

private slots:
    void aNewDesignShowsNoReportOfTheOldOne() {
        app::MainWindow window;
        window.workspace()->newFromExample(QStringLiteral("annulus"), 0);
        QVERIFY(!window.solverPanel()->hasReport());
        QVERIFY(liftAndSolve(window));
        QVERIFY(window.solverPanel()->iterationRows() > 0);
        const QString solvedText = window.solverPanel()->statusText();
        window.workspace()->newFromExample(QStringLiteral("fig8"), 0);
        QVERIFY(!window.solverPanel()->hasReport());
        QCOMPARE(window.solverPanel()->iterationRows(), 0);
        QVERIFY(window.solverPanel()->statusText() != solvedText);
        QVERIFY(!window.solverPanel()->selectPatchesButton()->isEnabled());
        QVERIFY(window.solverPanel()->report().summaries.empty());
    }

    void anOpenedDesignShowsNoReportOfTheOldOne() {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const QString path = dir.filePath(QStringLiteral("fig8.devsurf"));
        {
            app::MainWindow saver;
            saver.workspace()->newFromExample(QStringLiteral("fig8"), 0);
            QVERIFY(saver.workspace()->saveTo(path));
        }
        app::MainWindow window;
        window.workspace()->newFromExample(QStringLiteral("annulus"), 0);
        QVERIFY(liftAndSolve(window));
        QVERIFY(window.workspace()->open(path));
        QVERIFY(!window.solverPanel()->hasReport());
        QCOMPARE(window.solverPanel()->iterationRows(), 0);
        QVERIFY(!window.solverPanel()->selectPatchesButton()->isEnabled());
    }

    void undoAndRedoShowTheReportOfTheStateReached() {
        app::MainWindow window;
        window.workspace()->newFromExample(QStringLiteral("annulus"), 0);
        QVERIFY(liftAndSolve(window));
        QUndoStack* stack = window.workspace()->document()->undoStack();
        const int rows = window.solverPanel()->iterationRows();
        const QString solvedText = window.solverPanel()->statusText();
        stack->undo(); // the lift, not solved
        QVERIFY(!window.solverPanel()->hasReport());
        QCOMPARE(window.solverPanel()->iterationRows(), 0);
        QVERIFY(window.solverPanel()->statusText() != solvedText);
        stack->redo(); // the solved design again: its report
        QVERIFY(window.solverPanel()->hasReport());
        QCOMPARE(window.solverPanel()->iterationRows(), rows);
        QCOMPARE(window.solverPanel()->statusText(), solvedText);
        // An edit after the solve: the report no longer describes the design; its undo does.
        document::Document* doc = window.workspace()->document();
        stack->push(document::MoveVerticesCommand::createTranslation(*doc, 0, {3},
                                                                     model::Vec3(1.0, 0.0, 0.0))
                        .takeCommand()
                        .release());
        QVERIFY(!window.solverPanel()->hasReport());
        stack->undo();
        QVERIFY(window.solverPanel()->hasReport());
        QCOMPARE(window.solverPanel()->statusText(), solvedText);
        // Undoing to the lift and editing anew drops the solved state and its report.
        stack->undo();
        stack->push(document::MoveVerticesCommand::createTranslation(*doc, 0, {3},
                                                                     model::Vec3(1.0, 0.0, 0.0))
                        .takeCommand()
                        .release());
        QVERIFY(!window.solverPanel()->hasReport());
        QVERIFY(!stack->canRedo());
    }
};

DEVSURF_REGISTER_TEST(TstSolverPanelFollows);
#include "tst_solve_report.moc"
