// The verdict of a solve (solver::verdictOf, worded by VerdictText): one plain sentence in the
// Solver panel, its short form in both views' corner, the same in `devsurf-cli solve`; it
// follows the undo state like the panel.
#include "cli_run.h"
#include "main_window.h"
#include "model/document/commands/move_vertices_command.h"
#include "model/document/document.h"
#include "panels/solver_panel.h"
#include "solve_controller.h"
#include "test_registry.h"
#include "verdict_text.h"
#include "views/development_view.h"
#include "views/surface_view.h"
#include "window_test_support.h"
#include "workspace.h"

#include <QLabel>
#include <QRegularExpression>
#include <QSettings>
#include <QTemporaryDir>
#include <QTest>
#include <QUndoStack>

using namespace devsurf;

class TstVerdict : public QObject {
    Q_OBJECT

    static QString solveOnce(app::MainWindow& window) {
        window.action(QStringLiteral("actionSolve"))->trigger();
        return test::waitForSolve(window);
    }

    // Both views write the panel's verdict in its short form.
    static void checkViewsShow(app::MainWindow& window, const QString& brief) {
        QCOMPARE(window.surfaceView()->verdictText(), brief);
        QCOMPARE(window.developmentView()->verdictText(), brief);
    }

private slots:
    void init() { QSettings().clear(); }

    void anUnchangedExampleIsReadyToCut() {
        app::MainWindow window;
        window.show();
        window.workspace()->newFromExample(QStringLiteral("sheet"), 0);
        checkViewsShow(window, QString()); // no solve yet: no verdict
        QVERIFY(window.solverPanel()->verdictText().isEmpty());
        const QString sentence = solveOnce(window);
        const solver::Verdict& verdict = window.solverPanel()->report().verdict;
        QVERIFY2(verdict.kind == solver::VerdictKind::ReadyToCut, qPrintable(sentence));
        QVERIFY(verdict.residual <= verdict.tolerance && verdict.tolerance > 0.0);
        QCOMPARE(window.solverPanel()->verdictText(), app::VerdictText::of(verdict));
        checkViewsShow(window, app::VerdictText::brief(verdict));
        // The status bar's sentence starts with it.
        QVERIFY2(sentence.startsWith(app::VerdictText::brief(verdict)), qPrintable(sentence));
        // The numbers are on demand: the verdict's tooltip.
        auto* label = window.solverPanel()->findChild<QLabel*>(QStringLiteral("SolverVerdict"));
        QVERIFY(label != nullptr && label->isVisibleTo(window.solverPanel()));
        QCOMPARE(label->toolTip(), app::VerdictText::details(verdict));
        // The flat 300 mm sheet develops onto itself: the sheet's extent is its side.
        QVERIFY2(std::abs(verdict.sheetExtent - 300.0) < 1.0,
                 qPrintable(QString::number(verdict.sheetExtent)));
        QVERIFY(verdict.isometryMm >= 0.0 && verdict.isometryMm < 1e-6);
    }

    void aSolveThatStopsFarOffSaysWhereAndWhatToTry() {
        QSettings().setValue(QStringLiteral("solver/iterations"), 1);
        app::MainWindow window;
        window.show();
        window.workspace()->newFromExample(QStringLiteral("fig8"), 0);
        document::Document* doc = window.workspace()->document();
        // The middle vertices lifted far without the surface following: far from developable.
        auto lift = document::MoveVerticesCommand::createTranslation(*doc, 0, {5, 6, 9, 10},
                                                                     model::Vec3(0.0, 0.0, 60.0));
        QVERIFY(!lift.isRefused());
        doc->undoStack()->push(lift.takeCommand().release());
        solveOnce(window);
        const solver::Verdict verdict = window.solverPanel()->report().verdict;
        QCOMPARE(verdict.kind, solver::VerdictKind::NotDevelopable);
        QVERIFY(!verdict.patches.empty());
        QVERIFY(verdict.solveMore);   // one iteration only
        QVERIFY(verdict.releasePins); // fig8's bottom corners are pinned
        QVERIFY(verdict.edgeLengthError > 1e-4);
        const QString text = window.solverPanel()->verdictText();
        QVERIFY2(text.contains(QString::number(verdict.patches.front().second)), qPrintable(text));
        checkViewsShow(window, app::VerdictText::brief(verdict));
        QVERIFY(!window.surfaceView()->verdictRect().isEmpty());

        // Undo: the design on screen has no solve, so no verdict anywhere; redo brings it back.
        doc->undoStack()->undo();
        QVERIFY(window.solverPanel()->verdictText().isEmpty());
        checkViewsShow(window, QString());
        QVERIFY(window.surfaceView()->verdictRect().isEmpty());
        doc->undoStack()->redo();
        checkViewsShow(window, app::VerdictText::brief(verdict));
    }

    void anOverlappingDevelopmentAloneIsSaidSo() {
        // A release developable patch by patch whose development overlaps itself (the rings of
        // a lifted annulus): it cannot be cut from one piece, and the verdict says that rather
        // than "not developable"; with a fold-over as well it is not developable.
        solver::JobOutcome outcome;
        outcome.ok = true;
        outcome.settled = true;
        solver::SurfaceAssessment a;
        a.solved = true;
        a.measured = true;
        a.summary.finalMaxConstraintResidual = 1e-13;
        a.summary.tolerance = 1e-8;
        a.summary.toleranceReached = true;
        a.edgeLengthError = 1e-9;
        a.sheetExtent = 500.0;
        a.isometryMm = 5e-7;
        a.overlapping = {245, 246};
        outcome.assessments = {a};
        const solver::Verdict overlap = solver::verdictOf(outcome);
        QCOMPARE(overlap.kind, solver::VerdictKind::NotDevelopable);
        QVERIFY(overlap.overlapsOnly);
        QVERIFY(overlap.undoLastStep);
        const QString notDevelopable = app::VerdictText::tr("Not developable");
        for (const QString& text :
             {app::VerdictText::of(overlap), app::VerdictText::brief(overlap)}) {
            QVERIFY2(text.contains(QStringLiteral("245, 246")), qPrintable(text));
            QVERIFY2(!text.startsWith(notDevelopable), qPrintable(text));
        }
        outcome.assessments.front().foldOvers = {{17, 2}};
        const solver::Verdict folded = solver::verdictOf(outcome);
        QCOMPARE(folded.kind, solver::VerdictKind::NotDevelopable);
        QVERIFY(!folded.overlapsOnly);
        QVERIFY(app::VerdictText::of(folded).startsWith(notDevelopable));
        QVERIFY(app::VerdictText::brief(folded).startsWith(notDevelopable));
        // Short of the tolerance and far off (the unfolding stretches 1 %): not only an overlap.
        outcome.assessments.front().foldOvers.clear();
        outcome.assessments.front().summary.toleranceReached = false;
        outcome.assessments.front().summary.finalMaxConstraintResidual = 1e-3;
        outcome.assessments.front().edgeLengthError = 1e-2;
        QVERIFY(!solver::verdictOf(outcome).overlapsOnly);
    }

    void theCommandLineGivesTheSameVerdictWithItsLength() {
        // A flat sheet whose vertex 5 was pulled up letting it stretch, then solved for one
        // iteration: the tolerance is not reached, but the sheet is close to its development.
        QTemporaryDir dir;
        const QString sheet = dir.filePath(QStringLiteral("sheet.devsurf"));
        const QString pulled = dir.filePath(QStringLiteral("pulled.devsurf"));
        const QString solved = dir.filePath(QStringLiteral("solved.devsurf"));
        QCOMPARE(test::runCli({"example", "sheet", "--as-built", "-o", sheet}).exitCode, 0);
        QCOMPARE(test::runCli({"drag", sheet, "--vertices", "5", "--by", "0,0,80", "--steps", "2",
                               "--after", "0", "--stretch", "-o", pulled})
                     .exitCode,
                 0);
        const test::CliRun run = test::runCli({"solve", pulled, "--iterations", "1", "-o", solved});
        QCOMPARE(run.exitCode, 0);
        const QRegularExpression within(
            QStringLiteral("Verdict: Developable to within ([0-9.e-]+) mm of isometry over the "
                           "sheet: the cut pattern is off by at most \\1 mm\\."));
        const QRegularExpressionMatch match = within.match(run.out);
        QVERIFY2(match.hasMatch(), qPrintable(run.out));
        const double mm = match.captured(1).toDouble();
        // The length is the development's relative edge-length error over the sheet's extent.
        const QRegularExpression numbers(
            QStringLiteral("edge-length error ([0-9.e+-]+) over a sheet of ([0-9]+) mm"));
        const QRegularExpressionMatch measured = numbers.match(run.out);
        QVERIFY2(measured.hasMatch(), qPrintable(run.out));
        const double error = measured.captured(1).toDouble();
        const double extent = measured.captured(2).toDouble();
        QVERIFY(extent > 300.0 && extent < 330.0); // the 300 mm sheet, pulled up 80 mm
        QVERIFY2(mm > 0.0 && std::abs(mm - error * extent) <= 0.1 * mm,
                 qPrintable(QStringLiteral("%1 mm, %2 × %3").arg(mm).arg(error).arg(extent)));
        QVERIFY(mm < 1.0);
    }
};

DEVSURF_REGISTER_TEST(TstVerdict);
#include "tst_verdict.moc"
