#include "drag_tool.h"
#include "io/project_file.h"
#include "main_window.h"
#include "model/document/commands/apply_surface_command.h"
#include "model/document/commands/move_vertices_command.h"
#include "model/document/commands/pin_vertices_command.h"
#include "model/document/document.h"
#include "model/document/selection.h"
#include "model/examples.h"
#include "panels/solver_panel.h"
#include "solve_controller.h"
#include "solver/quality/crease_quality.h"
#include "solver/quality/quality_measures.h"
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
using test::waitForSolve;
using test::waitForWorkerIdle;

namespace {

// Every coarse vertex and S-edge control point of every surface, in a fixed order.
std::vector<model::Vec3> allPoints(const document::Document& doc) {
    std::vector<model::Vec3> points;
    for (const auto& surface : doc.project().surfaces) {
        for (const auto& [id, p] : surface.vertices()) {
            points.push_back(p);
        }
        for (const auto& [id, edge] : surface.edges()) {
            points.insert(points.end(), edge.controlPoints.begin(), edge.controlPoints.end());
        }
    }
    return points;
}

double diameter(const std::vector<model::Vec3>& points) {
    model::Vec3 lo(1e300, 1e300, 1e300);
    model::Vec3 hi(-1e300, -1e300, -1e300);
    for (const model::Vec3& p : points) {
        for (int k = 0; k < 3; ++k) {
            lo[k] = std::min(lo[k], p[k]);
            hi[k] = std::max(hi[k], p[k]);
        }
    }
    return (hi - lo).norm();
}

} // namespace

// Pins in the desktop application.
class TstPins : public QObject {
    Q_OBJECT

private slots:
    void init() { QSettings().clear(); }

    void pinActionsExplainWhyTheyAreDisabled() {
        app::MainWindow window;
        window.workspace()->newFromExample(QStringLiteral("annulus"), 0);
        QAction* pin = window.action(QStringLiteral("actionPinVertices"));
        QAction* unpin = window.action(QStringLiteral("actionUnpinVertices"));
        QVERIFY(pin != nullptr && unpin != nullptr);
        QVERIFY(!pin->isEnabled());
        QVERIFY(!unpin->isEnabled());
        // Disabled, each says what to select; enabled or refused, each says something else.
        const QString selectToPin = pin->toolTip();
        const QString selectToUnpin = unpin->toolTip();
        QVERIFY(!selectToPin.isEmpty() && !selectToUnpin.isEmpty());
        window.workspace()->selection()->set({{Pick::Kind::Vertex, 0, 1}});
        QVERIFY(pin->isEnabled());
        QVERIFY(pin->toolTip() != selectToPin);
        QVERIFY(!unpin->isEnabled()); // nothing selected is pinned
        QVERIFY(!unpin->toolTip().isEmpty());
        QVERIFY2(unpin->toolTip() != selectToUnpin, qPrintable(unpin->toolTip()));
        QCOMPARE(pin->shortcut(), QKeySequence(QStringLiteral("Ctrl+K")));
    }

    void theViewsContextMenuOffersPins() {
        app::MainWindow window;
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        window.workspace()->newFromExample(QStringLiteral("annulus"), 0);
        window.surfaceView()->grabImage();
        QStringList offered;
        // The menu runs its own event loop: a timer looks for it there and closes it.
        QTimer poll;
        connect(&poll, &QTimer::timeout, &poll, [&] {
            if (auto* menu = qobject_cast<QMenu*>(QApplication::activePopupWidget())) {
                for (QAction* a : menu->actions()) {
                    if (a->isEnabled()) {
                        offered << a->objectName();
                    }
                }
                menu->close();
            }
        });
        poll.start(10);
        const QPoint at = window.surfaceView()->projectVertexToWidget(0, 3);
        QTest::mouseClick(window.surfaceView()->glWidget(), Qt::RightButton, {}, at);
        poll.stop();
        QVERIFY(window.workspace()->selection()->contains({Pick::Kind::Vertex, 0, 3}));
        QVERIFY2(offered.contains(QStringLiteral("actionPinVertices")),
                 qPrintable(offered.join(',')));
        QVERIFY(!offered.contains(QStringLiteral("actionUnpinVertices")));
    }

    void pinningIsUndoableAndDrawnInBothViews() {
        app::MainWindow window;
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        window.workspace()->newFromExample(QStringLiteral("annulus"), 0);
        document::Document* doc = window.workspace()->document();
        const std::string before = bytesOf(window);
        const std::set<Pick> picks{{Pick::Kind::Vertex, 0, 0}, {Pick::Kind::Vertex, 0, 2}};
        window.workspace()->selection()->set(picks);
        window.action(QStringLiteral("actionPinVertices"))->trigger();
        QVERIFY(doc->surface(0).isPinned(0));
        QVERIFY(doc->surface(0).isPinned(2));
        QCOMPARE(doc->undoStack()->count(), 1);
        QVERIFY(test::undoCommand<document::PinVerticesCommand>(*doc) != nullptr);
        QVERIFY(doc->undoStack()->undoText().contains(QStringLiteral("2"))); // vertices
        QCOMPARE(window.surfaceView()->pinnedPicks(), picks);
        QCOMPARE(window.developmentView()->pinnedPicks(), picks);
        const std::string after = bytesOf(window);
        QVERIFY(after != before);

        // Drawn red where the vertex is (the selection, orange, is cleared first).
        window.workspace()->selection()->clear();
        const QImage image = window.surfaceView()->grabImage();
        const qreal dpr = image.devicePixelRatio();
        const QPoint at = window.surfaceView()->projectVertexToWidget(0, 0);
        const QColor colour = image.pixelColor(at * dpr);
        QVERIFY2(colour.red() > 150 && colour.green() < 90 && colour.blue() < 90,
                 qPrintable(colour.name()));

        doc->undoStack()->undo();
        QCOMPARE(bytesOf(window), before);
        QVERIFY(window.surfaceView()->pinnedPicks().empty());
        QVERIFY(window.developmentView()->pinnedPicks().empty());
        doc->undoStack()->redo();
        QCOMPARE(bytesOf(window), after);

        window.workspace()->selection()->set({{Pick::Kind::Vertex, 0, 2}});
        QAction* unpin = window.action(QStringLiteral("actionUnpinVertices"));
        QVERIFY(unpin->isEnabled());
        unpin->trigger();
        QVERIFY(!doc->surface(0).isPinned(2));
        QCOMPARE(window.surfaceView()->pinnedPicks(), (std::set<Pick>{{Pick::Kind::Vertex, 0, 0}}));
        doc->undoStack()->undo();
        QCOMPARE(bytesOf(window), after);
    }
};

DEVSURF_REGISTER_TEST(TstPins);

// Tools ▸ Solve.
class TstSolve : public QObject {
    Q_OBJECT

private slots:
    void init() { QSettings().clear(); }

    void solveOnAnUnchangedExampleChangesNothingAndIsOneUndoStep() {
        app::MainWindow window;
        window.workspace()->newFromExample(QStringLiteral("annulus"), 0);
        document::Document* doc = window.workspace()->document();
        const std::string before = bytesOf(window);
        const std::vector<model::Vec3> start = allPoints(*doc);
        QAction* solve = window.action(QStringLiteral("actionSolve"));
        QVERIFY(solve != nullptr);
        QCOMPARE(solve->shortcut(), QKeySequence(QStringLiteral("Ctrl+Return")));
        solve->trigger();
        QVERIFY(window.solveController()->isSolving());
        const QString sentence = waitForSolve(window);
        QVERIFY2(window.solveController()->lastEnding() == app::SolveController::Ending::Solved,
                 qPrintable(sentence));
        QCOMPARE(doc->undoStack()->count(), 1);
        QVERIFY(test::undoCommand<document::ApplySurfaceCommand>(*doc) != nullptr);
        const std::vector<model::Vec3> end = allPoints(*doc);
        QCOMPARE(end.size(), start.size());
        const double size = diameter(start);
        double moved = 0.0;
        for (std::size_t i = 0; i < end.size(); ++i) {
            moved = std::max(moved, (end[i] - start[i]).norm());
        }
        QVERIFY2(moved <= 1e-6 * size, qPrintable(QString::number(moved / size)));
        QVERIFY(window.solverPanel()->iterationRows() > 0);
        QCOMPARE(window.solveController()->lastEnding(), app::SolveController::Ending::Solved);
        QCOMPARE(window.solverPanel()->report().outcome.kind, solver::JobKind::Solve);
        // No crease of the annulus has a condition: no crease residual is reported.
        QCOMPARE(window.solverPanel()->report().creaseResidual, -1.0);

        const std::string after = bytesOf(window);
        doc->undoStack()->undo();
        QCOMPARE(bytesOf(window), before);
        doc->undoStack()->redo();
        QCOMPARE(bytesOf(window), after);
    }

    void aSolveThatChangesNothingAddsNoUndoStep() {
        // mixed is developable as built: its Solve moves nothing, so it leaves no undo step
        // and the document stays unmodified.
        app::MainWindow window;
        window.workspace()->newFromExample(QStringLiteral("mixed"), 0);
        document::Document* doc = window.workspace()->document();
        const std::string before = bytesOf(window);
        const int steps = doc->undoStack()->count();
        QVERIFY(!window.isWindowModified());
        window.action(QStringLiteral("actionSolve"))->trigger();
        const QString sentence = waitForSolve(window);
        QVERIFY2(window.solveController()->lastEnding() == app::SolveController::Ending::Solved,
                 qPrintable(sentence));
        QCOMPARE(doc->undoStack()->count(), steps);
        QVERIFY(doc->undoStack()->isClean());
        QVERIFY(!window.isWindowModified());
        QCOMPARE(bytesOf(window), before);
    }

    void solveReportsTheCreaseResidualSampledAlongTheCreases() {
        // fig8 lifted by hand: Solve folds it; the panel gives the crease conditions' residual
        // sampled along the creases, which the solver's residual does not bound.
        app::MainWindow window;
        window.workspace()->newFromExample(QStringLiteral("fig8"), 0);
        document::Document* doc = window.workspace()->document();
        doc->undoStack()->push(document::MoveVerticesCommand::createTranslation(
                                   *doc, 0, {5, 6, 9, 10}, model::Vec3(0.0, 0.0, 10.0))
                                   .takeCommand()
                                   .release());
        window.action(QStringLiteral("actionSolve"))->trigger();
        const QString sentence = waitForSolve(window);
        QVERIFY2(window.solveController()->lastEnding() == app::SolveController::Ending::Solved,
                 qPrintable(sentence));
        const solver::CreaseQuality quality = solver::measureCreaseQuality(doc->surface(0));
        QVERIFY(quality.creases > 0);
        QCOMPARE(window.solverPanel()->report().creaseResidual, quality.residualMax);
    }

    void solveMakesALiftedDesignDevelopableAndKeepsPinsBitForBit() {
        app::MainWindow window;
        window.workspace()->newFromExample(QStringLiteral("annulus"), 0);
        document::Document* doc = window.workspace()->document();
        doc->undoStack()->push(
            document::PinVerticesCommand::create(*doc, 0, {0, 20}, true).takeCommand().release());
        doc->undoStack()->push(document::MoveVerticesCommand::createTranslation(
                                   *doc, 0, {21}, model::Vec3(0.0, 0.0, 5.0))
                                   .takeCommand()
                                   .release());
        const double before = solver::measureQuality(doc->surface(0)).developabilityMax;
        const model::Vec3 pinned0 = doc->surface(0).position(0);
        const model::Vec3 pinned20 = doc->surface(0).position(20);
        window.action(QStringLiteral("actionSolve"))->trigger();
        const QString sentence = waitForSolve(window);
        QVERIFY2(window.solveController()->lastEnding() == app::SolveController::Ending::Solved,
                 qPrintable(sentence));
        const double after = solver::measureQuality(doc->surface(0)).developabilityMax;
        qInfo("developability max before %.3g, after the solve %.3g", before, after);
        QVERIFY(after < before);
        const model::Vec3 now0 = doc->surface(0).position(0);
        const model::Vec3 now20 = doc->surface(0).position(20);
        QVERIFY(now0.x == pinned0.x && now0.y == pinned0.y && now0.z == pinned0.z);
        QVERIFY(now20.x == pinned20.x && now20.y == pinned20.y && now20.z == pinned20.z);
        QCOMPARE(doc->undoStack()->count(), 3);
    }

    void theIterationsComeFromTheSetting() {
        // The tooltip names the setting's number of iterations.
        QSettings().setValue(QStringLiteral("solver/iterations"), 7);
        const QString sevenTip = app::MainWindow().action(QStringLiteral("actionSolve"))->toolTip();
        QSettings().setValue(QStringLiteral("solver/iterations"), 3);
        app::MainWindow window;
        window.workspace()->newFromExample(QStringLiteral("sheet"), 0);
        const QString threeTip = window.action(QStringLiteral("actionSolve"))->toolTip();
        QVERIFY(threeTip.contains(QStringLiteral("3")));
        QCOMPARE(QString(threeTip).replace(QStringLiteral("3"), QStringLiteral("7")), sevenTip);
        window.action(QStringLiteral("actionSolve"))->trigger();
        const QString sentence = waitForSolve(window);
        QVERIFY2(window.solveController()->lastEnding() == app::SolveController::Ending::Solved,
                 qPrintable(sentence));
        QVERIFY(window.solverPanel()->iterationRows() >= 1);
        QVERIFY(window.solverPanel()->iterationRows() <= 3);
    }

    void cancelledSolveChangesNothing() {
        app::MainWindow window;
        window.workspace()->newFromExample(QStringLiteral("annulus"), 0);
        document::Document* doc = window.workspace()->document();
        const std::string before = bytesOf(window);
        QAction* cancel = window.action(QStringLiteral("actionCancelSolve"));
        QVERIFY(!cancel->isEnabled());
        QSignalSpy finished(window.solveController(), &app::SolveController::finished);
        window.action(QStringLiteral("actionSolve"))->trigger();
        QVERIFY(cancel->isEnabled());
        QVERIFY(!window.action(QStringLiteral("actionSelectNone"))->isEnabled());
        cancel->trigger();
        QCOMPARE(finished.size(), 1);
        QCOMPARE(window.solveController()->lastEnding(), app::SolveController::Ending::Cancelled);
        QVERIFY(!window.solveController()->isSolving());
        QVERIFY(window.action(QStringLiteral("actionSelectNone"))->isEnabled());
        // Whatever the worker still reports for the cancelled request is never applied.
        QVERIFY(waitForWorkerIdle(window, 120000));
        QCOMPARE(doc->undoStack()->count(), 0);
        QCOMPARE(bytesOf(window), before);
    }

    void escapeCancelsTheSolve() {
        app::MainWindow window;
        QVERIFY(showActiveWithExample(window, QStringLiteral("annulus")));
        const std::string before = bytesOf(window);
        QSignalSpy finished(window.solveController(), &app::SolveController::finished);
        QTest::keyClick(&window, Qt::Key_Return, Qt::ControlModifier);
        QVERIFY(window.solveController()->isSolving());
        QTest::keyClick(&window, Qt::Key_Escape);
        QCOMPARE(finished.size(), 1);
        QCOMPARE(window.solveController()->lastEnding(), app::SolveController::Ending::Cancelled);
        QCOMPARE(bytesOf(window), before);
    }

    void anEditWhileSolvingCancelsTheSolve() {
        app::MainWindow window;
        window.workspace()->newFromExample(QStringLiteral("annulus"), 0);
        document::Document* doc = window.workspace()->document();
        QSignalSpy finished(window.solveController(), &app::SolveController::finished);
        window.action(QStringLiteral("actionSolve"))->trigger();
        doc->undoStack()->push(
            document::PinVerticesCommand::create(*doc, 0, {1}, true).takeCommand().release());
        QCOMPARE(finished.size(), 1);
        QCOMPARE(window.solveController()->lastEnding(),
                 app::SolveController::Ending::CancelledByChange);
        const std::string pinned = bytesOf(window);
        QVERIFY(waitForWorkerIdle(window, 120000));
        QCOMPARE(doc->undoStack()->count(), 1);
        QCOMPARE(bytesOf(window), pinned);
    }
};

DEVSURF_REGISTER_TEST(TstSolve);
// The Drag tool, driven by synthesized mouse events in the 3D view.
#include "tst_live_solving.moc"
