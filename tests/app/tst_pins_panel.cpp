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
#include <QLabel>
#include <QListWidget>
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
        auto hoverText = [&]() {
            QTest::mouseMove(gl, QPoint(2, 2)); // nothing there
            QTest::mouseMove(gl, at);
            return hover.isEmpty() ? QString() : hover.back().front().toString();
        };
        // The first vertex the cursor finds (a legend of the view may cover some).
        model::VertexId vertex = 0;
        QString plain;
        for (; vertex < 12 && plain.isEmpty(); ++vertex) {
            at = view->projectVertexToWidget(0, vertex);
            plain = hoverText();
        }
        --vertex;
        QVERIFY(!plain.isEmpty());
        pin(window, {{Pick::Kind::Vertex, 0, vertex}});
        window.workspace()->selection()->clear();
        const QString pinned = hoverText();
        QVERIFY(!pinned.isEmpty());
        QVERIFY2(pinned != plain, qPrintable(pinned));
    }
};

DEVSURF_REGISTER_TEST(TstPinsPanel);
#include "tst_pins_panel.moc"
