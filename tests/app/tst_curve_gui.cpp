// File ▸ Import Curves…, the reference curves in the 3D view, Edit ▸ Remove Reference Curves and
// Tools ▸ Snap to Reference Curves.
#include "curve_snap.h"
#include "drag_tool.h"
#include "main_window.h"
#include "model/document/commands/reference_curves_command.h"
#include "model/document/document.h"
#include "model/document/selection.h"
#include "reactions/curve_reactions.h"
#include "test_registry.h"
#include "views/development_view.h"
#include "views/surface_view.h"
#include "views/vtk_opengl_widget.h"
#include "window_test_support.h"
#include "workspace.h"

#include <QAction>
#include <QMessageBox>
#include <QProcess>
#include <QProgressDialog>
#include <QPushButton>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>
#include <QUndoStack>

#include <cmath>

using namespace devsurf;
using document::Pick;

namespace {

app::ImportCurvesReaction* importCurvesReaction(const app::MainWindow& window) {
    QAction* action = window.action(QStringLiteral("actionImportCurves"));
    return action != nullptr ? action->findChild<app::ImportCurvesReaction*>() : nullptr;
}

} // namespace

class TstCurveGui : public QObject {
    Q_OBJECT
    QTemporaryDir m_dir;

    QString path(const QString& name) const { return m_dir.filePath(name); }

    // Imports `file` through the action (its file dialog answered with `file`); the result
    // of finished().
    static bool importThroughAction(app::MainWindow& window, const QString& file) {
        app::ImportCurvesReaction* reaction = importCurvesReaction(window);
        reaction->setFileChooser([file] { return file; });
        QSignalSpy finished(reaction, &app::ImportCurvesReaction::finished);
        window.action(QStringLiteral("actionImportCurves"))->trigger();
        if (!finished.wait(60000)) {
            return false;
        }
        return finished.front().front().toBool();
    }

private slots:
    void initTestCase() {
        QProcess python;
        python.start(
            QStringLiteral("/usr/bin/python3"),
            {QStringLiteral(DEVSURF_SOURCE_DIR "/tests/io/write_curves_dxf.py"), m_dir.path()});
        QVERIFY(python.waitForFinished(60000));
        QVERIFY2(python.exitCode() == 0, python.readAllStandardError().constData());
    }

    void importIsOneUndoStepShownIn3dOnly() {
        app::MainWindow window;
        QVERIFY(test::showActiveWithExample(window, QStringLiteral("fig8")));
        document::Document* doc = window.workspace()->document();
        QAction* remove = window.action(QStringLiteral("actionRemoveReferenceCurves"));
        QVERIFY(remove != nullptr && !remove->isEnabled());
        const std::string before = test::bytesOf(window);
        const int steps = doc->undoStack()->count();
        QVERIFY(importThroughAction(window, path("curves.dxf")));
        QCOMPARE(doc->project().referenceCurves.size(), std::size_t(9));
        QCOMPARE(doc->undoStack()->count(), steps + 1);
        QVERIFY(test::undoCommand<document::ReferenceCurvesCommand>(*doc) != nullptr);
        QCOMPARE(window.surfaceView()->referenceCurvesDrawn(), 9);
        QCOMPARE(window.developmentView()->referenceCurvesDrawn(), 0);
        QVERIFY(remove->isEnabled());
        const std::string imported = test::bytesOf(window);
        QVERIFY(imported != before);
        // The curves are drawn, never picked: a click on a curve's point away from the surface
        // picks nothing.
        const model::ReferenceCurve& circle = doc->project().referenceCurves[5];
        QCOMPARE(circle.name, std::string("CIRCLE 6"));
        window.surfaceView()->grabImage();
        const QPoint onCircle = window.surfaceView()->projectToWidget(circle.points[3]);
        const std::optional<Pick> pick = window.surfaceView()->pickAt(onCircle);
        QVERIFY(!pick || pick->kind == Pick::Kind::Face);

        doc->undoStack()->undo();
        QVERIFY(test::bytesOf(window) == before);
        QCOMPARE(window.surfaceView()->referenceCurvesDrawn(), 0);
        QVERIFY(!remove->isEnabled());
        doc->undoStack()->redo();
        QVERIFY(test::bytesOf(window) == imported);
        QCOMPARE(window.surfaceView()->referenceCurvesDrawn(), 9);
        remove->trigger();
        QVERIFY(doc->project().referenceCurves.empty());
        QCOMPARE(window.surfaceView()->referenceCurvesDrawn(), 0);
        doc->undoStack()->undo();
        QVERIFY(test::bytesOf(window) == imported);
    }

    void unreadableFileIsOneMessageAndChangesNothing() {
        app::MainWindow window;
        QVERIFY(test::showActiveWithExample(window, QStringLiteral("fig8")));
        document::Document* doc = window.workspace()->document();
        const std::string before = test::bytesOf(window);
        QFile damaged(path("damaged.dxf"));
        QVERIFY(damaged.open(QIODevice::WriteOnly));
        damaged.write(QByteArray("0\nSECTION\n2\nENTITIES\n0\nLWPOLYLINE\n90\n999999999\n"));
        damaged.close();
        int boxes = 0;
        QTimer closer;
        connect(&closer, &QTimer::timeout, [&boxes] {
            if (auto* box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget())) {
                ++boxes;
                box->accept();
            }
        });
        closer.start(20);
        for (const QString& file : {path("damaged.dxf"), path("missing.step"), path("notes.txt")}) {
            const int shown = boxes;
            QVERIFY(!importThroughAction(window, file));
            QCOMPARE(boxes, shown + 1);
            QVERIFY(test::bytesOf(window) == before);
            QCOMPARE(doc->undoStack()->count(), 0);
            QVERIFY(!doc->isModified());
        }
    }

    void cancelChangesNothing() {
        // Two hundred thousand lines: long enough to read that the cancel comes first.
        QFile big(path("big.dxf"));
        QVERIFY(big.open(QIODevice::WriteOnly));
        big.write("0\nSECTION\n2\nENTITIES\n");
        for (int i = 0; i < 200000; ++i) {
            big.write(QStringLiteral("0\nLINE\n8\n0\n10\n%1\n20\n0\n30\n0\n11\n%1\n21\n1\n31\n0\n")
                          .arg(i)
                          .toLatin1());
        }
        big.write("0\nENDSEC\n0\nEOF\n");
        big.close();
        app::MainWindow window;
        QVERIFY(test::showActiveWithExample(window, QStringLiteral("sheet")));
        const std::string before = test::bytesOf(window);
        app::ImportCurvesReaction* reaction = importCurvesReaction(window);
        reaction->setFileChooser([this] { return path("big.dxf"); });
        QSignalSpy finished(reaction, &app::ImportCurvesReaction::finished);
        window.action(QStringLiteral("actionImportCurves"))->trigger();
        QVERIFY(reaction->isBusy());
        auto* progress = window.findChild<QProgressDialog*>(QStringLiteral("importCurvesProgress"));
        QVERIFY(progress != nullptr);
        auto* cancel = progress->findChild<QPushButton*>();
        QVERIFY(cancel != nullptr);
        cancel->click();
        QVERIFY(finished.wait(60000));
        QCOMPARE(finished.front().front().toBool(), false);
        QVERIFY(!reaction->isBusy());
        QVERIFY(test::bytesOf(window) == before);
        // Not cancelled, the same file is read.
        QVERIFY(importThroughAction(window, path("big.dxf")));
        QCOMPARE(window.workspace()->document()->project().referenceCurves.size(),
                 std::size_t(200000));
    }

    void dragSnapsToAReferenceCurve() {
        app::MainWindow window;
        QVERIFY(test::showActiveWithExample(window, QStringLiteral("annulus")));
        document::Document* doc = window.workspace()->document();
        views::SurfaceView* view = window.surfaceView();
        const model::VertexId dragged = 20;
        const model::Vec3 start = doc->surface(0).position(dragged);
        // A straight curve 15 mm above the vertex, across the view.
        const model::Vec3 lift(0, 0, 15);
        document::CommandOrError add = document::ReferenceCurvesCommand::createImport(
            *doc,
            {{"LINE 1",
              "",
              {start + lift + model::Vec3(-40, 0, 0), start + lift + model::Vec3(40, 0, 0)}}});
        QVERIFY(document::push(*doc, add));
        view->grabImage();
        const QPoint on = view->projectToWidget(start + lift);
        // Within 10 pixels the nearest point of the curve; farther, none.
        const std::optional<app::CurveSnap> near =
            app::snapToCurves(*view, doc->project().referenceCurves, on + QPoint(3, 4));
        QVERIFY(near);
        QCOMPARE(near->curve, 0);
        QVERIFY(near->pixels <= 10.0);
        QVERIFY(std::abs(near->point.z - (start.z + 15)) < 1e-9);
        QVERIFY(std::abs(near->point.y - start.y) < 1e-9);
        QVERIFY(!app::snapToCurves(*view, doc->project().referenceCurves, on + QPoint(0, 40)));

        QAction* snap = window.action(QStringLiteral("actionSnapToCurves"));
        QVERIFY(snap != nullptr && snap->isCheckable());
        window.action(QStringLiteral("actionDragTool"))->setChecked(true);
        window.workspace()->selection()->set({{Pick::Kind::Vertex, 0, dragged}});
        QWidget* gl = view->glWidget();
        const QPoint at = view->projectVertexToWidget(0, dragged);
        for (const bool snapping : {false, true}) {
            snap->setChecked(snapping);
            QCOMPARE(window.dragTool()->snapsToCurves(), snapping);
            QSignalSpy finished(window.dragTool(), &app::DragTool::dragFinished);
            QTest::mousePress(gl, Qt::LeftButton, {}, at);
            QVERIFY(window.dragTool()->isDragging());
            QTest::mouseMove(gl, at + (on - at) / 2);
            QTest::mouseMove(gl, on + QPoint(2, 3));
            QCOMPARE(window.dragTool()->snappedCurve(), snapping ? 0 : -1);
            QTest::keyClick(gl, Qt::Key_Escape); // back to the state at press
            QCOMPARE(finished.size(), 1);
            QVERIFY(!window.dragTool()->isDragging());
            QTest::mouseRelease(gl, Qt::LeftButton, {}, on + QPoint(2, 3));
            QVERIFY(test::waitForWorkerIdle(window, 60000));
            QCOMPARE(doc->surface(0).position(dragged), start);
        }
    }

    void creaseIsFittedToTheNearestCurve() {
        // Two curves: a wave beside and above a crease of fig8, and a line far away. Fitting
        // the selected crease lays it on the wave (one undo step); undo brings it back.
        app::MainWindow window;
        QVERIFY(test::showActiveWithExample(window, QStringLiteral("fig8")));
        document::Document* doc = window.workspace()->document();
        QAction* fit = window.action(QStringLiteral("actionFitEdgeToCurve"));
        QVERIFY(fit != nullptr && !fit->isEnabled()); // no curves yet
        model::EdgeId crease = model::kInvalidId;
        for (const auto& [id, record] : doc->surface(0).edges()) {
            if (record.isSpline() && doc->surface(0).facesOfEdge(id).size() == 2) {
                crease = id;
                break;
            }
        }
        QVERIFY(crease != model::kInvalidId);
        const model::EdgeRecord before = doc->surface(0).edge(crease);
        model::ReferenceCurve wave{"wave", "", {}};
        for (int i = 0; i <= 100; ++i) {
            const double t = i / 100.0;
            const model::Vec3 p =
                before.controlPoints.front() * (1 - t) + before.controlPoints.back() * t;
            wave.points.push_back(p + model::Vec3(0, 5, 10 * std::sin(3.14159265358979 * t)));
        }
        const model::ReferenceCurve away{"away", "", {{0, 0, 500}, {300, 0, 500}}};
        document::CommandOrError add =
            document::ReferenceCurvesCommand::createImport(*doc, {away, wave});
        QVERIFY(document::push(*doc, add));
        QVERIFY(!fit->isEnabled()); // nothing selected
        window.workspace()->selection()->set({{Pick::Kind::Edge, 0, crease}});
        QVERIFY(fit->isEnabled());
        const int steps = doc->undoStack()->count();
        QSignalSpy said(window.workspace(), &app::Workspace::statusMessage);
        fit->trigger();
        QCOMPARE(doc->undoStack()->count(), steps + 1);
        QVERIFY(!said.isEmpty());
        QVERIFY2(said.last().at(0).toString().contains(QStringLiteral("wave")),
                 qPrintable(said.last().at(0).toString()));
        const model::EdgeRecord& after = doc->surface(0).edge(crease);
        const model::Vec3 middle = after.controlPoints[after.controlPoints.size() / 2];
        QVERIFY2(middle.z > 5.0, qPrintable(QString::number(middle.z)));
        doc->undoStack()->undo();
        QVERIFY(doc->surface(0).edge(crease).controlPoints == before.controlPoints);
    }
};

DEVSURF_REGISTER_TEST(TstCurveGui);

#include "tst_curve_gui.moc"
