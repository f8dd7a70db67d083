#include "model/examples.h"
#include "solver/core/analysis_cache.h"
#include "solver/formulation/perturbation.h"
#include "solver/quality/crease_quality.h"
#include "solver/quality/quality_measures.h"
#include "solver/quality/shape_change.h"
#include "solver/session/crease_drag.h"
#include "solver/worker/solver_worker.h"
#include "worker_test_support.h"

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

using namespace devsurf::test;

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
        // The lifted Fig. 8 folded along curved creases by a drag that kept lengths, 10
        // iterations after the release (det about 1.3e-4, not nearly valid): a fresh Solve's
        // fairness pulls it towards flat through a crumpled shape: the worker returns it as it
        // was and says so. (16 iterations after the release, det 3e-6, is nearly valid since
        // kNearlyValidResidual is 1e-4, and Solve improves it a little: 2.9e-6.)
        const model::CompositeSurface folded = test::liftedFig8(10);
        const double before = measureQuality(folded).developabilityMax;
        QVERIFY2(before > kNearlyValidResidual && before < 1e-3,
                 qPrintable(QString::number(before)));

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
        const model::CompositeSurface folded = test::liftedFig8(20);
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
        QVERIFY2(
            result.outcome.failure.problem &&
                (result.outcome.failure.problem->code == model::ProblemCode::PositionNotFinite ||
                 result.outcome.failure.problem->code == model::ProblemCode::ControlPointNotFinite),
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
