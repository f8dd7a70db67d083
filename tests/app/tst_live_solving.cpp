#include "drag_tool.h"
#include "io/project_file.h"
#include "main_window.h"
#include "model/document/commands/apply_surface_command.h"
#include "model/document/commands/move_vertices_command.h"
#include "model/document/commands/pin_vertices_command.h"
#include "model/document/document.h"
#include "model/document/selection.h"
#include "model/examples.h"
#include "model/sampled_mesh.h"
#include "panels/solver_panel.h"
#include "reactions/sheet_reactions.h"
#include "sheet_shape_dialog.h"
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
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFile>
#include <QLabel>
#include <QMenu>
#include <QPushButton>
#include <QSettings>
#include <QSignalSpy>
#include <QTemporaryDir>
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

    void holdingTheSheetIsOneUndoStep() {
        app::MainWindow window;
        window.workspace()->newFromExample(QStringLiteral("fig8"), 0);
        document::Document* doc = window.workspace()->document();
        QAction* hold = window.action(QStringLiteral("actionHoldSheet"));
        QVERIFY(hold != nullptr && hold->isEnabled() && hold->isCheckable());
        QVERIFY(!hold->isChecked());
        QVERIFY(!doc->surface(0).keepsDevelopment());
        const int steps = doc->undoStack()->count();
        hold->trigger();
        QCOMPARE(doc->undoStack()->count(), steps + 1);
        const model::CompositeSurface& held = doc->surface(0);
        QVERIFY(held.keepsDevelopment() && hold->isChecked());
        QCOMPARE(held.development().size(),
                 model::sampledVertexCount(held, model::kDevelopmentSamplesPerInterval));
        doc->undoStack()->undo();
        QVERIFY(!doc->surface(0).keepsDevelopment() && !hold->isChecked());
        doc->undoStack()->redo();
        QVERIFY(doc->surface(0).keepsDevelopment() && hold->isChecked());
        hold->trigger(); // and back: the sheet may stretch again
        QVERIFY(!doc->surface(0).keepsDevelopment() && doc->surface(0).development().empty());
    }

    void sheetShapeIsChosenInItsDialog() {
        // Tools ▸ Sheet Shape…: the dialog comes up with the rectangle that holds the flat
        // square; choosing it holds the sheet on that rectangle in one undo step.
        app::MainWindow window;
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        window.workspace()->newFromExample(QStringLiteral("sheet"), 0);
        document::Document* doc = window.workspace()->document();
        QAction* shape = window.action(QStringLiteral("actionSheetShape"));
        QVERIFY(shape != nullptr && shape->isEnabled());
        const int steps = doc->undoStack()->count();
        double offeredWidth = 0.0;
        QTimer poll; // the dialog runs its own event loop: a timer fills it in there
        connect(&poll, &QTimer::timeout, &poll, [&] {
            auto* dialog = qobject_cast<app::SheetShapeDialog*>(QApplication::activeModalWidget());
            if (!dialog) {
                return;
            }
            dialog->shapeBox()->setCurrentIndex(
                dialog->shapeBox()->findData(static_cast<int>(model::SheetShape::Rectangle)));
            offeredWidth = dialog->widthBox()->value();
            dialog->accept();
        });
        poll.start(10);
        shape->trigger();
        poll.stop();
        QVERIFY2(std::abs(offeredWidth - 300.0) < 0.01, qPrintable(QString::number(offeredWidth)));
        QCOMPARE(doc->undoStack()->count(), steps + 1);
        const model::CompositeSurface& held = doc->surface(0);
        QVERIFY(held.keepsDevelopment());
        QCOMPARE(held.sheetDomain().shape, model::SheetShape::Rectangle);
        const model::SampledMesh mesh =
            model::sampleSurface(held, model::kDevelopmentSamplesPerInterval);
        QVERIFY(model::largestDomainGap(held.sheetDomain(), mesh, held.development()) < 1e-6);
        QVERIFY(window.action(QStringLiteral("actionHoldSheet"))->isChecked());
        doc->undoStack()->undo();
        QVERIFY(!doc->surface(0).keepsDevelopment());
        QVERIFY(doc->surface(0).sheetDomain().isFree());
        doc->undoStack()->redo();
        QCOMPARE(doc->surface(0).sheetDomain().shape, model::SheetShape::Rectangle);
    }

    void aTubeHoldsTheCylinderItUnrollsOnto() {
        // Hold the Sheet on the cylinder example holds it around a cylinder (one undo step);
        // Sheet Shape… then opens no dialog and says why no flat shape applies.
        app::MainWindow window;
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        window.workspace()->newFromExample(QStringLiteral("cylinder"), 0);
        document::Document* doc = window.workspace()->document();
        const int steps = doc->undoStack()->count();
        window.action(QStringLiteral("actionHoldSheet"))->trigger();
        QCOMPARE(doc->undoStack()->count(), steps + 1);
        QVERIFY(doc->surface(0).keepsDevelopment());
        QCOMPARE(doc->surface(0).sheetDomain().shape, model::SheetShape::Cylinder);
        QSignalSpy said(window.workspace(), &app::Workspace::statusMessage);
        bool dialogShown = false;
        QTimer poll;
        connect(&poll, &QTimer::timeout, &poll, [&] {
            if (auto* dialog = QApplication::activeModalWidget()) {
                dialogShown = true;
                dialog->close();
            }
        });
        poll.start(10);
        window.action(QStringLiteral("actionSheetShape"))->trigger();
        poll.stop();
        QVERIFY(!dialogShown);
        QCOMPARE(doc->undoStack()->count(), steps + 1);
        QVERIFY(!said.isEmpty());
        QCOMPARE(said.last().at(0).toString(),
                 app::SheetShapeReaction::cylinderText(doc->surface(0)));
    }

    void sheetOutlineComesFromADrawing() {
        // Outline of a drawing: a damaged file and a drawing without a closed curve are said
        // in the dialog and OK stays off; a 300 mm square drawn in an SVG becomes the sheet.
        QTemporaryDir dir;
        const auto write = [&dir](const char* name, const QByteArray& bytes) {
            QFile file(dir.filePath(QString::fromLatin1(name)));
            return file.open(QIODevice::WriteOnly) && file.write(bytes) == bytes.size();
        };
        QVERIFY(write("square.svg", "<svg xmlns='http://www.w3.org/2000/svg' width='400mm' "
                                    "height='400mm' viewBox='0 0 400 400'><rect x='50' y='50' "
                                    "width='300' height='300'/></svg>"));
        QVERIFY(write("open.svg", "<svg xmlns='http://www.w3.org/2000/svg' width='10mm' "
                                  "height='10mm' viewBox='0 0 10 10'><path d='M0 0 L5 5'/></svg>"));
        QVERIFY(write("damaged.svg", "<svg><rect"));
        app::MainWindow window;
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        window.workspace()->newFromExample(QStringLiteral("sheet"), 0);
        document::Document* doc = window.workspace()->document();
        QStringList said;
        bool okBeforeChoosing = true;
        QTimer poll;
        connect(&poll, &QTimer::timeout, &poll, [&] {
            auto* dialog = qobject_cast<app::SheetShapeDialog*>(QApplication::activeModalWidget());
            if (!dialog) {
                return;
            }
            poll.stop();
            dialog->shapeBox()->setCurrentIndex(
                dialog->shapeBox()->findData(static_cast<int>(model::SheetShape::Outline)));
            okBeforeChoosing = dialog->okButton()->isEnabled();
            for (const char* name : {"damaged.svg", "open.svg"}) {
                QVERIFY(!dialog->loadOutline(dir.filePath(QString::fromLatin1(name))));
                said << dialog->fitLabel()->text();
                QVERIFY(!dialog->okButton()->isEnabled());
            }
            QString chosen = dir.filePath(QStringLiteral("square.svg"));
            dialog->setOutlineChooser([&chosen] { return chosen; });
            QVERIFY(dialog->outlineButton()->isEnabled());
            dialog->outlineButton()->click();
            said << dialog->fitLabel()->text();
            QVERIFY(dialog->okButton()->isEnabled());
            dialog->okButton()->click();
        });
        poll.start(10);
        window.action(QStringLiteral("actionSheetShape"))->trigger();
        poll.stop();
        QVERIFY(!okBeforeChoosing);
        QCOMPARE(said.size(), 3);
        QVERIFY2(said[0].contains(QStringLiteral("damaged.svg")), qPrintable(said[0]));
        QVERIFY2(said[1].contains(QStringLiteral("open.svg")), qPrintable(said[1]));
        QVERIFY2(!said[2].contains(QStringLiteral(".svg")), qPrintable(said[2])); // it fits
        const model::CompositeSurface& held = doc->surface(0);
        QCOMPARE(held.sheetDomain().shape, model::SheetShape::Outline);
        QVERIFY(std::abs(model::domainArea(held.sheetDomain()) - 90000.0) < 1e-6);
        const model::SampledMesh mesh =
            model::sampleSurface(held, model::kDevelopmentSamplesPerInterval);
        QVERIFY(model::largestDomainGap(held.sheetDomain(), mesh, held.development()) < 1e-6);
    }

    void creaseCurvesComeFromADrawing() {
        // The annulus on an annulus sheet with circles drawn at 130 and 205 mm (a DXF chosen
        // in the dialog): the rings at 125 and 200 mm follow them, in one undo step; "None"
        // takes the curves away again. A free sheet offers no curves.
        QTemporaryDir dir;
        const QString drawing = dir.filePath(QStringLiteral("creases.dxf"));
        {
            QFile file(drawing);
            QVERIFY(file.open(QIODevice::WriteOnly));
            file.write("0\nSECTION\n2\nENTITIES\n"
                       "0\nCIRCLE\n8\nCREASE\n10\n0\n20\n0\n30\n0\n40\n130\n"
                       "0\nCIRCLE\n8\nCREASE\n10\n0\n20\n0\n30\n0\n40\n205\n0\nENDSEC\n0\n"
                       "EOF\n");
        }
        app::MainWindow window;
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        window.workspace()->newFromExample(QStringLiteral("annulus"), 0);
        document::Document* doc = window.workspace()->document();
        const int steps = doc->undoStack()->count();
        bool offeredWhenFree = true;
        QString said;
        QTimer poll;
        connect(&poll, &QTimer::timeout, &poll, [&] {
            auto* dialog = qobject_cast<app::SheetShapeDialog*>(QApplication::activeModalWidget());
            if (!dialog) {
                return;
            }
            poll.stop();
            dialog->shapeBox()->setCurrentIndex(
                dialog->shapeBox()->findData(static_cast<int>(model::SheetShape::Free)));
            offeredWhenFree = dialog->creasesButton()->isEnabled();
            dialog->shapeBox()->setCurrentIndex(
                dialog->shapeBox()->findData(static_cast<int>(model::SheetShape::Annulus)));
            dialog->radiusBox()->setValue(250.0);
            dialog->innerRadiusBox()->setValue(100.0);
            dialog->setCreasesChooser([&drawing] { return drawing; });
            QVERIFY(dialog->creasesButton()->isEnabled());
            dialog->creasesButton()->click();
            said = dialog->creasesLabel()->text();
            dialog->okButton()->click();
        });
        poll.start(10);
        window.action(QStringLiteral("actionSheetShape"))->trigger();
        poll.stop();
        QVERIFY(!offeredWhenFree);
        QVERIFY2(said.contains(QStringLiteral("creases.dxf")) &&
                     said.contains(QStringLiteral("16")),
                 qPrintable(said));
        QCOMPARE(doc->undoStack()->count(), steps + 1);
        const model::SheetDomain& held = doc->surface(0).sheetDomain();
        QCOMPARE(held.shape, model::SheetShape::Annulus);
        QCOMPARE(static_cast<int>(held.creaseCurves.size()), 2);
        QCOMPARE(static_cast<int>(held.creaseCurveOf.size()), 16);
        // Opened again, the dialog shows the curves kept; None clears them.
        poll.disconnect();
        connect(&poll, &QTimer::timeout, &poll, [&] {
            auto* dialog = qobject_cast<app::SheetShapeDialog*>(QApplication::activeModalWidget());
            if (!dialog) {
                return;
            }
            poll.stop();
            said = dialog->creasesLabel()->text();
            dialog->clearCreasesButton()->click();
            dialog->okButton()->click();
        });
        poll.start(10);
        window.action(QStringLiteral("actionSheetShape"))->trigger();
        poll.stop();
        QVERIFY2(said.contains(QStringLiteral("16")), qPrintable(said));
        QVERIFY(doc->surface(0).sheetDomain().creaseCurves.empty());
        doc->undoStack()->undo();
        QCOMPARE(static_cast<int>(doc->surface(0).sheetDomain().creaseCurveOf.size()), 16);
    }

    void aTorusIsNoSheetToHold() {
        // A torus unrolls onto no one sheet, flat or around a cylinder: refused with a message,
        // nothing changed.
        app::MainWindow window;
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        window.workspace()->newFromExample(QStringLiteral("torus"), 0);
        document::Document* doc = window.workspace()->document();
        const int steps = doc->undoStack()->count();
        bool warned = false;
        test::acceptNextMessageBox(warned);
        window.action(QStringLiteral("actionHoldSheet"))->trigger();
        QVERIFY(warned);
        QVERIFY(!doc->surface(0).keepsDevelopment());
        QCOMPARE(doc->undoStack()->count(), steps);
        QVERIFY(!window.action(QStringLiteral("actionHoldSheet"))->isChecked());
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
