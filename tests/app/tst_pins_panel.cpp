// Pins as data: the Properties panel says a vertex is pinned, the Pins panel lists the pinned
// vertices (select, unpin), and hovering a pinned vertex says so.
#include "main_window.h"
#include "model/document/commands/pin_vertices_command.h"
#include "model/document/document.h"
#include "model/document/selection.h"
#include "panels/pins_panel.h"
#include "panels/properties_panel.h"
#include "test_registry.h"
#include "views/surface_view.h"
#include "views/vtk_opengl_widget.h"
#include "window_test_support.h"
#include "workspace.h"

#include <QAction>
#include <QApplication>
#include <QLabel>
#include <QListWidget>
#include <QMouseEvent>
#include <QPushButton>
#include <QSettings>
#include <QSignalSpy>
#include <QTest>
#include <QUndoStack>

using namespace devsurf;
using document::Pick;

namespace {

void pin(app::MainWindow& window, const std::set<Pick>& vertices) {
    window.workspace()->selection()->set(vertices);
    window.action(QStringLiteral("actionPinVertices"))->trigger();
}

} // namespace

class TstPinsPanel : public QObject {
    Q_OBJECT

private slots:
    void init() { QSettings().clear(); }

    void propertiesSayWhenTheVertexIsPinned() {
        app::MainWindow window;
        window.workspace()->newFromExample(QStringLiteral("annulus"), 0);
        app::PropertiesPanel* properties = window.propertiesPanel();
        const Pick vertex{Pick::Kind::Vertex, 0, 3};
        window.workspace()->selection()->set({vertex});
        QVERIFY(!properties->pinnedLine()->isVisibleTo(properties));
        pin(window, {vertex});
        QVERIFY(window.workspace()->document()->surface(0).isPinned(3));
        QVERIFY(properties->pinnedLine()->isVisibleTo(properties));
        // Another vertex, not pinned; then back.
        window.workspace()->selection()->set({{Pick::Kind::Vertex, 0, 4}});
        QVERIFY(!properties->pinnedLine()->isVisibleTo(properties));
        window.workspace()->selection()->set({vertex});
        QVERIFY(properties->pinnedLine()->isVisibleTo(properties));
        window.workspace()->document()->undoStack()->undo(); // the pin
        QVERIFY(!properties->pinnedLine()->isVisibleTo(properties));
    }

    void thePinsListSelectsAndUnpins() {
        app::MainWindow window;
        window.workspace()->newFromExample(QStringLiteral("annulus"), 0);
        document::Document* doc = window.workspace()->document();
        app::PinsPanel* pins = window.pinsPanel();
        QCOMPARE(pins->list()->count(), 0);
        pin(window, {{Pick::Kind::Vertex, 0, 0}, {Pick::Kind::Vertex, 0, 2}});
        QCOMPARE(pins->list()->count(), 2);
        const std::set<Pick> listed{pins->pickAt(0), pins->pickAt(1)};
        QVERIFY(listed == std::set<Pick>({{Pick::Kind::Vertex, 0, 0}, {Pick::Kind::Vertex, 0, 2}}));

        // A row selects its vertex in the views; a vertex selected in the views selects its row.
        window.workspace()->selection()->clear();
        QVERIFY(!pins->unpinButton()->isEnabled());
        pins->list()->item(1)->setSelected(true);
        const Pick second = pins->pickAt(1);
        QVERIFY(window.workspace()->selection()->picks() == std::set<Pick>{second});
        QVERIFY(pins->unpinButton()->isEnabled());
        window.workspace()->selection()->set({pins->pickAt(0)});
        QVERIFY(pins->list()->item(0)->isSelected() && !pins->list()->item(1)->isSelected());

        // Unpin: one undo step; undo and redo bring the row back and take it away.
        const int steps = doc->undoStack()->count();
        const std::string pinned = test::bytesOf(window);
        const Pick first = pins->pickAt(0);
        QVERIFY(pins->unpinButton()->isEnabled());
        pins->unpinButton()->click();
        QCOMPARE(doc->undoStack()->count(), steps + 1);
        QVERIFY(test::undoCommand<document::PinVerticesCommand>(*doc) != nullptr);
        QVERIFY(!doc->surface(0).isPinned(first.id));
        QVERIFY(doc->surface(0).isPinned(second.id));
        QCOMPARE(pins->list()->count(), 1);
        QCOMPARE(pins->pickAt(0), second);
        doc->undoStack()->undo();
        QCOMPARE(pins->list()->count(), 2);
        QCOMPARE(test::bytesOf(window), pinned);
        doc->undoStack()->redo();
        QCOMPARE(pins->list()->count(), 1);
        // A new design has its own pins (fig6 comes with two).
        window.workspace()->newFromExample(QStringLiteral("fig6"), 0);
        QCOMPARE(pins->list()->count(),
                 int(window.workspace()->document()->surface(0).pinnedVertices().size()));
        QVERIFY(pins->list()->count() > 0);
    }

    void hoveringAPinnedVertexSaysSo() {
        app::MainWindow window;
        QVERIFY(test::showActiveWithExample(window, QStringLiteral("annulus")));
        views::SurfaceView* view = window.surfaceView();
        view->grabImage();
        QWidget* gl = view->glWidget();
        QSignalSpy hover(view, &views::SurfaceView::hoverChanged);
        QPoint at;
        // Moves sent to the view's GL widget itself: a legend or another widget over the point
        // must not take them.
        auto moveTo = [gl](const QPoint& p) {
            QMouseEvent move(QEvent::MouseMove, QPointF(p), QPointF(gl->mapToGlobal(p)),
                             Qt::NoButton, Qt::NoButton, Qt::NoModifier);
            QApplication::sendEvent(gl, &move);
        };
        auto hoverText = [&]() {
            moveTo(QPoint(2, 2)); // nothing there
            moveTo(at);
            return hover.isEmpty() ? QString() : hover.back().front().toString();
        };
        // The first vertex the cursor finds (a legend of the view may cover some), once the
        // view has the scene the background job builds.
        model::VertexId vertex = 0;
        QString plain;
        auto hoverAVertex = [&]() {
            for (vertex = 0; vertex < 12; ++vertex) {
                at = view->projectVertexToWidget(0, vertex);
                plain = hoverText();
                if (!plain.isEmpty()) {
                    return true;
                }
            }
            return false;
        };
        QTRY_VERIFY_WITH_TIMEOUT(hoverAVertex(), 10000);
        pin(window, {{Pick::Kind::Vertex, 0, vertex}});
        window.workspace()->selection()->clear();
        QString pinned; // once the view shows the pin
        QTRY_VERIFY_WITH_TIMEOUT(!(pinned = hoverText()).isEmpty() && pinned != plain, 10000);
    }
};

DEVSURF_REGISTER_TEST(TstPinsPanel);
#include "tst_pins_panel.moc"
