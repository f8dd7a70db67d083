// Drags through the solver worker: continued sessions, the options of each kind, the
// keep-lengths replay and the stop before a degenerate surface.
#include "model/examples.h"
#include "solver/quality/quality_measures.h"
#include "solver/session/crease_drag.h"
#include "solver/session/solve_session.h"
#include "solver/worker/solver_worker.h"
#include "worker_test_support.h"

#include "test_registry.h"

#include <QSignalSpy>
#include <QTest>

#include <algorithm>
#include <cmath>

using namespace devsurf;
using namespace devsurf::solver;
using namespace devsurf::test;

class TstWorkerDrags : public QObject {
    Q_OBJECT

private slots:
    void movesTakeFactorisationsMadeBeside() {
        // SessionOptions::backgroundFactorization on the annulus of size 10 (2.9e7 flops per
        // factorisation): the first move factorises and starts the next factorisation on
        // another thread; once that has finished, the next move's step takes it, and so on;
        // the release factorises every time and ends developable, as without it.
        const model::CompositeSurface start = model::makeExample("annulus", 10).surfaces[0];
        const model::VertexId lifted = 6;
        SessionOptions options = keepLengthsSessionOptions();
        options.backgroundFactorization = true;
        SolveSession session(start, {{lifted, false, start.position(lifted)}}, options);
        for (int move = 1; move <= 4; ++move) {
            QVERIFY(session.setHandleTarget(lifted, start.position(lifted) +
                                                        model::Vec3(0, 0, 2.0 * move)));
            const Summary summary = session.step(1);
            QVERIFY2(summary.succeeded(), summary.briefReport().c_str());
            const IterationStats& it = summary.iterations.front();
            QCOMPARE(it.factorizationReused, move > 1);
            QCOMPARE(it.backgroundFactor, move > 1);
            session.waitForBackgroundFactorization();
        }
        session.settle();
        const Summary after = session.step(10);
        QVERIFY2(after.succeeded(), after.briefReport().c_str());
        for (const IterationStats& it : after.iterations) {
            QVERIFY(!it.factorizationReused);
        }
        QVERIFY2(after.finalMaxConstraintResidual < 1e-8,
                 qPrintable(QString::number(after.finalMaxConstraintResidual)));
        QVERIFY(std::abs(session.surface().position(lifted).z - start.position(lifted).z - 8.0) <
                1e-6);
    }

    void dragContinuesTheSession() {
        // Two requests of one drag give the same bits as one session stepped twice.
        const model::CompositeSurface surface = roughAnnulus(9);
        const model::VertexId dragged = surface.vertices().begin()->first;
        const model::Vec3 from = surface.position(dragged);
        const model::Vec3 first = from + model::Vec3{0.0, 0.0, 1.0};
        const model::Vec3 second = from + model::Vec3{0.0, 0.0, 2.0};
        SolverWorker worker;
        QSignalSpy finished(&worker, &SolverWorker::finished);
        SolveRequest request;
        request.job.kind = JobKind::VertexDrag;
        request.job.drag = 3;
        request.job.lengths = DragLengths::Stretch;
        request.job.iterations = 1;
        request.job.surfaces = {surface};
        request.job.pulled[0] = {{dragged, false, first}};
        request.revision = 1;
        worker.submit(request);
        QVERIFY(waitForResults(finished, 1));
        request.job.pulled[0] = {{dragged, false, second}};
        request.revision = 2;
        worker.submit(request);
        QVERIFY(waitForResults(finished, 2));

        SolveSession session(surface, {{dragged, false, first}});
        QVERIFY(session.step(1).succeeded());
        QVERIFY(session.setHandleTarget(dragged, second));
        QVERIFY(session.step(1).succeeded());
        const SolveResult result = resultAt(finished, 1);
        QVERIFY2(result.outcome.ok, qPrintable(why(result)));
        QVERIFY(result.outcome.surfaces.front() == session.surface());
    }

    void keepLengthsDragSettlesAfterTheRelease() {
        // A drag of fig6's top edge keeping lengths: moves of one iteration, then the release
        // (settle) with 10 iterations. The worker gives the bits of a session built with
        // keepLengthsSessionOptions and settled before its last 10 iterations, and the sheet
        // is developable at the end (without settling it stalls near 3e-4).
        const model::CompositeSurface surface = model::makeExample("fig6").surfaces.front();
        const std::vector<model::VertexId> dragged{4, 5};
        auto targets = [&](double t) {
            std::vector<VertexHandle> handles;
            for (model::VertexId v : dragged) {
                handles.push_back(
                    {v, false, surface.position(v) + model::Vec3{0.0, -30.0 * t, 60.0 * t}});
            }
            return handles;
        };
        SolverWorker worker;
        QSignalSpy finished(&worker, &SolverWorker::finished);
        SolveRequest request;
        request.job.kind = JobKind::VertexDrag;
        request.job.drag = 5;
        request.job.lengths = DragLengths::Stretch;
        request.job.lengths = DragLengths::Keep;
        request.job.surfaces = {surface};
        SolveSession session(surface, targets(0.0), keepLengthsSessionOptions());
        for (int k = 1; k <= 11; ++k) {
            const bool release = k == 11;
            const double t = std::min(1.0, k / 10.0);
            request.job.pulled[0] = targets(t);
            request.job.iterations = release ? 10 : 1;
            request.job.settle = release;
            request.revision = static_cast<quint64>(k);
            worker.submit(request);
            QVERIFY(waitForResults(finished, k));
            for (const VertexHandle& handle : targets(t)) {
                QVERIFY(session.setHandleTarget(handle.vertex, handle.target));
            }
            if (release) {
                session.settle();
            }
            QVERIFY(session.step(release ? 10 : 1).succeeded());
        }
        const SolveResult result = resultAt(finished, 10);
        QVERIFY2(result.outcome.ok, qPrintable(why(result)));
        QVERIFY(result.outcome.surfaces.front() == session.surface());
        QVERIFY2(result.outcome.assessments.front().summary.finalMaxConstraintResidual < 1e-8,
                 qPrintable(QString::number(
                     result.outcome.assessments.front().summary.finalMaxConstraintResidual)));
    }

    void creaseDragUsesItsOwnOptions() {
        // fig6's crease slid 20 mm: moves of one iteration, then the release with 10. The
        // worker gives the bits of a session built with creaseDragSessionOptions and settled
        // before its last 10 iterations (the options of a vertex drag give other bits).
        const model::CompositeSurface surface = model::makeExample("fig6").surfaces.front();
        const CreaseDrag drag(surface, 2);
        const model::Vec3 by{0.0, 20.0, 0.0};
        SolverWorker worker;
        QSignalSpy finished(&worker, &SolverWorker::finished);
        SolveRequest request;
        request.job.kind = JobKind::CreaseDrag;
        request.job.drag = 6;
        request.job.lengths = DragLengths::Stretch;
        request.job.surfaces = {surface};
        SolveSession session(surface, drag.vertexHandles({}, true),
                             drag.controlPointHandles({}, true), creaseDragSessionOptions());
        SolveSession vertexDrag(surface, drag.vertexHandles({}, true),
                                drag.controlPointHandles({}, true));
        for (int k = 1; k <= 11; ++k) {
            const bool release = k == 11;
            const model::Vec3 delta = by * (std::min(1.0, k / 10.0));
            request.job.pulled[0] = drag.vertexHandles(delta, true);
            request.job.pulledControlPoints[0] = drag.controlPointHandles(delta, true);
            request.job.iterations = release ? 10 : 1;
            request.job.settle = release;
            request.revision = static_cast<quint64>(k);
            worker.submit(request);
            QVERIFY(waitForResults(finished, k));
            for (SolveSession* each : {&session, &vertexDrag}) {
                for (const VertexHandle& handle : drag.vertexHandles(delta, true)) {
                    QVERIFY(each->setHandleTarget(handle.vertex, handle.target));
                }
                for (const ControlPointHandle& point : drag.controlPointHandles(delta, true)) {
                    QVERIFY(each->setControlPointTarget(point.edge, point.index, point.target));
                }
                if (release) {
                    each->settle();
                }
                QVERIFY(each->step(release ? 10 : 1).succeeded());
            }
        }
        const SolveResult result = resultAt(finished, 10);
        QVERIFY2(result.outcome.ok, qPrintable(why(result)));
        QVERIFY(result.outcome.surfaces.front() == session.surface());
        QVERIFY(!(result.outcome.surfaces.front() == vertexDrag.surface()));
        QVERIFY(measureQuality(result.outcome.surfaces.front()).developabilityMax <= 1e-8);
    }

    void automaticDragIsReplayedStretchingWhereKeepingLengthsFails() {
        // Tools ▸ Lengths While Dragging ▸ Automatic: a drag keeping lengths whose settled
        // result fails (judgeDrag) is replayed from the press stretching, along the moves the
        // worker solved, and the better of the two is returned. fig8 with all four corners
        // pinned and its middle lifted 85 mm cannot keep lengths (it folds over); fig6 with a
        // free corner lifted 75 mm can.
        auto dragThroughWorker = [](const model::CompositeSurface& start,
                                    const std::vector<model::VertexId>& dragged, double lift,
                                    std::vector<DragMove>* moves) {
            SolverWorker worker;
            QSignalSpy finished(&worker, &SolverWorker::finished);
            SolveRequest request;
            request.job.kind = JobKind::VertexDrag;
            request.job.drag = 3;
            request.job.lengths = DragLengths::Stretch;
            request.job.lengths = DragLengths::Keep;
            request.job.lengths = DragLengths::Automatic;
            request.job.surfaces = {start};
            for (int k = 1; k <= 21; ++k) {
                const bool release = k == 21;
                DragMove move;
                for (model::VertexId v : dragged) {
                    const double t = std::min(20, k) / 20.0;
                    move.vertices.push_back(
                        {v, false, start.position(v) + model::Vec3{0.0, 0.0, lift * t}});
                }
                request.job.pulled[0] = move.vertices;
                request.job.iterations = release ? kIterationsAfterDragKeepingLengths : 1;
                request.job.settle = release;
                request.revision = static_cast<quint64>(k);
                worker.submit(request);
                if (!waitForResults(finished, k)) {
                    return SolveResult{};
                }
                if (!release) {
                    moves->push_back(move); // a release where the last move was is no move
                }
            }
            return resultAt(finished, 20);
        };

        model::CompositeSurface fig8 = model::makeExample("fig8").surfaces.front();
        for (model::VertexId v : {0, 3, 12, 15}) {
            fig8.setPinned(v, true);
        }
        std::vector<DragMove> moves;
        SolveResult result = dragThroughWorker(fig8, {5, 6, 9, 10}, 85.0, &moves);
        QVERIFY2(result.outcome.ok, qPrintable(why(result)));
        const SurfaceAssessment& lifted = result.outcome.assessments.front();
        QVERIFY(lifted.replay && lifted.replay->taken);
        QVERIFY(lifted.replay->keepingLengths.problems() > 0);
        // Why: the four pinned corners hold the whole flat square (model::findVertexHeldByPins).
        QVERIFY(lifted.held.has_value());
        QCOMPARE(lifted.held->pins.size(), std::size_t(3));
        QVERIFY(fig8.isPinned(lifted.held->pins[0]));
        // The replay of the moves as solved (none coalesced here), bit for bit.
        const ReplayedDrag replay = replayStretching(fig8, moves, kIterationsAfterDrag);
        QVERIFY(result.outcome.surfaces.front() == replay.session->surface());
        QVERIFY2(result.outcome.assessments.front().summary.finalMaxConstraintResidual < 1e-8,
                 qPrintable(QString::number(
                     result.outcome.assessments.front().summary.finalMaxConstraintResidual)));
        QVERIFY(lifted.measured);
        QVERIFY(lifted.overlapping.empty());
        const double det = measureQuality(result.outcome.surfaces.front()).developabilityMax;
        QVERIFY2(det < 1e-8, qPrintable(QString::number(det)));

        moves.clear();
        const model::CompositeSurface fig6 = model::makeExample("fig6").surfaces.front();
        result = dragThroughWorker(fig6, {4}, 75.0, &moves);
        QVERIFY2(result.outcome.ok, qPrintable(why(result)));
        QVERIFY(!result.outcome.assessments.front().replay);
        // fig6's two pinned corners hold only its bottom edge.
        QVERIFY(!result.outcome.assessments.front().held);
        QVERIFY2(result.outcome.assessments.front().summary.finalMaxConstraintResidual < 1e-8,
                 qPrintable(QString::number(
                     result.outcome.assessments.front().summary.finalMaxConstraintResidual)));
    }

    void dragStopsBeforeADegenerateSurface() {
        // fig8 lifted 85 mm (stretching, its two corners pinned), then its four middle
        // vertices turned by −30° about the vertical through their centre in 20 moves: in the
        // 7th of the 10 iterations after the release patch 1 flattens to a line. The release's
        // result is the valid state before it, said so (the status ends a drag in the desktop
        // application), where it used to be a shape the document refuses.
        const std::vector<model::VertexId> moved{5, 6, 9, 10};
        model::CompositeSurface lifted = model::makeExample("fig8").surfaces.front();
        {
            std::vector<VertexHandle> handles;
            for (model::VertexId v : moved) {
                handles.push_back({v, false, lifted.position(v)});
            }
            SolveSession lift(lifted, handles);
            for (int k = 1; k <= 20; ++k) {
                for (const VertexHandle& h : handles) {
                    QVERIFY(lift.setHandleTarget(h.vertex,
                                                 h.target + model::Vec3{0.0, 0.0, 85.0 * k / 20}));
                }
                QVERIFY(lift.step(1).succeeded());
            }
            lift.settle();
            QVERIFY(lift.step(10).succeeded());
            lifted = lift.surface();
        }
        // As devsurf-cli drag --rotate 150,171.650635094611,85,0,0,1,-30 turns them.
        const model::Vec3 centre{150.0, 171.650635094611, 85.0};
        auto turned = [&](model::VertexId v, double t) {
            const double angle = -std::acos(-1.0) / 6.0 * t;
            const model::Vec3 d = lifted.position(v) - centre;
            const model::Vec3 cross{-d.y, d.x, 0.0};
            return centre + d * std::cos(angle) + cross * std::sin(angle) +
                   model::Vec3{0.0, 0.0, d.z * (1.0 - std::cos(angle))};
        };
        SolverWorker worker;
        QSignalSpy finished(&worker, &SolverWorker::finished);
        SolveRequest request;
        request.job.kind = JobKind::VertexDrag;
        request.job.drag = 9;
        request.job.lengths = DragLengths::Stretch;
        request.job.surfaces = {lifted};
        for (int k = 1; k <= 21; ++k) {
            const bool release = k == 21;
            std::vector<VertexHandle> handles;
            for (model::VertexId v : moved) {
                handles.push_back({v, false, turned(v, std::min(1.0, k / 20.0))});
            }
            request.job.pulled[0] = handles;
            request.job.iterations = release ? 10 : 1;
            request.job.settle = release;
            request.revision = static_cast<quint64>(k);
            worker.submit(request);
            QVERIFY(waitForResults(finished, k));
        }
        const SolveResult result = resultAt(finished, 20);
        QVERIFY2(result.outcome.ok, qPrintable(why(result)));
        const Summary& summary = result.outcome.assessments.front().summary;
        QCOMPARE(summary.status, Status::StoppedBeforeDegenerate);
        const auto& refused = result.outcome.assessments.front().refusedIterate;
        QVERIFY2(refused && refused->code == model::ProblemCode::ZeroArea, summary.detail.c_str());
        QVERIFY(summary.iterationsCompleted < 10);
        const auto problems = result.outcome.surfaces.front().validate();
        QVERIFY2(problems.empty(),
                 problems.empty() ? "" : model::technicalKey(problems.front()).c_str());
    }
};

DEVSURF_REGISTER_TEST(TstWorkerDrags);
#include "tst_worker_drags.moc"
