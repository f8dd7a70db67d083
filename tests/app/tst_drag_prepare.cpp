// The Drag tool prepares a drag while the pointer rests on a vertex: the press that follows
// continues the prepared session, and anything else starts cold as before.
#include "drag_tool.h"
#include "main_window.h"
#include "model/bspline_curve.h"
#include "model/document/commands/move_vertices_command.h"
#include "model/document/commands/pin_vertices_command.h"
#include "model/document/document.h"
#include "model/document/selection.h"
#include "model/examples.h"
#include "solve_controller.h"
#include "solver/session/crease_drag.h"
#include "solver/worker/solver_worker.h"
#include "test_registry.h"
#include "views/development_view.h"
#include "views/surface_view.h"
#include "views/vtk_opengl_widget.h"
#include "window_test_support.h"
#include "workspace.h"

#include <QAction>
#include <QMouseEvent>
#include <QSettings>
#include <QSignalSpy>
#include <QTest>
#include <QUndoStack>

#include <memory>
#include <optional>

using namespace devsurf;
using document::Pick;
using test::bytesOf;
using test::showActiveWithExample;

class TstDragPrepare : public QObject {
    Q_OBJECT

    // The annulus (48 patches) with vertex 0 pinned, nothing selected and the Drag tool on.
    struct Setup {
        app::MainWindow window;
        document::Document* doc = nullptr;
        QWidget* gl = nullptr;
    };

    static bool show(Setup& s, model::ExampleSheet sheet = model::ExampleSheet::AsBuilt) {
        if (!showActiveWithExample(s.window, QStringLiteral("annulus"), sheet)) {
            return false;
        }
        s.doc = s.window.workspace()->document();
        s.doc->undoStack()->push(
            document::PinVerticesCommand::create(*s.doc, 0, {0}, true).takeCommand().release());
        s.window.workspace()->selection()->clear();
        s.window.action(QStringLiteral("actionDragTool"))->setChecked(true);
        s.gl = s.window.surfaceView()->glWidget();
        s.window.surfaceView()->grabImage();
        return true;
    }

    static QPoint vertexAt(Setup& s, model::VertexId vertex) {
        const QPoint at = s.window.surfaceView()->projectVertexToWidget(0, vertex);
        const auto pick = s.window.surfaceView()->pickAt(at);
        return pick && pick->kind == Pick::Kind::Vertex && pick->id == vertex ? at : QPoint(-1, -1);
    }

    // The pointer comes to rest at `at`, by events sent to the view (the window system drops a
    // move to where the pointer already is, and may merge quick moves under load).
    static void restAt(Setup& s, const QPoint& at) {
        for (const QPoint& p : {at + QPoint(37, 23), at}) {
            QMouseEvent move(QEvent::MouseMove, QPointF(p), s.gl->mapToGlobal(QPointF(p)),
                             Qt::NoButton, Qt::NoButton, Qt::NoModifier);
            QCoreApplication::sendEvent(s.gl, &move);
        }
    }

    // Vertex 21 moved up 20 mm by hand, one undo step: a Solve then runs for a while.
    static void liftVertex21(Setup& s) {
        auto lift = document::MoveVerticesCommand::createTranslation(*s.doc, 0, {21},
                                                                     model::Vec3(0.0, 0.0, 20.0));
        QVERIFY(!lift.isRefused());
        s.doc->undoStack()->push(lift.takeCommand().release());
    }

    // A widget point on edge `edge` that picks it (sampled along the curve), if any.
    static std::optional<QPoint> pointOn(Setup& s, model::EdgeId edge) {
        const model::EdgeRecord& record = s.doc->surface(0).edge(edge);
        const model::BSplineCurve curve =
            model::BSplineCurve::uniform(record.space, record.controlPoints);
        for (int i = 30; i <= 70; ++i) {
            const double u =
                curve.domainBegin() + (curve.domainEnd() - curve.domainBegin()) * i / 100.0;
            const QPoint at = s.window.surfaceView()->projectToWidget(curve.evaluate(u));
            const auto pick = s.window.surfaceView()->pickAt(at);
            if (pick && pick->kind == Pick::Kind::Edge && pick->id == edge) {
                return at;
            }
        }
        return std::nullopt;
    }

    // The worker's results from now on.
    static std::unique_ptr<QSignalSpy> watchResults(Setup& s) {
        return std::make_unique<QSignalSpy>(s.window.solveController()->worker(),
                                            &solver::SolverWorker::finished);
    }

    static solver::SolveResult resultAt(const QSignalSpy& results, qsizetype i) {
        return results.at(i).front().value<solver::SolveResult>();
    }

    // The first result of a move (neither the preparation nor the release).
    static std::optional<solver::SolveResult> firstMove(const QSignalSpy& results) {
        for (qsizetype i = 0; i < results.size(); ++i) {
            const solver::SolveResult result = resultAt(results, i);
            if (!result.outcome.prepared && !result.outcome.settled) {
                return result;
            }
        }
        return std::nullopt;
    }

    // Presses at `at`, moves 20 pixels up in 4 steps and releases; true once the drag ended
    // applied. The first move's result comes before the other moves (later requests replace
    // one the worker has not started yet).
    static bool drag(Setup& s, const QPoint& at, QSignalSpy& results) {
        QSignalSpy finished(s.window.dragTool(), &app::DragTool::dragFinished);
        QTest::mousePress(s.gl, Qt::LeftButton, {}, at);
        QTest::mouseMove(s.gl, at + QPoint(0, -5));
        while (!firstMove(results)) {
            if (!results.wait(30000)) {
                return false;
            }
        }
        for (int i = 2; i <= 4; ++i) {
            QTest::mouseMove(s.gl, at + QPoint(0, -5 * i));
        }
        QTest::mouseRelease(s.gl, Qt::LeftButton, {}, at + QPoint(0, -20));
        return finished.wait(60000) && finished.front().front().toBool();
    }

    // Rests the pointer at `at` and waits for the preparation; its ticket, or 0 if none came.
    static quint64 prepareAt(Setup& s, const QPoint& at, QSignalSpy& results) {
        restAt(s, at);
        if (!results.wait(30000) || !resultAt(results, 0).outcome.prepared) {
            return 0;
        }
        return resultAt(results, 0).ticket;
    }

    // Drags from `at`; true if the drag was applied and its first move started a session of its
    // own instead of continuing the preparation `prepared`.
    static bool dragStartsCold(Setup& s, const QPoint& at, QSignalSpy& results, quint64 prepared) {
        if (!drag(s, at, results)) {
            return false;
        }
        const std::optional<solver::SolveResult> move = firstMove(results);
        return move && move->ticket != prepared &&
               !move->outcome.assessments.front().summary.structureReused;
    }

    // Drags from `at`; true if the drag was applied and its first move continued the session
    // of the preparation `prepared`, finding the solver's structure built.
    static bool dragContinues(Setup& s, const QPoint& at, QSignalSpy& results, quint64 prepared) {
        if (!drag(s, at, results)) {
            return false;
        }
        const std::optional<solver::SolveResult> move = firstMove(results);
        return move && move->ticket == prepared &&
               move->outcome.assessments.front().summary.structureReused;
    }

private slots:
    void init() { QSettings().clear(); }

    void aRestingPointerPreparesTheDragThatFollows() {
        Setup s;
        QVERIFY(show(s));
        const QPoint at = vertexAt(s, 20);
        QVERIFY(at.x() >= 0);
        const std::string before = bytesOf(s.window);
        const model::Vec3 startOf20 = s.doc->surface(0).position(20);
        const auto results = watchResults(s);
        // The pointer comes to rest on vertex 20: the worker prepares its drag and changes
        // nothing.
        restAt(s, at);
        QVERIFY(results->wait(30000));
        const solver::SolveResult prepared = resultAt(*results, 0);
        QVERIFY(prepared.outcome.ok);
        QVERIFY(prepared.outcome.prepared);
        QVERIFY(!prepared.outcome.settled);
        QCOMPARE(prepared.outcome.iterationsRun, 0);
        QCOMPARE(bytesOf(s.window), before);
        QVERIFY(!s.window.dragTool()->isDragging());
        // Coming to rest there again prepares nothing more.
        restAt(s, at);
        QVERIFY(!results->wait(400));
        QCOMPARE(results->size(), 1);

        // The press on it continues the prepared session: the first move finds the solver's
        // structure built and analysed.
        QVERIFY(dragContinues(s, at, *results, prepared.ticket));
        QVERIFY(model::distance(s.doc->surface(0).position(20), startOf20) > 1.0);
    }

    void aPressElsewhereStartsCold() {
        // Prepared on vertex 20, pressed on vertex 21: the drag of 21 gets a session of its own.
        Setup s;
        QVERIFY(show(s));
        const QPoint rest = vertexAt(s, 20);
        const QPoint at = vertexAt(s, 21);
        QVERIFY(rest.x() >= 0 && at.x() >= 0);
        const auto results = watchResults(s);
        const quint64 prepared = prepareAt(s, rest, *results);
        QVERIFY(prepared != 0);
        QVERIFY(dragStartsCold(s, at, *results, prepared));
    }

    void aChangeAfterThePreparationStartsCold() {
        // An edit between the rest and the press (here an undo of the pin) makes the prepared
        // session stale: the press starts a new one from the design as it is now.
        Setup s;
        QVERIFY(show(s));
        const QPoint at = vertexAt(s, 20);
        QVERIFY(at.x() >= 0);
        const auto results = watchResults(s);
        const quint64 prepared = prepareAt(s, at, *results);
        QVERIFY(prepared != 0);
        s.doc->undoStack()->undo(); // vertex 0 is free again
        QVERIFY(!s.doc->surface(0).isPinned(0));
        QVERIFY(dragStartsCold(s, at, *results, prepared));
    }

    void aSolveRunningDelaysThePreparation() {
        // Tools ▸ Solve runs while the pointer comes to rest on vertex 20: the preparation
        // waits for the Solve's result and follows it while the pointer still rests there.
        Setup s;
        QVERIFY(show(s));
        const QPoint at = vertexAt(s, 20);
        QVERIFY(at.x() >= 0);
        liftVertex21(s); // the Solve has work to do
        const auto results = watchResults(s);
        s.window.action(QStringLiteral("actionSolve"))->trigger();
        QVERIFY(s.window.solveController()->isSolving());
        restAt(s, at);
        while (results->size() < 2) {
            QVERIFY(results->wait(60000));
        }
        qInfo("the Solve took %.0f ms", resultAt(*results, 0).outcome.elapsedMs);
        QVERIFY(!resultAt(*results, 0).outcome.prepared); // the Solve's
        QCOMPARE(resultAt(*results, 0).outcome.kind, solver::JobKind::Solve);
        QVERIFY(resultAt(*results, 1).outcome.prepared);
    }

    void anotherJobAfterThePreparationDropsIt() {
        // Prepared, then the worker runs another job (here a Solve of one iteration whose
        // result nobody applies, so the design and its revision stay): the worker's session is
        // gone, so resting there again prepares again, and the drag continues that preparation.
        Setup s;
        QVERIFY(show(s));
        const QPoint at = vertexAt(s, 20);
        QVERIFY(at.x() >= 0);
        const auto results = watchResults(s);
        QVERIFY(prepareAt(s, at, *results) != 0);
        const quint64 revision = s.doc->revision();
        solver::SolveRequest other;
        other.revision = revision;
        other.ticket = 7; // no one's
        other.job.kind = solver::JobKind::Solve;
        other.job.iterations = 1;
        other.job.surfaces = s.doc->project().surfaces;
        s.window.solveController()->worker()->submit(std::move(other));
        QVERIFY(results->wait(60000));
        QCOMPARE(resultAt(*results, 1).ticket, quint64(7));
        QCOMPARE(s.doc->revision(), revision);
        results->clear();
        const quint64 again = prepareAt(s, at, *results);
        QVERIFY(again != 0);
        QVERIFY(dragContinues(s, at, *results, again));
    }

    void aRestInTheDevelopmentViewPreparesItsDrag() {
        // Two-way editing is prepared alike: the annulus holding its sheet, the pointer resting
        // on vertex 20 in the development view. The press there continues the preparation and
        // drags vertex 20's place in the sheet; the surface follows.
        Setup s;
        QVERIFY(show(s, model::ExampleSheet::Held));
        QVERIFY(s.doc->surface(0).keepsDevelopment());
        views::DevelopmentView* view = s.window.developmentView();
        view->grabImage();
        s.gl = view->glWidget();
        const QPoint at = view->projectVertexToWidget(0, 20);
        const auto pick = view->pickAt(at);
        QVERIFY(pick && pick->kind == Pick::Kind::Vertex && pick->id == 20);
        const std::vector<model::Vec2> sheetBefore = s.doc->surface(0).development();
        const model::Vec3 startOf20 = s.doc->surface(0).position(20);
        const auto results = watchResults(s);
        const quint64 prepared = prepareAt(s, at, *results);
        QVERIFY(prepared != 0);
        QCOMPARE(s.doc->surface(0).development(), sheetBefore); // the preparation changes nothing
        QVERIFY(dragContinues(s, at, *results, prepared));
        QVERIFY(s.window.dragTool()->isDragging() == false);
        QVERIFY(s.doc->surface(0).development() != sheetBefore);
        QVERIFY(model::distance(s.doc->surface(0).position(20), startOf20) > 1e-3);

        // Resting on the same vertex in the 3D view prepares another drag (of the vertex, not
        // of its place in the sheet), which a press in the development view does not continue.
        results->clear();
        s.gl = s.window.surfaceView()->glWidget();
        s.window.surfaceView()->grabImage();
        const QPoint in3d = vertexAt(s, 20);
        QVERIFY(in3d.x() >= 0);
        const quint64 in3dPrepared = prepareAt(s, in3d, *results);
        QVERIFY(in3dPrepared != 0);
        s.gl = view->glWidget();
        view->grabImage();
        const QPoint again = view->projectVertexToWidget(0, 20);
        QVERIFY(dragStartsCold(s, again, *results, in3dPrepared));
    }

    void aRestOnACreasePreparesItsDrag() {
        // A rest on a crease (a ring of the annulus between two of its strips) prepares the
        // crease's drag, which the press on it continues.
        Setup s;
        QVERIFY(show(s));
        const model::CompositeSurface& surface = s.doc->surface(0);
        std::optional<QPoint> at;
        model::EdgeId edge = model::kInvalidId;
        for (const auto& [id, record] : surface.edges()) {
            (void)record;
            try {
                solver::CreaseDrag crease(surface, id);
            } catch (const solver::CreaseDragRefused&) {
                continue; // a ruling or a boundary curve
            }
            if ((at = pointOn(s, id))) {
                edge = id;
                break;
            }
        }
        QVERIFY(at);
        const model::EdgeRecord before = surface.edge(edge);
        const auto results = watchResults(s);
        const quint64 prepared = prepareAt(s, *at, *results);
        QVERIFY(prepared != 0);
        QCOMPARE(resultAt(*results, 0).outcome.kind, solver::JobKind::CreaseDrag);
        QVERIFY(dragContinues(s, *at, *results, prepared));
        QVERIFY(s.doc->surface(0).edge(edge).controlPoints != before.controlPoints);
    }

    void smallDesignsAreNotPrepared() {
        // fig8's nine patches answer their first move at once: no preparation.
        Setup s;
        QVERIFY(showActiveWithExample(s.window, QStringLiteral("fig8")));
        s.doc = s.window.workspace()->document();
        s.window.action(QStringLiteral("actionDragTool"))->setChecked(true);
        s.gl = s.window.surfaceView()->glWidget();
        s.window.surfaceView()->grabImage();
        const QPoint at = vertexAt(s, 5);
        QVERIFY(at.x() >= 0);
        const auto results = watchResults(s);
        restAt(s, at);
        QVERIFY(!results->wait(500));
        QVERIFY(!s.window.solveController()->worker()->isBusy());
    }
};

DEVSURF_REGISTER_TEST(TstDragPrepare);

#include "tst_drag_prepare.moc"
