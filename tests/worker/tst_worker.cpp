#include "model/examples.h"
#include "solver/core/analysis_cache.h"
#include "solver/formulation/perturbation.h"
#include "solver/quality/crease_quality.h"
#include "solver/quality/quality_measures.h"
#include "solver/quality/shape_change.h"
#include "solver/session/crease_drag.h"
#include "solver/worker/solver_worker.h"

#include "helical_band.h"
#include "lifted_fig8.h"
#include "test_registry.h"

#include <QSignalSpy>
#include <QTest>

#include <algorithm>
#include <cmath>
#include <cstring>

using namespace devsurf;
using namespace devsurf::solver;

namespace {

model::CompositeSurface roughAnnulus(unsigned seed = 5) {
    model::CompositeSurface surface = model::makeExample("annulus").surfaces.front();
    perturbSurface(surface, 1e-3 * surfaceDiameter(surface), seed, {});
    return surface;
}

SolveResult resultAt(const QSignalSpy& spy, int index) {
    return spy.at(index).at(0).value<SolveResult>();
}

// Waits until a result arrives (or the spy's wait times out, which fails the test).
bool waitForResults(QSignalSpy& spy, int count) {
    while (spy.count() < count) {
        if (!spy.wait(60000)) {
            return false;
        }
    }
    return true;
}

// One Solve of `surface` (`iterations` at most) on a worker of its own; a result with ok false
// and an error if none arrives.
SolveResult solveOnce(const model::CompositeSurface& surface, int iterations) {
    SolverWorker worker;
    QSignalSpy finished(&worker, &SolverWorker::finished);
    SolveRequest request;
    request.revision = 3;
    request.job.surfaces = {surface};
    request.job.iterations = iterations;
    worker.submit(request);
    if (!waitForResults(finished, 1)) {
        SolveResult none;
        none.outcome.failure.detail = "no result arrived";
        return none;
    }
    return resultAt(finished, 0);
}

// What went wrong, for a failed check's message.
QString why(const SolveResult& result) {
    return QStringLiteral("error %1: %2")
        .arg(static_cast<int>(result.outcome.failure.error))
        .arg(QString::fromStdString(result.outcome.failure.detail));
}

bool allFinite(const model::CompositeSurface& surface) {
    for (const auto& [id, p] : surface.vertices()) {
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) {
            return false;
        }
    }
    for (const auto& [id, edge] : surface.edges()) {
        for (const model::Vec3& p : edge.controlPoints) {
            if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) {
                return false;
            }
        }
    }
    return true;
}

} // namespace

class TstSolverWorker : public QObject {
    Q_OBJECT

private slots:
    void requestYieldsProgressAndResult() {
        SolverWorker worker;
        QSignalSpy progress(&worker, &SolverWorker::progress);
        QSignalSpy finished(&worker, &SolverWorker::finished);
        SolveRequest request;
        request.revision = 42;
        request.job.surfaces = {roughAnnulus(), model::makeExample("sheet").surfaces.front()};
        request.job.iterations = 3;
        worker.submit(request);
        QVERIFY(waitForResults(finished, 1));
        const SolveResult result = resultAt(finished, 0);
        QVERIFY2(result.outcome.ok, qPrintable(why(result)));
        QVERIFY(!result.outcome.cancelled());
        QCOMPARE(result.revision, quint64{42});
        QCOMPARE(result.outcome.surfaces.size(), std::size_t{2});
        QCOMPARE(result.outcome.assessments.size(), std::size_t{2});
        QCOMPARE(result.outcome.assessments[0].summary.iterationsCompleted, 3);
        QVERIFY(!(result.outcome.surfaces[0] == request.job.surfaces[0]));
        QVERIFY(allFinite(result.outcome.surfaces[0]));
        // The sheet is developable already: a Solve stops after its first iteration
        // (kSolveStopResidual).
        QCOMPARE(result.outcome.assessments[1].summary.status, Status::Converged);
        QCOMPARE(result.outcome.assessments[1].summary.iterationsCompleted, 1);
        // Progress: one per iteration of every surface, queued before the result.
        QCOMPARE(progress.count(), 4);
        const QList<QVariant> last = progress.last();
        QCOMPARE(last.at(0).value<quint64>(), quint64{42});
        QCOMPARE(last.at(1).toInt(), 4);
        QCOMPARE(last.at(2).toInt(), 6);
        QVERIFY(std::isfinite(last.at(3).toDouble()));
        QVERIFY(!worker.isBusy());
    }

    void rapidRequestsAreCoalesced() {
        const model::CompositeSurface surface = roughAnnulus();
        const model::VertexId dragged = surface.vertices().rbegin()->first;
        const model::Vec3 from = surface.position(dragged);
        const double diameter = surfaceDiameter(surface);
        std::vector<SolveRequest> requests(100);
        for (int i = 0; i < 100; ++i) {
            SolveRequest& request = requests[static_cast<std::size_t>(i)];
            request.revision = static_cast<quint64>(i + 1);
            request.job.kind = JobKind::VertexDrag;
            request.job.drag = 7;
            request.job.lengths = DragLengths::Stretch;
            request.job.iterations = 1;
            request.job.surfaces = {surface};
            request.job.pulled[0] = {
                {dragged, false, from + model::Vec3{0.0, 0.0, 1e-3 * diameter * (i + 1)}}};
        }
        SolverWorker worker;
        QSignalSpy finished(&worker, &SolverWorker::finished);
        for (SolveRequest& request : requests) {
            worker.submit(std::move(request));
        }
        // Results arrive in order; the last one is the newest request.
        while (finished.isEmpty() || resultAt(finished, finished.count() - 1).revision != 100) {
            QVERIFY(finished.wait(60000));
        }
        QVERIFY(!worker.isBusy());
        quint64 previous = 0;
        for (int i = 0; i < finished.count(); ++i) {
            const SolveResult result = resultAt(finished, i);
            QVERIFY2(result.outcome.ok, qPrintable(why(result)));
            QVERIFY(result.revision > previous);
            previous = result.revision;
        }
        // Only a few of the 100 were solved: the others were replaced while waiting.
        QCOMPARE(static_cast<quint64>(finished.count()), worker.solvedCount());
        QVERIFY2(finished.count() <= 5, qPrintable(QString::number(finished.count())));
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
        QVERIFY2(summary.message.find("zero area") != std::string::npos, summary.message.c_str());
        QVERIFY(summary.iterationsCompleted < 10);
        const std::vector<std::string> problems = result.outcome.surfaces.front().validate();
        QVERIFY2(problems.empty(), problems.empty() ? "" : problems.front().c_str());
    }

    void finalResultsSayWhereTheDevelopmentOverlapsItself() {
        // A band winding one and a half times round: its development overlaps itself whatever
        // the solver makes of its strips. A Solve's result and a drag's settling result say
        // where; the results of a drag's moves, which nobody reports, are not measured.
        const model::CompositeSurface band = test::helicalBand();
        const model::VertexId end = band.vertices().begin()->first;
        auto overlapsItself = [&band](const SolveResult& result) {
            const SurfaceAssessment& a = result.outcome.assessments.front();
            if (!a.measured || a.overlapping.empty()) {
                return false;
            }
            return std::all_of(a.overlapping.begin(), a.overlapping.end(),
                               [&band](model::FaceId face) { return band.hasFace(face); });
        };
        SolverWorker worker;
        QSignalSpy finished(&worker, &SolverWorker::finished);
        SolveRequest request;
        request.job.surfaces = {band};
        request.revision = 1;
        worker.submit(request);
        QVERIFY(waitForResults(finished, 1));
        SolveResult result = resultAt(finished, 0);
        QVERIFY2(result.outcome.ok, qPrintable(why(result)));
        QVERIFY(overlapsItself(result));

        request.job.kind = JobKind::VertexDrag;
        request.job.drag = 7;
        request.job.lengths = DragLengths::Stretch;
        request.job.iterations = 1;
        request.job.pulled[0] = {{end, false, band.position(end) + model::Vec3{0, 0, 1}}};
        request.revision = 2;
        worker.submit(request);
        QVERIFY(waitForResults(finished, 2));
        result = resultAt(finished, 1);
        QVERIFY2(result.outcome.ok, qPrintable(why(result)));
        QVERIFY(!result.outcome.settled && !result.outcome.assessments.front().measured);
        QVERIFY(result.outcome.assessments.front().overlapping.empty());

        request.job.settle = true;
        request.job.iterations = 10;
        request.revision = 3;
        worker.submit(request);
        QVERIFY(waitForResults(finished, 3));
        result = resultAt(finished, 2);
        QVERIFY2(result.outcome.ok, qPrintable(why(result)));
        QVERIFY(overlapsItself(result));

        // A design whose development lies flat without overlapping.
        request = SolveRequest();
        request.job.surfaces = {model::makeExample("annulus").surfaces.front()};
        request.revision = 4;
        worker.submit(request);
        QVERIFY(waitForResults(finished, 4));
        result = resultAt(finished, 3);
        QVERIFY2(result.outcome.ok, qPrintable(why(result)));
        QVERIFY(result.outcome.assessments.front().measured);
        QVERIFY(result.outcome.assessments.front().overlapping.empty());
    }

    void solveNeverLeavesADesignLessDevelopable() {
        // The lifted Fig. 8 folded along curved creases by a drag that kept lengths, 16
        // iterations after the release (det about 3e-6, not nearly valid): a fresh Solve's
        // fairness pulls it towards flat through a crumpled shape (det about 3e-3 after 10
        // iterations): the worker returns it as it was and says so.
        const model::CompositeSurface folded = testing::liftedFig8(16);
        const double before = measureQuality(folded).developabilityMax;
        QVERIFY2(before < 1e-5, qPrintable(QString::number(before)));

        const SolveResult result = solveOnce(folded, 10);
        QVERIFY2(result.outcome.ok, qPrintable(why(result)));
        const auto& kept = result.outcome.assessments.front().keptAsItWas;
        QVERIFY(kept.has_value());
        QVERIFY(result.outcome.surfaces.front() == folded);
        // The figures it reports are the geometry's, and the solved shape was indeed worse.
        QVERIFY(kept->before <= before);
        QVERIFY2(kept->after > kLessDevelopableFactor * kept->before,
                 qPrintable(QString::number(kept->after)));

        // A design Solve improves is solved as before: nothing is kept.
        const model::CompositeSurface annulus = roughAnnulus();
        const SolveResult rough = solveOnce(annulus, 10);
        QVERIFY2(rough.outcome.ok, qPrintable(why(rough)));
        QVERIFY(!rough.outcome.assessments.front().keptAsItWas);
        QVERIFY(!(rough.outcome.surfaces.front() == annulus));
        QCOMPARE(rough.outcome.assessments.front().creases.creases, 0); // no crease condition
    }

    void solveKeepsANearlyValidFold() {
        // The same fold 20 iterations after the release (sampled det about 7e-7, every condition
        // nearly held): Solve keeps the exact normals of its strips, so it starts at the fold's
        // own residual and leaves the fold where it is (before, with fitted cubic normals: det
        // 3e-4 after 30 iterations, a point moved by 116 mm, and the design was kept as it was).
        const model::CompositeSurface folded = testing::liftedFig8(20);
        const double before = measureQuality(folded).developabilityMax;
        QVERIFY2(before < kNearlyValidResidual, qPrintable(QString::number(before)));
        // Its residual cycles (2.6e-8, 1.7e-6, 1.8e-6); Solve ends on the best iterate.
        const SolveResult result = solveOnce(folded, 10);
        QVERIFY2(result.outcome.ok, qPrintable(why(result)));
        QVERIFY(!result.outcome.assessments.front().keptAsItWas);
        const model::CompositeSurface& solved = result.outcome.surfaces.front();
        const double after = measureQuality(solved).developabilityMax;
        QVERIFY2(after <= before, qPrintable(QString::number(after)));
        QVERIFY2(result.outcome.assessments.front().summary.finalMaxConstraintResidual < 1e-7,
                 qPrintable(QString::number(
                     result.outcome.assessments.front().summary.finalMaxConstraintResidual)));
        const double moved = measureShapeChange(folded, solved).largestMove;
        QVERIFY2(moved < 1.0, qPrintable(QString::number(moved)));
        // The crease conditions sampled along the creases, for the Solver panel.
        QCOMPARE(result.outcome.assessments.front().creases.residualMax,
                 measureCreaseQuality(solved).residualMax);
    }

    void cancelMidSolveGivesCancelledResult() {
        SolverWorker worker;
        QSignalSpy progress(&worker, &SolverWorker::progress);
        QSignalSpy finished(&worker, &SolverWorker::finished);
        SolveRequest request;
        request.revision = 5;
        request.job.surfaces = {roughAnnulus()};
        request.job.iterations = 10000;
        worker.submit(request);
        QVERIFY(progress.wait(60000));
        QVERIFY(worker.isBusy());
        worker.cancel();
        QVERIFY(waitForResults(finished, 1));
        const SolveResult result = resultAt(finished, 0);
        QVERIFY(result.outcome.cancelled());
        QVERIFY(!result.outcome.ok);
        QCOMPARE(result.outcome.failure.error, JobError::Cancelled);
        QVERIFY(result.outcome.surfaces.empty());
        QCOMPARE(result.revision, quint64{5});
        QVERIFY(progress.count() < 10000);
    }

    void twoWorkersOnOneStructureAgree() {
        // Two threads analyse or share the same structure at once; the results are the same bits.
        AnalysisCache::instance().clear();
        const model::CompositeSurface surface = roughAnnulus(21);
        SolverWorker first;
        SolverWorker second;
        QSignalSpy firstDone(&first, &SolverWorker::finished);
        QSignalSpy secondDone(&second, &SolverWorker::finished);
        SolveRequest request;
        request.job.surfaces = {surface};
        request.job.iterations = 4;
        first.submit(request);
        second.submit(request);
        QVERIFY(waitForResults(firstDone, 1));
        QVERIFY(waitForResults(secondDone, 1));
        const SolveResult a = resultAt(firstDone, 0);
        const SolveResult b = resultAt(secondDone, 0);
        QVERIFY2(a.outcome.ok, qPrintable(why(a)));
        QVERIFY2(b.outcome.ok, qPrintable(why(b)));
        QVERIFY(a.outcome.surfaces.front() == b.outcome.surfaces.front());
    }

    void nanInTheInputIsRefused() {
        model::CompositeSurface surface = roughAnnulus();
        const model::VertexId id = surface.vertices().begin()->first;
        surface.moveVertex(id, {std::nan(""), 0.0, 0.0});
        SolverWorker worker;
        QSignalSpy finished(&worker, &SolverWorker::finished);
        SolveRequest request;
        request.revision = 9;
        request.job.surfaces = {surface};
        worker.submit(request);
        QVERIFY(waitForResults(finished, 1));
        const SolveResult result = resultAt(finished, 0);
        QVERIFY(!result.outcome.ok);
        QVERIFY(!result.outcome.cancelled());
        QVERIFY(result.outcome.surfaces.empty());
        QCOMPARE(result.outcome.failure.error, JobError::CannotSolve);
        QVERIFY2(result.outcome.failure.detail.find("not a finite number") != std::string::npos,
                 qPrintable(why(result)));

        // A NaN drag target is refused the same way.
        request.job.surfaces = {roughAnnulus()};
        request.job.kind = JobKind::VertexDrag;
        request.job.drag = 1;
        request.job.lengths = DragLengths::Stretch;
        request.job.pulled[0] = {{id, false, {0.0, std::nan(""), 0.0}}};
        worker.submit(request);
        QVERIFY(waitForResults(finished, 2));
        QVERIFY(!resultAt(finished, 1).outcome.ok);
        QVERIFY(resultAt(finished, 1).outcome.surfaces.empty());
    }
};

DEVSURF_REGISTER_TEST(TstSolverWorker);
#include "tst_worker.moc"
