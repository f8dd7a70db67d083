#include "io/project_file.h"
#include "main_window.h"
#include "model/document/commands/crease_condition_command.h"
#include "model/document/document.h"
#include "model/document/selection.h"
#include "panels/properties_panel.h"
#include "test_registry.h"
#include "views/development_view.h"
#include "views/surface_view.h"
#include "views/vtk_opengl_widget.h"
#include "window_test_support.h"
#include "workspace.h"

#include <QAction>
#include <QApplication>
#include <QMenu>
#include <QMenuBar>
#include <QSettings>
#include <QStatusBar>
#include <QTest>
#include <QTimer>

using namespace devsurf;
using document::Pick;
using model::CreaseCondition;
using model::EdgeId;
using test::bytesOf;
using test::waitForSolve;
using test::waitForWorkerIdle;

namespace {

const model::CompositeSurface& surfaceOf(const app::MainWindow& window) {
    return window.workspace()->document()->project().surfaces.front();
}

// The 3 × 3 sheet (vertex j·4 + i at (100 i, 100 j)): curves run along x, rulings along y.
struct Sheet {
    EdgeId crease, otherCrease, innerRuling, boundaryRuling;
};

Sheet sheetEdges(const model::CompositeSurface& sheet) {
    return {sheet.edgeBetween(4, 5), sheet.edgeBetween(5, 6), sheet.edgeBetween(5, 9),
            sheet.edgeBetween(0, 4)};
}

Pick edgePick(EdgeId id) {
    return {Pick::Kind::Edge, 0, id};
}

} // namespace

class TstCreaseMenu : public QObject {
    Q_OBJECT
private slots:
    void init() { QSettings().clear(); }

    void toolsCreaseSubmenuListsConditionsThenSmoothAndSharp() {
        app::MainWindow window;
        QMenu* crease = window.findChild<QMenu*>(QStringLiteral("menuCrease"));
        QVERIFY(crease != nullptr);
        QStringList names;
        for (QAction* a : crease->actions()) {
            names << (a->isSeparator() ? QStringLiteral("|") : a->objectName());
        }
        QCOMPARE(names.join(','), QStringLiteral("actionCurvedFold,actionGeodesic,"
                                                 "actionStraightWhenUnfolded,actionNoCondition,|,"
                                                 "actionSmoothRulings,actionSharpRulings"));
        QCOMPARE(window.action("actionStraightWhenUnfolded")->text(),
                 document::CreaseConditionCommand::conditionText(CreaseCondition::Straight));
        // Under Tools (the menu of Tools ▸ Solve).
        bool underTools = false;
        for (QAction* menu : window.menuBar()->actions()) {
            if (menu->menu() != nullptr && menu->menu()->actions().contains(crease->menuAction())) {
                underTools = menu->menu()->actions().contains(window.action("actionSolve"));
            }
        }
        QVERIFY(underTools);
    }

    void enabledStateFollowsTheSelection() {
        app::MainWindow window;
        window.workspace()->newFromExample(QStringLiteral("sheet"), 3);
        const Sheet sheet = sheetEdges(surfaceOf(window));
        QAction* curved = window.action("actionCurvedFold");
        QAction* smooth = window.action("actionSmoothRulings");
        QAction* sharp = window.action("actionSharpRulings");
        QVERIFY(!curved->isEnabled() && !smooth->isEnabled());
        // Disabled, an action says what to select; enabled, something else.
        const QString selectCreases = curved->toolTip();
        QVERIFY(!selectCreases.isEmpty());
        document::Selection* selection = window.workspace()->selection();
        selection->set({edgePick(sheet.crease)});
        QVERIFY(curved->isEnabled());
        QVERIFY(curved->toolTip() != selectCreases);
        QVERIFY(!curved->isChecked());
        QVERIFY(!smooth->isEnabled());
        const QString selectRulings = smooth->toolTip();
        QVERIFY(!selectRulings.isEmpty());
        selection->set({edgePick(sheet.innerRuling)});
        QVERIFY(!curved->isEnabled());
        QVERIFY(smooth->isEnabled() && sharp->isEnabled());
        QVERIFY(smooth->toolTip() != selectRulings);
        QVERIFY(sharp->isChecked() && !smooth->isChecked()); // rulings start sharp
        selection->set({edgePick(sheet.boundaryRuling)});
        QVERIFY(!smooth->isEnabled() && !sharp->isEnabled());
    }

    void conditionsApplyAndUndoByteExact() {
        app::MainWindow window;
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        window.workspace()->newFromExample(QStringLiteral("sheet"), 3);
        const Sheet sheet = sheetEdges(surfaceOf(window));
        window.workspace()->selection()->set({edgePick(sheet.crease), edgePick(sheet.otherCrease)});
        std::vector<std::string> states{bytesOf(window)};
        const std::pair<const char*, CreaseCondition> steps[] = {
            {"actionCurvedFold", CreaseCondition::CurvedFold},
            {"actionGeodesic", CreaseCondition::Geodesic},
            {"actionStraightWhenUnfolded", CreaseCondition::Straight},
            {"actionNoCondition", CreaseCondition::None}};
        for (const auto& [name, condition] : steps) {
            QAction* action = window.action(QString::fromLatin1(name));
            QVERIFY2(action->isEnabled(), name);
            action->trigger();
            QCOMPARE(surfaceOf(window).edge(sheet.crease).condition, condition);
            QCOMPARE(surfaceOf(window).edge(sheet.otherCrease).condition, condition);
            QVERIFY2(action->isChecked(), name);
            states.push_back(bytesOf(window));
            QVERIFY(states.back() != states[states.size() - 2]);
            // The properties of one of them name the condition.
            window.workspace()->selection()->set({edgePick(sheet.crease)});
            QVERIFY(window.propertiesPanel()->describedCrease().has_value());
            QCOMPARE(window.propertiesPanel()->describedCrease()->edge, sheet.crease);
            const QString text = window.propertiesPanel()->summaryText();
            QVERIFY2(text.contains(document::CreaseConditionCommand::conditionText(condition)),
                     qPrintable(text));
            window.workspace()->selection()->set(
                {edgePick(sheet.crease), edgePick(sheet.otherCrease)});
        }
        // Badges while a condition is set (the 3D and development views draw the last but one).
        window.action("actionUndo")->trigger();
        window.surfaceView()->grabImage();
        window.developmentView()->grabImage();
        QCOMPARE(window.surfaceView()->conditionBadges().size(), std::size_t(2));
        QCOMPARE(window.developmentView()->conditionBadges().size(), std::size_t(2));
        QCOMPARE(window.developmentView()->legendContents().conditions,
                 std::vector<CreaseCondition>{CreaseCondition::Straight});
        QCOMPARE(bytesOf(window), states[3]);
        for (int i = 2; i >= 0; --i) {
            window.action("actionUndo")->trigger();
            QCOMPARE(bytesOf(window), states[static_cast<std::size_t>(i)]);
        }
        for (std::size_t i = 1; i < states.size(); ++i) {
            window.action("actionRedo")->trigger();
            QCOMPARE(bytesOf(window), states[i]);
        }
    }

    void refusalsLeaveTheBytesAndSayWhyInTheStatusBar() {
        app::MainWindow window;
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        window.workspace()->newFromExample(QStringLiteral("sheet"), 3);
        const Sheet sheet = sheetEdges(surfaceOf(window));
        const std::string before = bytesOf(window);
        const int undoSteps = window.action("actionUndo")->isEnabled() ? 1 : 0;

        // A ruling among the creases: the command's sentence names it.
        QStatusBar* status = window.statusBar();
        window.workspace()->selection()->set({edgePick(sheet.crease), edgePick(sheet.innerRuling)});
        QAction* geodesic = window.action("actionGeodesic");
        QVERIFY(geodesic->isEnabled());
        status->clearMessage();
        geodesic->trigger();
        QCOMPARE(bytesOf(window), before);
        QVERIFY2(status->currentMessage().contains(QString::number(sheet.innerRuling)),
                 qPrintable(status->currentMessage()));
        QVERIFY(!geodesic->isChecked());

        // The condition the crease already has.
        window.workspace()->selection()->set({edgePick(sheet.crease)});
        status->clearMessage();
        window.action("actionNoCondition")->trigger();
        QCOMPARE(bytesOf(window), before);
        QVERIFY(!status->currentMessage().isEmpty());
        QVERIFY(window.action("actionNoCondition")->isChecked());

        // Sharp on a ruling that is sharp; smooth with a boundary ruling among the edges.
        window.workspace()->selection()->set({edgePick(sheet.innerRuling)});
        status->clearMessage();
        window.action("actionSharpRulings")->trigger();
        QCOMPARE(bytesOf(window), before);
        QVERIFY(!status->currentMessage().isEmpty());
        window.workspace()->selection()->set(
            {edgePick(sheet.innerRuling), edgePick(sheet.boundaryRuling)});
        status->clearMessage();
        window.action("actionSmoothRulings")->trigger();
        QCOMPARE(bytesOf(window), before);
        QVERIFY2(status->currentMessage().contains(QString::number(sheet.boundaryRuling)),
                 qPrintable(status->currentMessage()));
        QCOMPARE(window.action("actionUndo")->isEnabled() ? 1 : 0, undoSteps);
    }

    void smoothAndSharpApplyUndoAndShowInPropertiesAndViews() {
        app::MainWindow window;
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        window.workspace()->newFromExample(QStringLiteral("sheet"), 3);
        const Sheet sheet = sheetEdges(surfaceOf(window));
        const std::string before = bytesOf(window);
        window.workspace()->selection()->set({edgePick(sheet.innerRuling)});
        QVERIFY(window.propertiesPanel()->describedPick() == edgePick(sheet.innerRuling));
        const QString sharpText = window.propertiesPanel()->summaryText();
        QVERIFY(!sharpText.isEmpty());
        window.action("actionSmoothRulings")->trigger();
        QVERIFY(surfaceOf(window).edge(sheet.innerRuling).smooth);
        QVERIFY(window.action("actionSmoothRulings")->isChecked());
        QVERIFY(!window.action("actionSharpRulings")->isChecked());
        // The properties follow: the same ruling, now described as smooth.
        QVERIFY(window.propertiesPanel()->describedPick() == edgePick(sheet.innerRuling));
        const QString text = window.propertiesPanel()->summaryText();
        QVERIFY2(!text.isEmpty() && text != sharpText, qPrintable(text));
        const std::string smooth = bytesOf(window);
        QVERIFY(smooth != before);
        window.developmentView()->grabImage();
        QCOMPARE(window.developmentView()->rulingsDrawn(), std::make_pair(1, 5));
        QVERIFY(window.developmentView()->legendContents().smoothRulings);

        window.action("actionUndo")->trigger();
        QCOMPARE(bytesOf(window), before);
        window.developmentView()->grabImage();
        QCOMPARE(window.developmentView()->rulingsDrawn(), std::make_pair(0, 6));
        window.action("actionRedo")->trigger();
        QCOMPARE(bytesOf(window), smooth);
        window.action("actionSharpRulings")->trigger();
        QCOMPARE(bytesOf(window), before);
    }

    void theViewsContextMenuOffersTheCreaseSubmenuOverAnEdge() {
        app::MainWindow window;
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        window.workspace()->newFromExample(QStringLiteral("sheet"), 3);
        const Sheet sheet = sheetEdges(surfaceOf(window));
        views::DevelopmentView* view = window.developmentView();
        view->grabImage();
        const model::EdgeRecord& ruling = surfaceOf(window).edge(sheet.innerRuling);
        const QPoint at = (view->projectVertexToWidget(0, ruling.from) +
                           view->projectVertexToWidget(0, ruling.to)) /
                          2;
        QStringList offered;
        // The menu runs its own event loop: a timer looks for it there and closes it.
        QTimer poll;
        connect(&poll, &QTimer::timeout, &poll, [&] {
            if (auto* menu = qobject_cast<QMenu*>(QApplication::activePopupWidget())) {
                for (QAction* a : menu->actions()) {
                    if (a->menu() != nullptr) {
                        for (QAction* sub : a->menu()->actions()) {
                            if (sub->isEnabled() && !sub->isSeparator()) {
                                offered << sub->objectName();
                            }
                        }
                    }
                }
                menu->close();
            }
        });
        poll.start(10);
        QTest::mouseClick(view->glWidget(), Qt::RightButton, {}, at);
        poll.stop();
        QVERIFY(window.workspace()->selection()->contains(edgePick(sheet.innerRuling)));
        QCOMPARE(offered.join(','), QStringLiteral("actionSmoothRulings,actionSharpRulings"));
    }
};

DEVSURF_REGISTER_TEST(TstCreaseMenu);
#include "tst_crease_menu.moc"
