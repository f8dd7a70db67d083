// The Drag tool: live moves, one undo step on release, Esc, pins that hold a vertex.
#include "drag_tool.h"
#include "io/project_file.h"
#include "main_window.h"
#include "model/development.h"
#include "model/document/commands/apply_surface_command.h"
#include "model/document/commands/move_vertices_command.h"
#include "model/document/commands/pin_vertices_command.h"
#include "model/document/document.h"
#include "model/document/selection.h"
#include "model/examples.h"
#include "model/sampled_mesh.h"
#include "model/sheet_domain.h"
#include "panels/solver_panel.h"
#include "solve_controller.h"
#include "solver/quality/crease_quality.h"
#include "solver/quality/quality_measures.h"
#include "solver/session/verdict.h"
#include "solver/worker/solver_worker.h"
#include "test_registry.h"
#include "views/development_view.h"
#include "views/surface_view.h"
#include "views/vtk_opengl_widget.h"
#include "window_test_support.h"
#include "workspace.h"

#include <QAction>
#include <QApplication>
#include <QMenu>
#include <QSettings>
#include <QSignalSpy>
#include <QTest>
#include <QTimer>
#include <QUndoStack>

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>

using namespace devsurf;
using document::Pick;
using test::bytesOf;
using test::showActiveWithExample;

namespace {

// The window on the flat `sheet` holding its sheet on its 300 × 300 mm rectangle, its bottom
// corners (vertices 0 and 3) pinned.
bool showSheetHeldOnItsSquare(app::MainWindow& window) {
    if (!showActiveWithExample(window, QStringLiteral("sheet"))) {
        return false;
    }
    document::Document* doc = window.workspace()->document();
    model::Project project = doc->project();
    model::CompositeSurface& s = project.surfaces.front();
    if (model::keepDevelopment(s).has_value()) {
        return false;
    }
    model::SheetDomain square;
    square.shape = model::SheetShape::Rectangle;
    square.width = 300.0;
    square.height = 300.0;
    s.setSheetDomain(model::placeDomain(square, model::sampleSurface(s, 2), s.development()));
    s.setPinned(0, true);
    s.setPinned(3, true);
    doc->resetProject(project);
    return true;
}

} // namespace
using test::waitForWorkerIdle;

class TstDrag : public QObject {
    Q_OBJECT

    // A shown window with the annulus, vertex `dragged` and `other` selected, `pinned` pinned,
    // and the Drag tool on.
    struct Setup {
        app::MainWindow window;
        document::Document* doc = nullptr;
        QWidget* gl = nullptr;
        QPoint at;
    };
    static constexpr model::VertexId kDragged = 20;
    static constexpr model::VertexId kOther = 21;
    static constexpr model::VertexId kPinned = 0;

    static bool prepare(Setup& s) {
        if (!showActiveWithExample(s.window, QStringLiteral("annulus"))) {
            return false;
        }
        s.doc = s.window.workspace()->document();
        s.doc->undoStack()->push(document::PinVerticesCommand::create(*s.doc, 0, {kPinned}, true)
                                     .takeCommand()
                                     .release());
        s.window.workspace()->selection()->set(
            {{Pick::Kind::Vertex, 0, kDragged}, {Pick::Kind::Vertex, 0, kOther}});
        s.window.action(QStringLiteral("actionDragTool"))->setChecked(true);
        s.gl = s.window.surfaceView()->glWidget();
        s.window.surfaceView()->grabImage();
        s.at = s.window.surfaceView()->projectVertexToWidget(0, kDragged);
        const auto pick = s.window.surfaceView()->pickAt(s.at);
        return pick && pick->kind == Pick::Kind::Vertex && pick->id == kDragged;
    }

    // The drag tool's signals and the document's changes, watched from the press on.
    struct Watch {
        QSignalSpy finished;
        QSignalSpy changed;
        QSignalSpy status;
        explicit Watch(Setup& s)
            : finished(s.window.dragTool(), &app::DragTool::dragFinished),
              changed(s.doc, &document::Document::changed),
              status(s.window.dragTool(), &app::DragTool::statusMessage) {}
    };

    // Presses on the dragged vertex and moves 20 pixels up; true once the design follows.
    static bool pressAndMove(Setup& s, Watch& watch) {
        QTest::mousePress(s.gl, Qt::LeftButton, {}, s.at);
        QTest::mouseMove(s.gl, s.at + QPoint(0, -20));
        return watch.changed.wait(60000);
    }

private slots:
    void init() { QSettings().clear(); }

    void lengthsWhileDraggingIsChosenInTheMenuAndRemembered() {
        using Mode = app::SolveController::LengthsMode;
        const model::CompositeSurface annulus = model::makeExample("annulus").surfaces[0];
        const model::CompositeSurface fig8 = model::makeExample("fig8").surfaces[0];
        {
            app::MainWindow window;
            QAction* automatic = window.action(QStringLiteral("actionLengthsAutomatic"));
            QAction* keep = window.action(QStringLiteral("actionKeepLengths"));
            QAction* stretch = window.action(QStringLiteral("actionLetStretch"));
            QVERIFY(automatic && keep && stretch);
            QVERIFY(automatic->isChecked() && !keep->isChecked() && !stretch->isChecked());
            // Automatic: drags keep lengths and are replayed stretching where that fails.
            QVERIFY(app::SolveController::keepsLengths());
            QVERIFY(app::SolveController::stretchesWhereLengthsFail());
            keep->trigger();
            QVERIFY(keep->isChecked() && !automatic->isChecked());
            QCOMPARE(app::SolveController::lengthsSetting(), Mode::Keep);
            QVERIFY(app::SolveController::keepsLengths());
            QVERIFY(!app::SolveController::stretchesWhereLengthsFail());
            stretch->trigger();
            QVERIFY(!app::SolveController::keepsLengths());
            QVERIFY(!app::SolveController::stretchesWhereLengthsFail());
        }
        // A new window shows the choice made.
        app::MainWindow again;
        QVERIFY(again.action(QStringLiteral("actionLetStretch"))->isChecked());
        // The on/off choice of earlier versions is taken over while no new choice was made.
        QSettings().clear();
        QSettings().setValue(QStringLiteral("solver/keepLengths"), true);
        QCOMPARE(app::SolveController::lengthsSetting(), Mode::Keep);
        QSettings().setValue(QStringLiteral("solver/keepLengths"), false);
        QCOMPARE(app::SolveController::lengthsSetting(), Mode::Stretch);
    }

    void aPointOfTheSheetIsDraggedInTheDevelopmentView() {
        // Two-way editing: the flat `sheet` holding its sheet on its 300 × 300 mm rectangle,
        // its bottom corners pinned. With the Drag tool on, a press on vertex 5 in the
        // development view and a move drag its place in the sheet; the surface follows (one
        // undo step), stays on the square, and undo and redo give the states byte for byte.
        app::MainWindow window;
        QVERIFY(showSheetHeldOnItsSquare(window));
        document::Document* doc = window.workspace()->document();
        const model::Project project = doc->project();
        constexpr model::VertexId kVertex = 5; // (100, 100): inside the sheet
        views::DevelopmentView* view = window.developmentView();
        view->grabImage();
        const QPoint at = view->projectVertexToWidget(0, kVertex);
        const auto pick = view->pickAt(at);
        QVERIFY(pick && pick->kind == Pick::Kind::Vertex && pick->id == kVertex);
        window.action(QStringLiteral("actionDragTool"))->setChecked(true);
        const std::string atPress = bytesOf(window);
        const int stackAtPress = doc->undoStack()->count();
        const model::Vec3 start = doc->surface(0).position(kVertex);
        QSignalSpy finished(window.dragTool(), &app::DragTool::dragFinished);
        QWidget* gl = view->glWidget();
        QTest::mousePress(gl, Qt::LeftButton, {}, at);
        QVERIFY(window.dragTool()->isDragging());
        QVERIFY(window.dragTool()->draggingSheet());
        for (int i = 1; i <= 5; ++i) {
            QTest::mouseMove(gl, at + QPoint(4 * i, 0));
        }
        QTest::mouseRelease(gl, Qt::LeftButton, {}, at + QPoint(20, 0));
        QVERIFY(finished.wait(60000));
        QCOMPARE(finished.front().front().toBool(), true);
        QCOMPARE(doc->undoStack()->count(), stackAtPress + 1);
        QVERIFY(doc->undoStack()->undoText().contains(QStringLiteral("5")));
        const model::CompositeSurface& result = doc->surface(0);
        // 20 pixels along the sheet moved the vertex's place by several mm, and the vertex
        // itself (the surface follows its sheet).
        QVERIFY2(model::distance(result.position(kVertex), start) > 1.0,
                 qPrintable(QString::number(model::distance(result.position(kVertex), start))));
        QVERIFY(result.keepsDevelopment());
        QVERIFY(model::keptSheetStretch(result) < 1e-3);
        QVERIFY(model::largestDomainGap(result.sheetDomain(), model::sampleSurface(result, 2),
                                        result.development()) < 1e-6);
        QCOMPARE(result.position(0), project.surfaces.front().position(0)); // pinned
        const std::string after = bytesOf(window);
        doc->undoStack()->undo();
        QCOMPARE(bytesOf(window), atPress);
        doc->undoStack()->redo();
        QCOMPARE(bytesOf(window), after);
        window.action(QStringLiteral("actionDragTool"))->setChecked(false);
    }

    void selectedPointsOfTheSheetAreDraggedTogether() {
        // Vertices 5 and 6 of the flat `sheet` (on its rectangle, bottom corners pinned)
        // selected, a press on 5 in the development view and a move along the sheet: both
        // places in the sheet move, and the surface follows, in one undo step.
        app::MainWindow window;
        QVERIFY(showSheetHeldOnItsSquare(window));
        document::Document* doc = window.workspace()->document();
        views::DevelopmentView* view = window.developmentView();
        view->grabImage();
        const QPoint at = view->projectVertexToWidget(0, 5);
        window.workspace()->selection()->set(
            {Pick{Pick::Kind::Vertex, 0, 5}, Pick{Pick::Kind::Vertex, 0, 6}});
        window.action(QStringLiteral("actionDragTool"))->setChecked(true);
        const int stackAtPress = doc->undoStack()->count();
        const std::vector<model::Vec2> before = doc->surface(0).development();
        QSignalSpy finished(window.dragTool(), &app::DragTool::dragFinished);
        QWidget* gl = view->glWidget();
        QTest::mousePress(gl, Qt::LeftButton, {}, at);
        QVERIFY(window.dragTool()->draggingSheet());
        for (int i = 1; i <= 5; ++i) {
            QTest::mouseMove(gl, at + QPoint(4 * i, 0));
        }
        QTest::mouseRelease(gl, Qt::LeftButton, {}, at + QPoint(20, 0));
        QVERIFY(finished.wait(60000));
        QCOMPARE(finished.front().front().toBool(), true);
        QCOMPARE(doc->undoStack()->count(), stackAtPress + 1);
        QVERIFY2(doc->undoStack()->undoText().contains(QStringLiteral("2")),
                 qPrintable(doc->undoStack()->undoText()));
        const model::CompositeSurface& result = doc->surface(0);
        // The coarse vertices come first in the development, in id order: 5 and 6 at 5 and 6.
        const double moved5 = (result.development()[5] - before[5]).norm();
        const double moved6 = (result.development()[6] - before[6]).norm();
        QVERIFY2(moved5 > 1.0 && moved6 > 1.0,
                 qPrintable(QStringLiteral("%1 %2").arg(moved5).arg(moved6)));
        QVERIFY(model::keptSheetStretch(result) < 1e-3);
        window.action(QStringLiteral("actionDragTool"))->setChecked(false);
    }

    void aSheetThatIsNotHeldIsNotDraggedInTheDevelopmentView() {
        app::MainWindow window;
        QVERIFY(showActiveWithExample(window, QStringLiteral("sheet")));
        views::DevelopmentView* view = window.developmentView();
        view->grabImage();
        const QPoint at = view->projectVertexToWidget(0, 5);
        window.action(QStringLiteral("actionDragTool"))->setChecked(true);
        QSignalSpy status(window.dragTool(), &app::DragTool::statusMessage);
        QTest::mousePress(view->glWidget(), Qt::LeftButton, {}, at);
        QVERIFY(!window.dragTool()->isDragging());
        QVERIFY(!status.isEmpty());
        // It names the menu command that holds the sheet, in the language shown.
        const QString hold =
            window.action(QStringLiteral("actionHoldSheet"))->text().remove(QLatin1Char('&'));
        QVERIFY2(status.back().front().toString().contains(hold),
                 qPrintable(status.back().front().toString()));
        QTest::mouseRelease(view->glWidget(), Qt::LeftButton, {}, at);
        window.action(QStringLiteral("actionDragTool"))->setChecked(false);
    }

    void dragIsOneUndoStepAndUndoGivesTheStateAtPress() {
        Setup s;
        QVERIFY(prepare(s));
        const int stackAtPress = s.doc->undoStack()->count();
        const std::string atPress = bytesOf(s.window);
        const model::Vec3 pinnedAt = s.doc->surface(0).position(kPinned);
        const model::Vec3 start = s.doc->surface(0).position(kDragged);
        QSignalSpy finished(s.window.dragTool(), &app::DragTool::dragFinished);
        QSignalSpy changed(s.doc, &document::Document::changed);
        QTest::mousePress(s.gl, Qt::LeftButton, {}, s.at);
        QVERIFY(s.window.dragTool()->isDragging());
        QSignalSpy stackMoves(s.doc->undoStack(), &QUndoStack::indexChanged);
        const bool modifiedAtPress = s.doc->isModified();
        for (int i = 1; i <= 6; ++i) {
            QTest::mouseMove(s.gl, s.at + QPoint(0, -6 * i));
            if (i == 3) {
                QVERIFY(changed.wait(60000)); // the surface follows during the drag
            }
        }
        // The moves are shown outside the undo history; the release pushes one step.
        QCOMPARE(s.doc->undoStack()->count(), stackAtPress);
        QCOMPARE(stackMoves.count(), 0);
        QCOMPARE(s.doc->isModified(), modifiedAtPress);
        QTest::mouseRelease(s.gl, Qt::LeftButton, {}, s.at + QPoint(0, -36));
        QVERIFY(finished.wait(60000));
        QCOMPARE(finished.front().front().toBool(), true);
        QCOMPARE(s.doc->undoStack()->count(), stackAtPress + 1);
        QVERIFY(test::undoCommand<document::ApplySurfaceCommand>(*s.doc) != nullptr);
        QVERIFY(s.doc->undoStack()->undoText().contains(QStringLiteral("2"))); // vertices
        const model::Vec3 end = s.doc->surface(0).position(kDragged);
        QVERIFY2((end - start).norm() > 1.0, qPrintable(QString::number((end - start).norm())));
        const model::Vec3 pinnedNow = s.doc->surface(0).position(kPinned);
        QVERIFY(pinnedNow.x == pinnedAt.x && pinnedNow.y == pinnedAt.y &&
                pinnedNow.z == pinnedAt.z);
        const app::SolveReport& shown = window(s)->solverPanel()->report();
        QCOMPARE(shown.outcome.kind, solver::JobKind::VertexDrag);
        QVERIFY(shown.outcome.settled);
        const QString report = window(s)->solverPanel()->statusText();
        // The report is the one of the iterations after the release: 20, since a vertex drag
        // keeps lengths by default (Tools ▸ Lengths While Dragging ▸ Automatic).
        const QAction* automatic =
            s.window.findChild<QAction*>(QStringLiteral("actionLengthsAutomatic"));
        QVERIFY(automatic && automatic->isChecked());
        QVERIFY(app::SolveController::keepsLengths());
        QVERIFY2(window(s)->solverPanel()->iterationRows() ==
                         solver::kIterationsAfterDragKeepingLengths ||
                     shown.outcome.assessments.front().summary.status == solver::Status::Converged,
                 qPrintable(report));
        const solver::QualityMeasures quality = solver::measureQuality(s.doc->surface(0));
        qInfo("after the drag: developability max %.3g, mean %.3g", quality.developabilityMax,
              quality.developabilityMean);
        QVERIFY(std::isfinite(quality.developabilityMax));

        const std::string after = bytesOf(s.window);
        const int rows = window(s)->solverPanel()->iterationRows();
        s.doc->undoStack()->undo();
        QCOMPARE(bytesOf(s.window), atPress);
        // The Solver panel shows the design on screen: the undone drag's report goes, and
        // comes back with the redo.
        QVERIFY(!window(s)->solverPanel()->hasReport());
        QCOMPARE(window(s)->solverPanel()->iterationRows(), 0);
        s.doc->undoStack()->redo();
        QCOMPARE(bytesOf(s.window), after);
        QVERIFY(window(s)->solverPanel()->hasReport());
        QCOMPARE(window(s)->solverPanel()->report().outcome.kind, solver::JobKind::VertexDrag);
        QCOMPARE(window(s)->solverPanel()->iterationRows(), rows);
    }

    void anUndoDuringADragEndsItWithoutAStep() {
        // The moves are shown outside the history; an undo meanwhile (here of the pin made
        // before the press) wins: the drag ends, adds no step, and the design is the undo's.
        Setup s;
        QVERIFY(prepare(s));
        const int stackAtPress = s.doc->undoStack()->count();
        QSignalSpy finished(s.window.dragTool(), &app::DragTool::dragFinished);
        QSignalSpy changed(s.doc, &document::Document::changed);
        QTest::mousePress(s.gl, Qt::LeftButton, {}, s.at);
        QTest::mouseMove(s.gl, s.at + QPoint(0, -20));
        QVERIFY(changed.wait(60000));
        s.doc->undoStack()->undo();
        const std::string undone = bytesOf(s.window);
        QVERIFY(!s.doc->surface(0).isPinned(kPinned));
        QTest::mouseMove(s.gl, s.at + QPoint(0, -30));
        QVERIFY(finished.wait(60000));
        QCOMPARE(finished.front().front().toBool(), false);
        QTest::mouseRelease(s.gl, Qt::LeftButton, {}, s.at + QPoint(0, -30));
        QVERIFY(waitForWorkerIdle(s.window, 60000));
        QCOMPARE(s.doc->undoStack()->count(), stackAtPress);
        QCOMPARE(s.doc->undoStack()->index(), stackAtPress - 1);
        QCOMPARE(bytesOf(s.window), undone);
    }

    void escapeRestoresTheStateAtPress_data() {
        QTest::addColumn<bool>("released");
        QTest::newRow("during the drag") << false;
        // The iterations after the release run seconds on a large model: Esc cancels them too.
        QTest::newRow("while the release settles") << true;
    }

    void escapeRestoresTheStateAtPress() {
        QFETCH(bool, released);
        Setup s;
        QVERIFY(prepare(s));
        const int stackAtPress = s.doc->undoStack()->count();
        const std::string atPress = bytesOf(s.window);
        Watch watch(s);
        QSignalSpy& finished = watch.finished;
        QVERIFY(pressAndMove(s, watch));
        QVERIFY(bytesOf(s.window) != atPress);
        QSignalSpy stackMoves(s.doc->undoStack(), &QUndoStack::indexChanged);
        if (released) {
            QTest::mouseRelease(s.gl, Qt::LeftButton, {}, s.at + QPoint(0, -20));
            // No event processed in between: the release's result cannot have arrived yet.
            QVERIFY(finished.isEmpty());
        }
        QTest::keyClick(s.gl, Qt::Key_Escape);
        QCOMPARE(finished.size(), 1);
        QCOMPARE(finished.front().front().toBool(), false);
        QVERIFY(!s.window.dragTool()->isDragging());
        QCOMPARE(watch.status.back().front().toString(),
                 QCoreApplication::translate("devsurf::app::DragTool",
                                             "Drag cancelled; the design is as it was."));
        QCOMPARE(bytesOf(s.window), atPress);
        // Esc restored the press without touching the history (no undo, no obsolete step).
        QCOMPARE(s.doc->undoStack()->count(), stackAtPress);
        QCOMPARE(stackMoves.count(), 0);
        QVERIFY(!s.window.workspace()->selection()->isEmpty()); // Esc did not select nothing
        if (!released) {
            // The release after Esc is an ordinary release; nothing of the drag comes back.
            QTest::mouseRelease(s.gl, Qt::LeftButton, {}, s.at + QPoint(0, -20));
        }
        QVERIFY(waitForWorkerIdle(s.window, 60000));
        QCOMPARE(bytesOf(s.window), atPress);
    }

    void theReleaseCountsItsIterationsInTheStatusBar() {
        // The iterations after the release run seconds on a large model: the status bar counts
        // them ("Drag 2 vertices: settling, iteration 3 of 20 (Esc cancels).").
        Setup s;
        QVERIFY(prepare(s));
        Watch watch(s);
        QSignalSpy& finished = watch.finished;
        QVERIFY(pressAndMove(s, watch));
        const QString undo = s.doc->undoStack()->undoText();
        QTest::mouseRelease(s.gl, Qt::LeftButton, {}, s.at + QPoint(0, -20));
        QVERIFY(finished.wait(60000));
        QCOMPARE(finished.front().front().toBool(), true);
        const QString step = s.doc->undoStack()->undoText();
        QVERIFY(step != undo);
        const QString first = QCoreApplication::translate("devsurf::app::DragTool",
                                                          "%1: settling, iteration %2 of %3 "
                                                          "(Esc cancels).")
                                  .arg(step)
                                  .arg(1)
                                  .arg(solver::kIterationsAfterDragKeepingLengths);
        QStringList shown;
        for (const QList<QVariant>& message : watch.status) {
            shown << message.front().toString();
        }
        QVERIFY2(shown.contains(first), qPrintable(shown.join(QLatin1Char('\n'))));
    }

    void qualityColoursFollowTheDrag() {
        Setup s;
        QVERIFY(prepare(s));
        app::MainWindow& w = s.window;
        QAction* developability = w.action(QStringLiteral("actionColourDevelopability"));
        QVERIFY(developability != nullptr);
        developability->trigger();
        QCOMPARE(w.surfaceView()->colourBy(), views::ColourBy::Developability);
        const QString developabilityTitle = w.surfaceView()->legendTitle();
        QVERIFY(!developabilityTitle.isEmpty());
        // The largest value the colouring gives a patch.
        auto worstPatch = [&w, &s] {
            double worst = 0.0;
            for (const auto& [face, loop] : s.doc->surface(0).faces()) {
                (void)loop;
                worst = std::max(worst, w.surfaceView()->legendValue({Pick::Kind::Face, 0, face}));
            }
            return worst;
        };
        const double flatWorst = worstPatch();
        const std::pair<double, double> scale = w.surfaceView()->legendRange();
        QSignalSpy finished(w.dragTool(), &app::DragTool::dragFinished);
        QSignalSpy changed(s.doc, &document::Document::changed);
        QTest::keyPress(s.gl, Qt::Key_Z); // lift along z
        QTest::mousePress(s.gl, Qt::LeftButton, {}, s.at);
        for (int i = 1; i <= 15; ++i) {
            QTest::mouseMove(s.gl, s.at + QPoint(0, -2 * i));
            if (i == 8) {
                QVERIFY(changed.wait(60000));
            }
        }
        QCOMPARE(w.dragTool()->axis(), app::DragTool::Axis::Z);
        QVERIFY(changed.wait(60000));
        // The colours follow the surface being dragged, on the same fixed scale.
        QVERIFY(worstPatch() > flatWorst);
        QCOMPARE(w.surfaceView()->legendRange(), scale);
        QTest::mouseRelease(s.gl, Qt::LeftButton, {}, s.at + QPoint(0, -30));
        QTest::keyRelease(s.gl, Qt::Key_Z);
        QVERIFY(finished.wait(60000));
        QCOMPARE(w.dragTool()->axis(), app::DragTool::Axis::Free);
        // A picture of the result for the documentation, on request.
        const QString shot = qEnvironmentVariable("DEVSURF_DRAG_SCREENSHOT");
        if (!shot.isEmpty()) {
            QVERIFY(w.grab().save(shot));
        }
        const model::Vec3 moved = s.doc->surface(0).position(kDragged);
        QVERIFY(moved.z > 1.0);
        w.action(QStringLiteral("actionColourAngleDefect"))->trigger();
        QCOMPARE(w.surfaceView()->colourBy(), views::ColourBy::AngleDefect);
        QVERIFY(!w.surfaceView()->legendTitle().isEmpty());
        QVERIFY(w.surfaceView()->legendTitle() != developabilityTitle);
        w.action(QStringLiteral("actionColourPatch"))->trigger();
        QVERIFY(w.surfaceView()->legendTitle().isEmpty());
    }

    void pressingAwayFromVerticesStillTurnsTheCamera() {
        Setup s;
        QVERIFY(prepare(s));
        QTest::mousePress(s.gl, Qt::LeftButton, {}, QPoint(5, 5));
        QVERIFY(!s.window.dragTool()->isDragging());
        QTest::mouseRelease(s.gl, Qt::LeftButton, {}, QPoint(5, 5));
    }

    // fig8 with all four corners pinned: they hold the whole flat square, so a vertex drag that
    // keeps lengths must stretch it. The status bar says so while the mouse moves, the Solver
    // panel after the release.
    void aDragOfAVertexThePinsHoldSaysSo() {
        app::MainWindow w;
        QVERIFY(showActiveWithExample(w, QStringLiteral("fig8")));
        document::Document* doc = w.workspace()->document();
        doc->undoStack()->push(
            document::PinVerticesCommand::create(*doc, 0, {12, 15}, true).takeCommand().release());
        w.action(QStringLiteral("actionDragTool"))->setChecked(true);
        QWidget* gl = w.surfaceView()->glWidget();
        w.surfaceView()->grabImage();
        const QPoint at = w.surfaceView()->projectVertexToWidget(0, 5);
        const auto pick = w.surfaceView()->pickAt(at);
        QVERIFY(pick && pick->kind == Pick::Kind::Vertex && pick->id == 5);
        QSignalSpy status(w.dragTool(), &app::DragTool::statusMessage);
        QSignalSpy finished(w.dragTool(), &app::DragTool::dragFinished);
        QTest::mousePress(gl, Qt::LeftButton, {}, at);
        QTest::mouseMove(gl, at + QPoint(0, -10));
        QVERIFY(!status.isEmpty());
        QVERIFY(w.dragTool()->isDragging());
        const auto& atPress = w.dragTool()->heldAtPress();
        QVERIFY(atPress.has_value());
        QCOMPARE(atPress->vertex, model::VertexId{5});
        QCOMPARE(atPress->pins, (std::vector<model::VertexId>{0, 3, 12}));
        QTest::mouseRelease(gl, Qt::LeftButton, {}, at + QPoint(0, -10));
        QVERIFY(finished.wait(60000));
        const auto& held = w.solverPanel()->report().outcome.assessments.front().held;
        QVERIFY(held.has_value());
        QCOMPARE(held->vertex, model::VertexId{5});
        QCOMPARE(held->pins, (std::vector<model::VertexId>{0, 3, 12}));

        // The example's two bottom corners hold only the bottom edge: nothing said.
        doc->undoStack()->undo(); // the drag
        doc->undoStack()->undo(); // the two pins
        QVERIFY(!doc->surface(0).isPinned(12));
        status.clear();
        QTest::mousePress(gl, Qt::LeftButton, {}, at);
        QTest::mouseMove(gl, at + QPoint(0, -10));
        QVERIFY(!status.isEmpty());
        QVERIFY(w.dragTool()->isDragging());
        QVERIFY(!w.dragTool()->heldAtPress());
        QTest::mouseRelease(gl, Qt::LeftButton, {}, at + QPoint(0, -10));
        QVERIFY(finished.wait(60000));
        QVERIFY(w.solverPanel()->report().outcome.settled);
        QVERIFY(!w.solverPanel()->report().outcome.assessments.front().held);
    }

    void aDragThatWouldEndBrokenIsTakenBack() {
        // The torus, nothing pinned: a vertex dragged far cannot end developable (its cone
        // bands do not bend that way). The release is taken back: no undo step, the design as
        // at the press byte for byte, and the status and the Solver panel say why.
        app::MainWindow w;
        QVERIFY(showActiveWithExample(w, QStringLiteral("torus")));
        document::Document* doc = w.workspace()->document();
        w.action(QStringLiteral("actionDragTool"))->setChecked(true);
        QWidget* gl = w.surfaceView()->glWidget();
        w.surfaceView()->grabImage();
        constexpr model::VertexId kVertex = 0;
        const QPoint at = w.surfaceView()->projectVertexToWidget(0, kVertex);
        const auto pick = w.surfaceView()->pickAt(at);
        QVERIFY(pick && pick->kind == Pick::Kind::Vertex && pick->id == kVertex);
        const int stackAtPress = doc->undoStack()->count();
        const std::string atPress = bytesOf(w);
        QSignalSpy status(w.dragTool(), &app::DragTool::statusMessage);
        QSignalSpy finished(w.dragTool(), &app::DragTool::dragFinished);
        QSignalSpy changed(doc, &document::Document::changed);
        QTest::mousePress(gl, Qt::LeftButton, {}, at);
        for (int i = 1; i <= 8; ++i) {
            QTest::mouseMove(gl, at + QPoint(0, -15 * i));
            if (i == 2) {
                QVERIFY(changed.wait(60000)); // the moves are shown while dragging
            }
        }
        QTest::mouseRelease(gl, Qt::LeftButton, {}, at + QPoint(0, -120));
        QVERIFY(finished.wait(60000));
        QCOMPARE(finished.back().front().toBool(), false);
        QCOMPARE(doc->undoStack()->count(), stackAtPress);
        QCOMPARE(bytesOf(w), atPress);
        const app::SolveReport& shown = w.solverPanel()->report();
        QVERIFY(shown.outcome.settled);
        const solver::SurfaceAssessment& a = shown.outcome.assessments.front();
        QVERIFY(a.takenBack);
        QVERIFY(solver::broken(*a.takenBack));
        QVERIFY(!solver::broken(a));
        // Both say what the drag would have broken (in the language of the run).
        const QString why = app::SolveController::takenBackText(*a.takenBack);
        QVERIFY(!why.isEmpty());
        const QString text = w.solverPanel()->statusText();
        QVERIFY2(text.contains(why), qPrintable(text));
        QVERIFY(!status.isEmpty());
        QVERIFY2(status.back().front().toString().contains(why),
                 qPrintable(status.back().front().toString()));
    }

private:
    static app::MainWindow* window(Setup& s) { return &s.window; }
};

DEVSURF_REGISTER_TEST(TstDrag);

#include "tst_drag.moc"
