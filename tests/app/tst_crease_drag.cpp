#include "drag_tool.h"
#include "main_window.h"
#include "model/bspline_curve.h"
#include "model/document/commands/apply_surface_command.h"
#include "model/document/document.h"
#include "model/document/selection.h"
#include "rotate_tool.h"
#include "solver/quality/quality_measures.h"
#include "test_registry.h"
#include "views/surface_view.h"
#include "views/vtk_opengl_widget.h"
#include "window_test_support.h"
#include "workspace.h"

#include <QAction>
#include <QSettings>
#include <QSignalSpy>
#include <QTest>
#include <QUndoStack>

#include <cmath>
#include <optional>

using namespace devsurf;
using document::Pick;
using test::bytesOf;
using test::waitForWorkerIdle;

// Dragging a crease with the Drag tool (synthesized mouse events in the 3D view): the crease of
// the fig6 example slides within its two strips.
class TstCreaseDrag : public QObject {
    Q_OBJECT

    static constexpr model::EdgeId kCrease = 2;   // fig6: the curved crease
    static constexpr model::EdgeId kBoundary = 0; // fig6: a boundary curve

    struct Setup {
        app::MainWindow window;
        document::Document* doc = nullptr;
        QWidget* gl = nullptr;
    };

    static bool prepare(Setup& s, const QString& tool) {
        s.window.show();
        s.window.activateWindow();
        if (!QTest::qWaitForWindowActive(&s.window)) {
            return false;
        }
        s.window.workspace()->newFromExample(QStringLiteral("fig6"), 0);
        s.doc = s.window.workspace()->document();
        s.window.action(tool)->setChecked(true);
        s.gl = s.window.surfaceView()->glWidget();
        s.window.surfaceView()->grabImage();
        return true;
    }

    // A widget point on edge `edge` that picks it (sampled along the curve), if any.
    static std::optional<QPoint> pointOn(Setup& s, model::EdgeId edge) {
        const model::EdgeRecord& record = s.doc->surface(0).edge(edge);
        const model::BSplineCurve curve =
            model::BSplineCurve::uniform(record.space, record.controlPoints);
        for (int i = 20; i <= 80; ++i) {
            const double u = curve.domainBegin() + (curve.domainEnd() - curve.domainBegin()) *
                                                       (i % 2 ? 100 - i : i) / 100.0;
            const QPoint at = s.window.surfaceView()->projectToWidget(curve.evaluate(u));
            const auto pick = s.window.surfaceView()->pickAt(at);
            if (pick && pick->kind == Pick::Kind::Edge && pick->id == edge) {
                return at;
            }
        }
        return std::nullopt;
    }

private slots:
    void init() { QSettings().clear(); }

    void aDraggedCreaseSlidesWithinTheSheetAsOneUndoStep() {
        Setup s;
        QVERIFY(prepare(s, QStringLiteral("actionDragTool")));
        const std::optional<QPoint> at = pointOn(s, kCrease);
        QVERIFY(at.has_value());
        const int stackAtPress = s.doc->undoStack()->count();
        const std::string atPress = bytesOf(s.window);
        const model::CompositeSurface before = s.doc->surface(0);
        QSignalSpy finished(s.window.dragTool(), &app::DragTool::dragFinished);
        QSignalSpy changed(s.doc, &document::Document::changed);
        QTest::mousePress(s.gl, Qt::LeftButton, {}, *at);
        QVERIFY(s.window.dragTool()->isDragging());
        QVERIFY(s.window.workspace()->selection()->contains({Pick::Kind::Edge, 0, kCrease}));
        for (int i = 1; i <= 6; ++i) {
            QTest::mouseMove(s.gl, *at + QPoint(0, -5 * i));
            if (i == 3) {
                QVERIFY(changed.wait(60000)); // the surface follows during the drag
            }
        }
        QTest::mouseRelease(s.gl, Qt::LeftButton, {}, *at + QPoint(0, -30));
        QVERIFY(finished.wait(60000));
        QCOMPARE(finished.front().front().toBool(), true);
        QCOMPARE(s.doc->undoStack()->count(), stackAtPress + 1);
        QVERIFY(test::undoCommand<document::ApplySurfaceCommand>(*s.doc) != nullptr);
        QVERIFY(!s.window.dragTool()->creaseRefusal().has_value());
        QVERIFY(s.doc->undoStack()->undoText().contains(QString::number(kCrease)));

        // Every interior control point of the crease moved by the same displacement, within
        // the plane of the flat sheet (z = 0), by more than a millimetre.
        const model::CompositeSurface& after = s.doc->surface(0);
        const auto& from = before.edge(kCrease).controlPoints;
        const auto& to = after.edge(kCrease).controlPoints;
        QCOMPARE(to.size(), from.size());
        const model::Vec3 shift = to[1] - from[1];
        QVERIFY2(shift.norm() > 1.0, qPrintable(QString::number(shift.norm())));
        for (std::size_t i = 1; i + 1 < to.size(); ++i) {
            QVERIFY(std::abs(to[i].z) < 1e-6);
            QVERIFY((to[i] - from[i] - shift).norm() < 1e-3 * shift.norm() + 1e-6);
        }
        // The pinned corners stay bit for bit; the result is developable, measured from the
        // geometry.
        for (model::VertexId v : before.pinnedVertices()) {
            QVERIFY(after.position(v) == before.position(v));
        }
        const solver::QualityMeasures quality = solver::measureQuality(after);
        QVERIFY2(quality.developabilityMax <= 1e-8,
                 qPrintable(QString::number(quality.developabilityMax)));

        const std::string moved = bytesOf(s.window);
        s.doc->undoStack()->undo();
        QCOMPARE(bytesOf(s.window), atPress);
        s.doc->undoStack()->redo();
        QCOMPARE(bytesOf(s.window), moved);
    }

    void escapeDuringACreaseDragRestoresTheStateAtPress() {
        Setup s;
        QVERIFY(prepare(s, QStringLiteral("actionDragTool")));
        const std::optional<QPoint> at = pointOn(s, kCrease);
        QVERIFY(at.has_value());
        const int stackAtPress = s.doc->undoStack()->count();
        const std::string atPress = bytesOf(s.window);
        QSignalSpy changed(s.doc, &document::Document::changed);
        QTest::mousePress(s.gl, Qt::LeftButton, {}, *at);
        QTest::mouseMove(s.gl, *at + QPoint(0, -20));
        QVERIFY(changed.wait(60000));
        QVERIFY(bytesOf(s.window) != atPress);
        QTest::keyClick(s.gl, Qt::Key_Escape);
        QVERIFY(!s.window.dragTool()->isDragging());
        QTest::mouseRelease(s.gl, Qt::LeftButton, {}, *at + QPoint(0, -20));
        QVERIFY(waitForWorkerIdle(s.window, 60000));
        QCOMPARE(bytesOf(s.window), atPress);
        QCOMPARE(s.doc->undoStack()->count(), stackAtPress);
    }

    void aBoundaryCurveIsNotDraggedAndTheToolSaysWhy() {
        Setup s;
        QVERIFY(prepare(s, QStringLiteral("actionDragTool")));
        const std::optional<QPoint> at = pointOn(s, kBoundary);
        QVERIFY(at.has_value());
        const std::string atPress = bytesOf(s.window);
        QSignalSpy messages(s.window.dragTool(), &app::DragTool::statusMessage);
        QTest::mousePress(s.gl, Qt::LeftButton, {}, *at);
        QVERIFY(!s.window.dragTool()->isDragging());
        QCOMPARE(s.window.dragTool()->creaseRefusal(),
                 std::optional(solver::CreaseDragRefusal::NotACrease));
        QVERIFY(!messages.isEmpty());
        const QString said = messages.back().front().toString();
        QVERIFY2(said.contains(QString::number(kBoundary)), qPrintable(said)); // names the edge
        QTest::mouseMove(s.gl, *at + QPoint(0, -20));
        QTest::mouseRelease(s.gl, Qt::LeftButton, {}, *at + QPoint(0, -20));
        QCOMPARE(bytesOf(s.window), atPress);
    }

    void theRotateToolDoesNotDragCreases() {
        Setup s;
        QVERIFY(prepare(s, QStringLiteral("actionRotateTool")));
        const std::optional<QPoint> at = pointOn(s, kCrease);
        QVERIFY(at.has_value());
        QTest::mousePress(s.gl, Qt::LeftButton, {}, *at);
        auto* rotate = s.window.findChild<app::RotateTool*>();
        QVERIFY(rotate != nullptr);
        QVERIFY(!rotate->isDragging());
        QTest::mouseRelease(s.gl, Qt::LeftButton, {}, *at);
    }
};

DEVSURF_REGISTER_TEST(TstCreaseDrag);
#include "tst_crease_drag.moc"
