#include "drag_tool.h"
#include "io/project_file.h"
#include "main_window.h"
#include "model/development.h"
#include "model/document/commands/apply_surface_command.h"
#include "model/document/commands/move_vertices_command.h"
#include "model/document/commands/pin_vertices_command.h"
#include "model/document/document.h"
#include "model/document/selection.h"
#include "model/topology_edits.h"
#include "move_dialog.h"
#include "panels/solver_panel.h"
#include "rotate_tool.h"
#include "sampled_developability.h"
#include "solve_controller.h"
#include "solver/quality/quality_measures.h"
#include "solver/quality/shape_change.h"
#include "solver/session/drag_lengths.h"
#include "solver/worker/solver_worker.h"
#include "test_registry.h"
#include "views/surface_view.h"
#include "views/vtk_opengl_widget.h"
#include "window_test_support.h"
#include "workspace.h"

#include <QAction>
#include <QApplication>
#include <QCheckBox>
#include <QDoubleSpinBox>
#include <QRadioButton>
#include <QSettings>
#include <QSignalSpy>
#include <QTest>
#include <QTimer>
#include <QUndoStack>

#include <cmath>
#include <functional>

using namespace devsurf;
using document::Pick;
using test::bytesOf;
using test::waitForSolve;
using test::waitForWorkerIdle;

namespace {

bool identical(const model::Vec3& a, const model::Vec3& b) {
    return a.x == b.x && a.y == b.y && a.z == b.z;
}

// The signed angle (degrees) from a to b about the unit axis.
double angleAbout(const model::Vec3& a, const model::Vec3& b, const model::Vec3& axis) {
    const model::Vec3 pa = a - axis * dot(a, axis);
    const model::Vec3 pb = b - axis * dot(b, axis);
    return std::atan2(dot(cross(pa, pb), axis), dot(pa, pb)) * 180.0 / M_PI;
}

// A shown window with the annulus, vertices kPressed and kOther selected, kPinned pinned.
struct Setup {
    static constexpr model::VertexId kPressed = 20;
    static constexpr model::VertexId kOther = 21;
    static constexpr model::VertexId kPinned = 0;

    app::MainWindow window;
    document::Document* doc = nullptr;
    QWidget* gl = nullptr;
    QPoint at;

    bool prepare(const QString& tool) {
        window.show();
        window.activateWindow();
        if (!QTest::qWaitForWindowActive(&window)) {
            return false;
        }
        window.workspace()->newFromExample(QStringLiteral("annulus"), 0);
        doc = window.workspace()->document();
        doc->undoStack()->push(
            document::PinVerticesCommand::create(*doc, 0, {kPinned}, true).takeCommand().release());
        window.workspace()->selection()->set(
            {{Pick::Kind::Vertex, 0, kPressed}, {Pick::Kind::Vertex, 0, kOther}});
        if (!tool.isEmpty()) {
            window.action(tool)->setChecked(true);
        }
        gl = window.surfaceView()->glWidget();
        window.surfaceView()->grabImage();
        at = window.surfaceView()->projectVertexToWidget(0, kPressed);
        const auto pick = window.surfaceView()->pickAt(at);
        return pick && pick->kind == Pick::Kind::Vertex && pick->id == kPressed;
    }
    model::Vec3 position(model::VertexId v) const { return doc->surface(0).position(v); }
    app::RotateTool* rotateTool() const { return window.findChild<app::RotateTool*>(); }
};

// Runs `fill` on the Move or Rotate dialog once it is open (it runs its own event loop).
void whenMoveDialogOpens(QTimer& poll, const std::function<void(app::MoveDialog*)>& fill) {
    QObject::connect(&poll, &QTimer::timeout, &poll, [&poll, fill] {
        if (auto* dialog = qobject_cast<app::MoveDialog*>(QApplication::activeModalWidget())) {
            poll.stop();
            fill(dialog);
        }
    });
    poll.start(10);
}

// A rotation by angle degrees about the X axis through the centroid, keep developable as given.
std::function<void(app::MoveDialog*)> rotateAboutX(double angle, bool keepDevelopable) {
    return [angle, keepDevelopable](app::MoveDialog* dialog) {
        dialog->findChild<QRadioButton*>(QStringLiteral("rotate"))->setChecked(true);
        dialog->findChild<QDoubleSpinBox*>(QStringLiteral("directionX"))->setValue(1.0);
        dialog->findChild<QDoubleSpinBox*>(QStringLiteral("directionZ"))->setValue(0.0);
        dialog->findChild<QDoubleSpinBox*>(QStringLiteral("angle"))->setValue(angle);
        dialog->findChild<QCheckBox*>(QStringLiteral("keepDevelopable"))
            ->setChecked(keepDevelopable);
        dialog->accept();
    };
}

} // namespace

// The Rotate tool and the axis choice, driven by synthesized mouse events in the 3D view.
class TstRotateTool : public QObject {
    Q_OBJECT

private slots:
    void init() { QSettings().clear(); }

    void theRotateToolIsExclusiveWithTheDragTool() {
        app::MainWindow window;
        QAction* rotate = window.action(QStringLiteral("actionRotateTool"));
        QAction* drag = window.action(QStringLiteral("actionDragTool"));
        QVERIFY(rotate != nullptr && drag != nullptr);
        QCOMPARE(rotate->shortcut(), QKeySequence(QStringLiteral("R")));
        QVERIFY(!rotate->icon().isNull());
        QVERIFY(!rotate->toolTip().isEmpty());
        QVERIFY(rotate->toolTip() != drag->toolTip());
        drag->setChecked(true);
        rotate->setChecked(true);
        QVERIFY(!drag->isChecked());
        rotate->setChecked(false);
        QVERIFY(!rotate->isChecked() && !drag->isChecked()); // no tool is fine too
        for (const char* name : {"actionAxisFree", "actionAxisX", "actionAxisY", "actionAxisZ"}) {
            QAction* axis = window.action(QString::fromLatin1(name));
            QVERIFY2(axis != nullptr && axis->isCheckable(), name);
            QVERIFY2(!axis->toolTip().isEmpty(), name);
        }
        QVERIFY(window.action(QStringLiteral("actionAxisFree"))->isChecked());
    }

    void rotateIsOneUndoStepAboutTheVerticalAxis() {
        Setup s;
        QVERIFY(s.prepare(QStringLiteral("actionRotateTool")));
        app::RotateTool* tool = s.rotateTool();
        QVERIFY(tool != nullptr);
        const int stackAtPress = s.doc->undoStack()->count();
        const std::string atPress = bytesOf(s.window);
        const model::Vec3 pinnedAt = s.position(Setup::kPinned);
        const model::Vec3 a = s.position(Setup::kPressed);
        const model::Vec3 b = s.position(Setup::kOther);
        const model::Vec3 centroid = (a + b) * 0.5;
        QSignalSpy finished(tool, &app::DragTool::dragFinished);
        QSignalSpy status(tool, &app::DragTool::statusMessage);
        QSignalSpy changed(s.doc, &document::Document::changed);
        QTest::mousePress(s.gl, Qt::LeftButton, {}, s.at);
        QVERIFY(tool->isDragging());
        for (int i = 1; i <= 6; ++i) {
            QTest::mouseMove(s.gl, s.at + QPoint(10 * i, 0));
            if (i == 3) {
                QVERIFY(changed.wait(60000)); // the surface follows during the rotation
            }
        }
        QCOMPARE(tool->angleDegrees(), 30.0);
        QVERIFY(s.window.surfaceView()->previewLineCount() > 0); // the axis is drawn
        // About the vertical axis through the pair's centroid, said with the angle.
        QCOMPARE(tool->axisDirection().z, 1.0);
        QVERIFY((tool->axisPoint() - centroid).norm() < 1e-9);
        QVERIFY(!status.isEmpty());
        const QString sentence = status.back().front().toString();
        QVERIFY2(sentence.contains(QStringLiteral("30.0")), qPrintable(sentence));
        QTest::mouseRelease(s.gl, Qt::LeftButton, {}, s.at + QPoint(60, 0));
        QVERIFY(finished.wait(60000));
        QCOMPARE(finished.front().front().toBool(), true);
        QCOMPARE(s.window.surfaceView()->previewLineCount(), 0);
        QCOMPARE(s.doc->undoStack()->count(), stackAtPress + 1);
        QVERIFY(test::undoCommand<document::ApplySurfaceCommand>(*s.doc) != nullptr);
        QVERIFY(s.doc->undoStack()->undoText().contains(QStringLiteral("2"))); // vertices
        // Both vertices turned counter-clockwise seen from above, by about 30°.
        const model::Vec3 z(0.0, 0.0, 1.0);
        const double turnedA = angleAbout(a - centroid, s.position(Setup::kPressed) - centroid, z);
        const double turnedB = angleAbout(b - centroid, s.position(Setup::kOther) - centroid, z);
        qInfo("turned %.2f° and %.2f° for 30°", turnedA, turnedB);
        QVERIFY2(turnedA > 20.0 && turnedA < 40.0, qPrintable(QString::number(turnedA)));
        QVERIFY2(turnedB > 20.0 && turnedB < 40.0, qPrintable(QString::number(turnedB)));
        QVERIFY(identical(s.position(Setup::kPinned), pinnedAt));

        const std::string after = bytesOf(s.window);
        s.doc->undoStack()->undo();
        QCOMPARE(bytesOf(s.window), atPress);
        s.doc->undoStack()->redo();
        QCOMPARE(bytesOf(s.window), after);
    }

    void aChosenAxisTurnsTheOtherWay() {
        Setup s;
        QVERIFY(s.prepare(QStringLiteral("actionRotateTool")));
        s.window.action(QStringLiteral("actionAxisX"))->trigger();
        app::RotateTool* tool = s.rotateTool();
        QCOMPARE(tool->axis(), app::DragTool::Axis::X);
        const model::Vec3 a = s.position(Setup::kPressed);
        const model::Vec3 b = s.position(Setup::kOther);
        const model::Vec3 centroid = (a + b) * 0.5;
        QSignalSpy finished(tool, &app::DragTool::dragFinished);
        QTest::mousePress(s.gl, Qt::LeftButton, {}, s.at);
        for (int i = 1; i <= 4; ++i) {
            QTest::mouseMove(s.gl, s.at - QPoint(10 * i, 0)); // to the left: negative angle
        }
        QCOMPARE(tool->angleDegrees(), -20.0);
        QCOMPARE(tool->axisDirection().x, 1.0);
        QTest::mouseRelease(s.gl, Qt::LeftButton, {}, s.at - QPoint(40, 0));
        QVERIFY(finished.wait(60000));
        QCOMPARE(finished.front().front().toBool(), true);
        const model::Vec3 x(1.0, 0.0, 0.0);
        const model::Vec3 nowA = s.position(Setup::kPressed) - centroid;
        const model::Vec3 nowB = s.position(Setup::kOther) - centroid;
        // Seen along X the pair turned clockwise; along X itself they barely moved.
        const double turnedA = angleAbout(a - centroid, nowA, x);
        const double turnedB = angleAbout(b - centroid, nowB, x);
        qInfo("turned %.2f° and %.2f° about X for -20°", turnedA, turnedB);
        QVERIFY2(turnedA < -5.0 || turnedB < -5.0,
                 qPrintable(QStringLiteral("%1 %2").arg(turnedA).arg(turnedB)));
        QVERIFY(turnedA < 1.0 && turnedB < 1.0);
    }

    void theViewAxisIsAnOption() {
        Setup s;
        QVERIFY(s.prepare(QStringLiteral("actionRotateTool")));
        QAction* viewAxis = s.window.action(QStringLiteral("actionRotateViewAxis"));
        QVERIFY(viewAxis != nullptr && !viewAxis->isChecked());
        viewAxis->setChecked(true);
        QVERIFY(QSettings().value(QStringLiteral("tools/rotateViewAxis")).toBool());
        app::RotateTool* tool = s.rotateTool();
        const std::string atPress = bytesOf(s.window);
        QSignalSpy status(tool, &app::DragTool::statusMessage);
        QTest::mousePress(s.gl, Qt::LeftButton, {}, s.at);
        QTest::mouseMove(s.gl, s.at + QPoint(20, 0));
        const model::Vec3 view = s.window.surfaceView()->viewDirection();
        const model::Vec3 towardsViewer = view * (-1.0 / view.norm());
        QVERIFY((tool->axisDirection() - towardsViewer).norm() < 1e-12);
        QVERIFY(tool->aboutViewAxis());
        QVERIFY(!status.isEmpty());
        // The axis choice wins over the option.
        s.window.action(QStringLiteral("actionAxisY"))->trigger();
        QCOMPARE(tool->axisDirection().y, 1.0);
        QTest::keyClick(s.gl, Qt::Key_Escape);
        QTest::mouseRelease(s.gl, Qt::LeftButton, {}, s.at + QPoint(20, 0));
        QVERIFY(waitForWorkerIdle(s.window, 60000));
        QCOMPARE(bytesOf(s.window), atPress);
    }

    void escapeMidRotateRestoresThePressState() {
        Setup s;
        QVERIFY(s.prepare(QStringLiteral("actionRotateTool")));
        app::RotateTool* tool = s.rotateTool();
        const int stackAtPress = s.doc->undoStack()->count();
        const std::string atPress = bytesOf(s.window);
        QSignalSpy finished(tool, &app::DragTool::dragFinished);
        QSignalSpy status(tool, &app::DragTool::statusMessage);
        QSignalSpy changed(s.doc, &document::Document::changed);
        QTest::mousePress(s.gl, Qt::LeftButton, {}, s.at);
        QTest::mouseMove(s.gl, s.at + QPoint(40, 0));
        QVERIFY(changed.wait(60000));
        QVERIFY(bytesOf(s.window) != atPress);
        const qsizetype said = status.size();
        QTest::keyClick(s.gl, Qt::Key_Escape);
        QCOMPARE(finished.size(), 1);
        QCOMPARE(finished.front().front().toBool(), false);
        QVERIFY(!tool->isDragging());
        QVERIFY(status.size() > said); // says so
        QCOMPARE(bytesOf(s.window), atPress);
        QCOMPARE(s.doc->undoStack()->count(), stackAtPress);
        QCOMPARE(s.window.surfaceView()->previewLineCount(), 0);
        QVERIFY(!s.window.workspace()->selection()->isEmpty());
        QTest::mouseRelease(s.gl, Qt::LeftButton, {}, s.at + QPoint(40, 0));
        QVERIFY(waitForWorkerIdle(s.window, 60000));
        QCOMPARE(bytesOf(s.window), atPress);
        QCOMPARE(s.doc->undoStack()->count(), stackAtPress);
    }

    void oneVertexAloneIsNotRotated() {
        Setup s;
        QVERIFY(s.prepare(QStringLiteral("actionRotateTool")));
        s.window.workspace()->selection()->set({{Pick::Kind::Vertex, 0, Setup::kPressed}});
        QSignalSpy status(s.rotateTool(), &app::DragTool::statusMessage);
        QTest::mousePress(s.gl, Qt::LeftButton, {}, s.at);
        QVERIFY(!s.rotateTool()->isDragging());
        QVERIFY(!status.isEmpty()); // says why
        QTest::mouseRelease(s.gl, Qt::LeftButton, {}, s.at);
    }

    void aPressOnAnUnselectedVertexTurnsTheSelection() {
        Setup s;
        QVERIFY(s.prepare(QStringLiteral("actionRotateTool")));
        const std::set<Pick> picks{{Pick::Kind::Vertex, 0, Setup::kOther},
                                   {Pick::Kind::Vertex, 0, Setup::kOther + 1}};
        s.window.workspace()->selection()->set(picks);
        const model::Vec3 other = s.position(Setup::kOther);
        QSignalSpy finished(s.rotateTool(), &app::DragTool::dragFinished);
        QTest::mousePress(s.gl, Qt::LeftButton, {}, s.at);
        QVERIFY(s.rotateTool()->isDragging());
        QCOMPARE(s.window.workspace()->selection()->picks(), picks); // the selection stays
        QTest::mouseMove(s.gl, s.at + QPoint(30, 0));
        QTest::mouseRelease(s.gl, Qt::LeftButton, {}, s.at + QPoint(30, 0));
        QVERIFY(finished.wait(60000));
        QCOMPARE(finished.front().front().toBool(), true);
        QVERIFY(test::undoCommand<document::ApplySurfaceCommand>(*s.doc) != nullptr);
        QVERIFY(s.doc->undoStack()->undoText().contains(QStringLiteral("2"))); // vertices
        QVERIFY((s.position(Setup::kOther) - other).norm() > 1.0);
    }

    void theAxisChoiceConstrainsADrag() {
        Setup s;
        QVERIFY(s.prepare(QStringLiteral("actionDragTool")));
        app::DragTool* tool = s.window.dragTool();
        s.window.action(QStringLiteral("actionAxisX"))->trigger();
        QCOMPARE(tool->axis(), app::DragTool::Axis::X);
        QCOMPARE(QSettings().value(QStringLiteral("tools/axis")).toInt(), 1);
        // A held key overrides the choice while held.
        QTest::keyPress(s.gl, Qt::Key_Z);
        QCOMPARE(tool->axis(), app::DragTool::Axis::Z);
        QTest::keyRelease(s.gl, Qt::Key_Z);
        QCOMPARE(tool->axis(), app::DragTool::Axis::X);

        const model::Vec3 start = s.position(Setup::kPressed);
        QSignalSpy finished(tool, &app::DragTool::dragFinished);
        QTest::mousePress(s.gl, Qt::LeftButton, {}, s.at);
        for (int i = 1; i <= 6; ++i) {
            QTest::mouseMove(s.gl, s.at + QPoint(8 * i, -8 * i)); // diagonally on the screen
        }
        QTest::mouseRelease(s.gl, Qt::LeftButton, {}, s.at + QPoint(48, -48));
        QVERIFY(finished.wait(60000));
        QCOMPARE(finished.front().front().toBool(), true);
        const model::Vec3 moved = s.position(Setup::kPressed) - start;
        qInfo("moved %.3f %.3f %.3f", moved.x, moved.y, moved.z);
        QVERIFY2(std::abs(moved.x) > 1.0, qPrintable(QString::number(moved.x)));
        QVERIFY(std::abs(moved.y) < 0.1 * std::abs(moved.x));
        QVERIFY(std::abs(moved.z) < 0.1 * std::abs(moved.x));

        // The choice is remembered for the next window.
        app::MainWindow next;
        QVERIFY(next.action(QStringLiteral("actionAxisX"))->isChecked());
        QCOMPARE(next.dragTool()->axis(), app::DragTool::Axis::X);
    }
};

DEVSURF_REGISTER_TEST(TstRotateTool);

// Tools ▸ Move or Rotate Vertices with Keep developable.
class TstKeepDevelopable : public QObject {
    Q_OBJECT

private slots:
    void init() { QSettings().clear(); }

    void motionAndSolveAreOneUndoStep() {
        Setup s;
        QVERIFY(s.prepare(QString()));
        const std::string before = bytesOf(s.window);
        const int stack = s.doc->undoStack()->count();
        const model::Vec3 pinnedAt = s.position(Setup::kPinned);
        const model::Vec3 a = s.position(Setup::kPressed);
        const model::Vec3 b = s.position(Setup::kOther);
        // The dialog's axis point: the centroid to the spin boxes' four decimals.
        model::Vec3 centroid = (a + b) * 0.5;
        for (int k = 0; k < 3; ++k) {
            centroid[k] = std::round(centroid[k] * 1e4) / 1e4;
        }
        // What the exact motion alone would give.
        const model::RigidMotion motion =
            model::RigidMotion::rotationAbout(centroid, {1.0, 0.0, 0.0}, 10.0 * M_PI / 180.0);
        const model::CompositeSurface movedOnly =
            model::moveVertices(s.doc->surface(0), {Setup::kPressed, Setup::kOther}, motion);
        const double movedOnlyDevelopability = solver::measureQuality(movedOnly).developabilityMax;

        QTimer poll;
        whenMoveDialogOpens(poll, rotateAboutX(10.0, true));
        s.window.action(QStringLiteral("actionMoveRotate"))->trigger();
        QVERIFY(s.window.solveController()->isSolving());
        QVERIFY(s.window.action(QStringLiteral("actionCancelSolve"))->isEnabled());
        QCOMPARE(bytesOf(s.window), before); // nothing moves before the solve has ended
        const QString sentence = waitForSolve(s.window);
        QVERIFY2(s.window.solveController()->lastEnding() == app::SolveController::Ending::Solved,
                 qPrintable(sentence));
        QCOMPARE(s.window.solverPanel()->report().outcome.kind, solver::JobKind::Edit);
        QCOMPARE(s.doc->undoStack()->count(), stack + 1);
        QVERIFY(test::undoCommand<document::ApplySurfaceCommand>(*s.doc) != nullptr);
        QVERIFY(s.doc->undoStack()->undoText().contains(QStringLiteral("2"))); // vertices
        // The moved vertices are where the motion put them, the pin where it was.
        QVERIFY(identical(s.position(Setup::kPressed), movedOnly.position(Setup::kPressed)));
        QVERIFY(identical(s.position(Setup::kOther), movedOnly.position(Setup::kOther)));
        QVERIFY(identical(s.position(Setup::kPinned), pinnedAt));
        const double developability = solver::measureQuality(s.doc->surface(0)).developabilityMax;
        const double mean = solver::measureQuality(s.doc->surface(0)).developabilityMean;
        const double movedOnlyMean = solver::measureQuality(movedOnly).developabilityMean;
        qInfo("developability max, mean: motion alone %.3g, %.3g; with the solve %.3g, %.3g",
              movedOnlyDevelopability, movedOnlyMean, developability, mean);
        QVERIFY(movedOnlyDevelopability > 0.1); // the motion alone breaks developability
        // Measured 5e-9 (2e-8 before steps were kept from halving guarded lengths at once;
        // 9e-10 before vertex developability was on in sessions: the annulus's crease stars
        // now also close their angles); the motion alone gives > 0.1.
        QVERIFY2(developability < 1e-5, qPrintable(QString::number(developability)));
        QVERIFY(mean < 1e-3 * movedOnlyMean);
        QVERIFY(QSettings().value(QStringLiteral("move/keepDevelopable")).toBool());

        const std::string after = bytesOf(s.window);
        s.doc->undoStack()->undo();
        QCOMPARE(bytesOf(s.window), before);
        s.doc->undoStack()->redo();
        QCOMPARE(bytesOf(s.window), after);
    }

    void onAHeldSheetARotationIsNeverLeftBroken_data() {
        QTest::addColumn<double>("degrees");
        QTest::addColumn<bool>("applied");
        QTest::newRow("3 degrees") << 3.0 << true;    // held back 0.015 mm, ready to cut
        QTest::newRow("10 degrees") << 10.0 << true;  // held back 0.11 mm, within 0.036 mm
        QTest::newRow("30 degrees") << 30.0 << false; // a patch 1.8e-4 from developable
    }

    void onAHeldSheetARotationIsNeverLeftBroken() {
        // The annulus holding its sheet (one outer vertex pinned), two inner vertices turned
        // about x, kept developable. The vertices used to be put where the rotation asked
        // after 11 iterations, which stretched the sheet: turned 10°, the design was committed
        // 7e-3 from developable. Now the job runs a held sheet's iterations and refuses a
        // result that is not developable from its sheet; what it keeps, the sheet may hold back.
        // (Turned 10° it was refused as "would stretch its sheet by 5.7 %" while its kept sheet
        // fitted to 0.036 mm: a fresh unfolding of the bent ring, sampled more finely than the
        // sheet is kept, does not close up; it is now measured on the kept sheet.)
        QFETCH(double, degrees);
        QFETCH(bool, applied);
        Setup s;
        QVERIFY(s.prepare(QString()));
        s.window.action(QStringLiteral("actionHoldSheet"))->trigger();
        QVERIFY(s.doc->surface(0).keepsDevelopment());
        const std::string before = bytesOf(s.window);
        const int stack = s.doc->undoStack()->count();
        QTimer poll;
        whenMoveDialogOpens(poll, rotateAboutX(degrees, true));
        s.window.action(QStringLiteral("actionMoveRotate"))->trigger();
        const QString sentence = waitForSolve(s.window);
        qInfo("%s", qPrintable(sentence));
        const app::SolveReport& report = s.window.solverPanel()->report();
        // The sentences' fixed words in the language the test runs in (German in the rerun).
        auto words = [](const char* source) {
            return QCoreApplication::translate("devsurf::app::SolveController", source)
                .section(QStringLiteral("%1"), 0, 0);
        };
        if (!applied) {
            // "Rotate 2 vertices not applied: the motion did not reach the tolerance (residual
            // 1.4e-06; patch 5 sampled 1.8e-04 from developable); the design is unchanged."
            QCOMPARE(s.window.solveController()->lastEnding(),
                     app::SolveController::Ending::LeftAsItWas);
            QVERIFY(report.outcome.assessments.at(0).takenBack != nullptr);
            QVERIFY2(sentence.contains(words("did not reach the tolerance (residual %1")),
                     qPrintable(sentence));
            QVERIFY2(report.status.startsWith(
                         words("not applied, since the motion %1: the design stays as it was")),
                     qPrintable(report.status));
            QCOMPARE(s.doc->undoStack()->count(), stack);
            QCOMPARE(bytesOf(s.window), before);
            return;
        }
        QCOMPARE(s.window.solveController()->lastEnding(), app::SolveController::Ending::Solved);
        // Ready to cut, or (short of the tolerance) developable within a few hundredths of a mm.
        const solver::Verdict& verdict = report.verdict;
        const double isometry = report.outcome.assessments.at(0).isometryMm;
        QVERIFY2(verdict.kind == solver::VerdictKind::ReadyToCut ||
                     (verdict.kind == solver::VerdictKind::WithinIsometry && isometry < 0.05),
                 qPrintable(QString::number(isometry)));
        QCOMPARE(s.doc->undoStack()->count(), stack + 1);
        const model::CompositeSurface& result = s.doc->surface(0);
        QVERIFY(result.keepsDevelopment());
        // Measured from the geometry: developable (short of the tolerance, no patch sampled
        // further than a drag may keep: 6.6e-6 at 10°), on its sheet, nothing folded over.
        const double developable =
            verdict.kind == solver::VerdictKind::ReadyToCut ? 1e-6 : solver::kDragConvergedResidual;
        QVERIFY2(test::sampledDevelopability(result) < developable,
                 qPrintable(QString::number(test::sampledDevelopability(result))));
        // On its sheet as a held sheet counts as kept (0.047 mm over this one of 470 mm).
        QVERIFY2(model::keptSheetStretch(result) <
                     solver::kKeptSheetTolerance * report.outcome.assessments.at(0).sheetExtent,
                 qPrintable(QString::number(model::keptSheetStretch(result))));
        QVERIFY(solver::foldOvers(result).empty());
        // The sheet held the vertices back a little, and the sentence says by how much.
        QVERIFY(report.outcome.assessments.at(0).largestHandleGap > solver::kNegligibleLag);
        QVERIFY2(sentence.contains(words("The sheet held the moved vertices back by up to %1 mm.")),
                 qPrintable(sentence));
        s.doc->undoStack()->undo();
        QCOMPARE(bytesOf(s.window), before);
    }

    void cancellingTheSolveMovesNothing() {
        Setup s;
        QVERIFY(s.prepare(QString()));
        const std::string before = bytesOf(s.window);
        const int stack = s.doc->undoStack()->count();
        QSignalSpy finished(s.window.solveController(), &app::SolveController::finished);
        QTimer poll;
        whenMoveDialogOpens(poll, rotateAboutX(10.0, true));
        s.window.action(QStringLiteral("actionMoveRotate"))->trigger();
        QVERIFY(s.window.solveController()->isSolving());
        QTest::keyClick(&s.window, Qt::Key_Escape);
        QCOMPARE(finished.size(), 1);
        QCOMPARE(s.window.solveController()->lastEnding(), app::SolveController::Ending::Cancelled);
        QVERIFY(waitForWorkerIdle(s.window, 120000));
        QCOMPARE(s.doc->undoStack()->count(), stack);
        QCOMPARE(bytesOf(s.window), before);
        QVERIFY(!s.window.workspace()->selection()->isEmpty());
    }

    void anEditWhileSolvingLeavesTheMotionOut() {
        Setup s;
        QVERIFY(s.prepare(QString()));
        QSignalSpy finished(s.window.solveController(), &app::SolveController::finished);
        QTimer poll;
        whenMoveDialogOpens(poll, rotateAboutX(10.0, true));
        s.window.action(QStringLiteral("actionMoveRotate"))->trigger();
        QVERIFY(s.window.solveController()->isSolving());
        s.doc->undoStack()->push(
            document::PinVerticesCommand::create(*s.doc, 0, {1}, true).takeCommand().release());
        QCOMPARE(finished.size(), 1);
        QCOMPARE(s.window.solveController()->lastEnding(),
                 app::SolveController::Ending::CancelledByChange);
        const std::string pinned = bytesOf(s.window);
        const int stack = s.doc->undoStack()->count();
        QVERIFY(waitForWorkerIdle(s.window, 120000));
        QCOMPARE(s.doc->undoStack()->count(), stack);
        QCOMPARE(bytesOf(s.window), pinned);
    }

    void withoutKeepDevelopableTheMotionIsExact() {
        Setup s;
        QVERIFY(s.prepare(QString()));
        const int stack = s.doc->undoStack()->count();
        const model::Vec3 other = s.position(20 - 1);
        QTimer poll;
        whenMoveDialogOpens(poll, rotateAboutX(25.0, false));
        s.window.action(QStringLiteral("actionMoveRotate"))->trigger();
        QVERIFY(!s.window.solveController()->isSolving());
        QCOMPARE(s.doc->undoStack()->count(), stack + 1);
        const auto* move = test::undoCommand<document::MoveVerticesCommand>(*s.doc);
        QVERIFY(move != nullptr);
        QCOMPARE(move->vertices().size(), std::size_t(2));
        QVERIFY(identical(s.position(20 - 1), other)); // no solve moved anything else
        QVERIFY(!QSettings().value(QStringLiteral("move/keepDevelopable")).toBool());
        // The next dialog remembers the choice.
        QTimer check;
        bool remembered = true;
        QVERIFY(s.window.action(QStringLiteral("actionMoveRotate"))->isEnabled());
        whenMoveDialogOpens(check, [&remembered](app::MoveDialog* dialog) {
            remembered = dialog->keepDevelopable();

            dialog->reject();
        });
        s.window.action(QStringLiteral("actionMoveRotate"))->trigger();
        QVERIFY(!remembered);
        QCOMPARE(s.doc->undoStack()->count(), stack + 1);
    }
};

DEVSURF_REGISTER_TEST(TstKeepDevelopable);
#include "tst_rotate_tool.moc"
