// Holding the sheet in the desktop application: Tools ▸ Hold the Sheet, the Sheet Shape dialog
// (shapes, a drawing's outline, crease curves), and what cannot hold a flat sheet.

#include "main_window.h"
#include "model/development.h"
#include "model/document/document.h"
#include "model/sampled_mesh.h"
#include "model/sheet_creases.h"
#include "model/sheet_domain.h"
#include "reactions/sheet_reactions.h"
#include "sheet_shape_dialog.h"
#include "test_registry.h"
#include "window_test_support.h"
#include "workspace.h"

#include <QAction>
#include <QApplication>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFile>
#include <QLabel>
#include <QPushButton>
#include <QSettings>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>
#include <QUndoStack>

#include <cmath>
#include <functional>

using namespace devsurf;

class TstSheetGui : public QObject {
    Q_OBJECT

    // Runs Tools ▸ Sheet Shape… in `window`; `fill` fills in the dialog and ends it (the dialog
    // runs its own event loop: a timer finds it there).
    static void withSheetShapeDialog(app::MainWindow& window,
                                     const std::function<void(app::SheetShapeDialog*)>& fill) {
        QTimer poll;
        QObject::connect(&poll, &QTimer::timeout, &poll, [&] {
            auto* dialog = qobject_cast<app::SheetShapeDialog*>(QApplication::activeModalWidget());
            if (dialog) {
                poll.stop();
                fill(dialog);
            }
        });
        poll.start(10);
        window.action(QStringLiteral("actionSheetShape"))->trigger();
        poll.stop();
    }

private slots:
    void init() { QSettings().clear(); }

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
        withSheetShapeDialog(window, [&](app::SheetShapeDialog* dialog) {
            dialog->shapeBox()->setCurrentIndex(
                dialog->shapeBox()->findData(static_cast<int>(model::SheetShape::Rectangle)));
            offeredWidth = dialog->widthBox()->value();
            dialog->accept();
        });
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
        withSheetShapeDialog(window, [&](app::SheetShapeDialog* dialog) {
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
        withSheetShapeDialog(window, [&](app::SheetShapeDialog* dialog) {
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
        withSheetShapeDialog(window, [&](app::SheetShapeDialog* dialog) {
            said = dialog->creasesLabel()->text();
            dialog->clearCreasesButton()->click();
            dialog->okButton()->click();
        });
        QVERIFY2(said.contains(QStringLiteral("16")), qPrintable(said));
        QVERIFY(doc->surface(0).sheetDomain().creaseCurves.empty());
        doc->undoStack()->undo();
        QCOMPARE(static_cast<int>(doc->surface(0).sheetDomain().creaseCurveOf.size()), 16);
    }

    void creasesHeldAsTheyLie() {
        // fig8 on its 300 × 300 mm square, "As They Lie" in the dialog: its two creases (three
        // S-edges each) become two curves in the sheet that hold all six, in one undo step. A
        // free sheet does not offer it.
        app::MainWindow window;
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        window.workspace()->newFromExample(QStringLiteral("fig8"), 0);
        document::Document* doc = window.workspace()->document();
        const int steps = doc->undoStack()->count();
        bool offeredWhenFree = true;
        QString said;
        withSheetShapeDialog(window, [&](app::SheetShapeDialog* dialog) {
            dialog->shapeBox()->setCurrentIndex(
                dialog->shapeBox()->findData(static_cast<int>(model::SheetShape::Free)));
            offeredWhenFree = dialog->keepCreasesButton()->isEnabled();
            dialog->shapeBox()->setCurrentIndex(
                dialog->shapeBox()->findData(static_cast<int>(model::SheetShape::Rectangle)));
            dialog->widthBox()->setValue(300.0);
            dialog->heightBox()->setValue(300.0);
            QVERIFY(dialog->keepCreasesButton()->isEnabled());
            dialog->keepCreasesButton()->click();
            said = dialog->creasesLabel()->text();
            dialog->okButton()->click();
        });
        QVERIFY(!offeredWhenFree);
        // "the creases as they lie: 2 curves, holding 6 creases" (in any language).
        QVERIFY2(said.contains(QStringLiteral("2")) && said.contains(QStringLiteral("6")),
                 qPrintable(said));
        QCOMPARE(doc->undoStack()->count(), steps + 1);
        const model::SheetDomain& held = doc->surface(0).sheetDomain();
        QCOMPARE(held.shape, model::SheetShape::Rectangle);
        QCOMPARE(static_cast<int>(held.creaseCurves.size()), 2);
        QCOMPARE(static_cast<int>(held.creaseCurveOf.size()), 6);
        const model::SampledMesh mesh =
            model::sampleSurface(doc->surface(0), model::kDevelopmentSamplesPerInterval);
        const double gap = model::largestCreaseCurveGap(held, mesh, doc->surface(0).development());
        QVERIFY2(gap < 1e-6, qPrintable(QString::number(gap)));
        doc->undoStack()->undo();
        QVERIFY(doc->surface(0).sheetDomain().creaseCurves.empty());
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
};

DEVSURF_REGISTER_TEST(TstSheetGui);
#include "tst_sheet_gui.moc"
