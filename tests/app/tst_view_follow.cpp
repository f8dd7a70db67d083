// The views follow the shape: View ▸ Fit after a drag that left the view shows every vertex
// whole, pinned corners included; the docks keep their width whatever a panel says; a long
// status message is elided before the permanent counters.
#include "drag_tool.h"
#include "eliding_status_bar.h"
#include "main_window.h"
#include "model/document/commands/pin_vertices_command.h"
#include "model/document/document.h"
#include "model/document/selection.h"
#include "panels/solver_panel.h"
#include "solve_controller.h"
#include "test_registry.h"
#include "views/development_view.h"
#include "views/scene_cache.h"
#include "views/surface_view.h"
#include "views/vtk_opengl_widget.h"
#include "window_test_support.h"
#include "workspace.h"

#include <QAction>
#include <QDockWidget>
#include <QLabel>
#include <QSettings>
#include <QSignalSpy>
#include <QStatusBar>
#include <QTest>
#include <QUndoStack>

#include <set>

using namespace devsurf;
using document::Pick;

namespace {

// Half the size of the largest marker drawn at a vertex (a pin, 13 px), and a pixel to spare.
constexpr int kMarker = 7;

// The vertices of surface 0 a view draws outside its widget shrunk by kMarker.
QStringList cutOff(views::SceneView* view, const model::CompositeSurface& surface) {
    const QRect inside = view->glWidget()->rect().adjusted(kMarker, kMarker, -kMarker, -kMarker);
    QStringList outside;
    for (const auto& [id, position] : surface.vertices()) {
        (void)position;
        const QPoint at = view->projectVertexToWidget(0, id);
        if (!inside.contains(at)) {
            outside << QStringLiteral("%1%2 at %3,%4")
                           .arg(id)
                           .arg(surface.isPinned(id) ? QStringLiteral(" (pinned)") : QString())
                           .arg(at.x())
                           .arg(at.y());
        }
    }
    return outside;
}

} // namespace

class TstViewFollow : public QObject {
    Q_OBJECT

private slots:
    void init() { QSettings().clear(); }

    void fitAfterADragOutOfTheViewShowsEveryVertexWhole_data() {
        QTest::addColumn<QString>("example");
        QTest::addColumn<int>("dragged");
        QTest::addColumn<QList<int>>("pinned");
        // fig6 (its bottom corners pinned) pulled up out of the view by its top left corner,
        // keeping lengths (the default): it ends developable. (The annulus pinned at two
        // vertices, fig8, or fig6 by its other top corner, pulled that far, fold over, and
        // such a drag is taken back.)
        QTest::newRow("fig6") << "fig6" << 4 << QList<int>{0, 1};
    }

    void fitAfterADragOutOfTheViewShowsEveryVertexWhole() {
        QFETCH(QString, example);
        QFETCH(int, dragged);
        QFETCH(QList<int>, pinned);
        app::MainWindow window;
        QVERIFY(test::showActiveWithExample(window, example));
        document::Document* doc = window.workspace()->document();
        const auto kDragged = static_cast<model::VertexId>(dragged);
        const std::set<model::VertexId> pins(pinned.begin(), pinned.end());
        auto pin = document::PinVerticesCommand::create(*doc, 0, pins, true);
        if (!pin.isRefused()) { // fig8 comes with its pins
            doc->undoStack()->push(pin.takeCommand().release());
        }
        QCOMPARE(doc->surface(0).pinnedVertices(), pins);
        window.workspace()->selection()->set({{Pick::Kind::Vertex, 0, kDragged}});
        window.action(QStringLiteral("actionDragTool"))->setChecked(true);
        views::SurfaceView* surfaceView = window.surfaceView();
        surfaceView->grabImage();
        QVERIFY2(cutOff(surfaceView, doc->surface(0)).isEmpty(),
                 qPrintable(cutOff(surfaceView, doc->surface(0)).join(QStringLiteral("; "))));
        QWidget* gl = surfaceView->glWidget();
        const QPoint at = surfaceView->projectVertexToWidget(0, kDragged);
        QVERIFY(surfaceView->pickAt(at) && surfaceView->pickAt(at)->kind == Pick::Kind::Vertex);

        // A real drag with the mouse, out of the top of the view.
        QSignalSpy finished(window.dragTool(), &app::DragTool::dragFinished);
        QSignalSpy changed(doc, &document::Document::changed);
        QTest::mousePress(gl, Qt::LeftButton, {}, at);
        const QPoint end(at.x(), -gl->height() / 2);
        for (int i = 1; i <= 10; ++i) {
            // Each move shown before the next: the same ten steps in every run (moves that
            // came faster than the solver were coalesced, and a drag of two big steps could
            // fold over and be taken back).
            changed.clear();
            QTest::mouseMove(gl, at + (end - at) * i / 10);
            QVERIFY(changed.wait(60000));
        }
        QTest::mouseRelease(gl, Qt::LeftButton, {}, end);
        QVERIFY(finished.wait(120000));
        QVERIFY(test::waitForWorkerIdle(window, 120000));
        // A large surface's scenes follow in the background: F fits what is drawn, so the
        // views first catch up with the design.
        views::SceneCache* cache = views::SceneCache::of(doc);
        QTRY_VERIFY_WITH_TIMEOUT(!cache->spatialPending() && !cache->developmentPending(), 60000);
        surfaceView->grabImage();
        const QStringList left = cutOff(surfaceView, doc->surface(0));
        QVERIFY2(!left.isEmpty(), qPrintable(QStringLiteral("the drag did not leave the view: ") +
                                             window.solverPanel()->statusText()));

        // View ▸ Fit (F): every vertex, the pins too, is drawn whole in both views.
        QCOMPARE(window.action(QStringLiteral("actionFitAll"))->shortcut(),
                 QKeySequence(QStringLiteral("F")));
        // Triggered, not typed: under a parallel ctest another test's window may hold the
        // keyboard focus of the shared display.
        window.action(QStringLiteral("actionFitAll"))->trigger();
        for (views::SceneView* view : {static_cast<views::SceneView*>(surfaceView),
                                       static_cast<views::SceneView*>(window.developmentView())}) {
            view->grabImage();
            const QStringList outside = cutOff(view, doc->surface(0));
            QVERIFY2(outside.isEmpty(), qPrintable(outside.join(QStringLiteral("; "))));
            for (model::VertexId pin : pins) {
                QVERIFY(view->pinnedPicks().count({Pick::Kind::Vertex, 0, pin}) == 1);
            }
        }
    }

    void theDocksKeepTheirWidthWhateverThePanelsSay() {
        app::MainWindow window;
        QVERIFY(test::showActiveWithExample(window, QStringLiteral("fig8")));
        auto* dock = window.findChild<QDockWidget*>(QStringLiteral("SolverDock"));
        QVERIFY(dock != nullptr);
        QCoreApplication::processEvents();
        const int width = dock->width();
        const int viewWidth = window.surfaceView()->width();
        // A report with a very long sentence, as a failure with the solver's note gives.
        app::SolveReport report;
        report.title = QStringLiteral("Solve");
        report.status = QString(QStringLiteral("a-very-long-technical-note ")).repeated(40);
        report.worstFaces << QString(QStringLiteral("patch 1234567890: 1.0e-03 ")).repeated(20);
        window.solverPanel()->showReport(report);
        QCoreApplication::processEvents();
        QTRY_COMPARE(dock->width(), width);
        QCOMPARE(window.surfaceView()->width(), viewWidth);
        // The Properties panel with many vertices selected says a lot too.
        std::set<Pick> picks;
        for (const auto& [id, position] : window.workspace()->document()->surface(0).vertices()) {
            (void)position;
            picks.insert({Pick::Kind::Vertex, 0, id});
        }
        auto* properties = window.findChild<QDockWidget*>(QStringLiteral("PropertiesDock"));
        QVERIFY(properties != nullptr);
        const int propertiesWidth = properties->width();
        window.workspace()->selection()->set(picks);
        QCoreApplication::processEvents();
        QTRY_COMPARE(properties->width(), propertiesWidth);
        QCOMPARE(window.surfaceView()->width(), viewWidth);
    }

    void aLongStatusMessageIsElidedBeforeTheCounters() {
        app::MainWindow window;
        QVERIFY(test::showActiveWithExample(window, QStringLiteral("fig8")));
        auto* bar = qobject_cast<app::ElidingStatusBar*>(window.statusBar());
        QVERIFY(bar != nullptr);
        QLabel* counts = nullptr;
        for (QLabel* label : bar->findChildren<QLabel*>()) {
            if (label->isVisible() && !label->text().isEmpty() &&
                (counts == nullptr || label->x() > counts->x())) {
                counts = label;
            }
        }
        QVERIFY(counts != nullptr);
        const QString longMessage =
            QString(QStringLiteral("Solved: something rather long to say. ")).repeated(30);
        bar->showMessage(longMessage);
        QCoreApplication::processEvents();
        const QString shown = bar->shownMessage();
        QVERIFY(shown.size() < longMessage.size());
        QVERIFY(shown.endsWith(QChar(0x2026))); // …
        QVERIFY(bar->fontMetrics().horizontalAdvance(shown) <= bar->messageRect().width());
        QVERIFY2(bar->messageRect().right() < counts->x(),
                 qPrintable(
                     QStringLiteral("%1 vs %2").arg(bar->messageRect().right()).arg(counts->x())));
        QCOMPARE(bar->toolTip(), longMessage); // the whole message on demand
        // A short one is shown whole, without a tooltip.
        bar->showMessage(QStringLiteral("Saved."));
        QCOMPARE(bar->shownMessage(), QStringLiteral("Saved."));
        QVERIFY(bar->toolTip().isEmpty());
    }
};

DEVSURF_REGISTER_TEST(TstViewFollow);
#include "tst_view_follow.moc"
