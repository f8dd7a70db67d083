// The command line and the desktop application's worker run the same solve job: for the same
// file and request, `devsurf-cli solve` and `drag` write the very surfaces the worker returns.
#include "cli_run.h"
#include "io/project_file.h"
#include "model/examples.h"
#include "solver/formulation/perturbation.h"
#include "solver/worker/solver_worker.h"
#include "test_registry.h"

#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

using namespace devsurf;

namespace {

// The worker's result for `request`, waiting for it (an empty outcome if none arrives).
solver::JobOutcome runOnWorker(solver::SolverWorker& worker, QSignalSpy& finished,
                               solver::SolveRequest request) {
    const int before = finished.count();
    worker.submit(std::move(request));
    while (finished.count() == before) {
        if (!finished.wait(120000)) {
            return {};
        }
    }
    return finished.last().at(0).value<solver::SolveResult>().outcome;
}

} // namespace

class TstCliWorker : public QObject {
    Q_OBJECT
    QTemporaryDir m_dir;
    QString path(const QString& name) const { return m_dir.filePath(name); }

private slots:
    void solveGivesTheWorkersBits() {
        // A rough annulus, as a designer's hand edit leaves it.
        model::Project project = model::makeExample("annulus");
        model::CompositeSurface& surface = project.surfaces.front();
        solver::perturbSurface(surface, 1e-3 * solver::surfaceDiameter(surface), 7u, {});
        const QString rough = path("rough.devsurf");
        io::saveProjectFile(project, rough);
        const QString solved = path("solved.devsurf");
        QCOMPARE(test::runCli({"solve", rough, "-o", solved}).exitCode, 0);

        solver::SolverWorker worker;
        QSignalSpy finished(&worker, &solver::SolverWorker::finished);
        solver::SolveRequest request;
        request.job.kind = solver::JobKind::Solve;
        request.job.surfaces = io::loadProjectFile(rough).surfaces;
        const solver::JobOutcome outcome = runOnWorker(worker, finished, request);
        QVERIFY(outcome.ok);
        QVERIFY(!(outcome.surfaces.front() == surface)); // it did solve
        QVERIFY(io::loadProjectFile(solved).surfaces.front() == outcome.surfaces.front());
    }

    void dragGivesTheWorkersBitsReplayIncluded() {
        // fig8 with its four corners pinned, its middle lifted 85 mm in 20 moves (Automatic:
        // keeping lengths fails and the drag is replayed stretching), then released.
        const QString fig8 = path("fig8.devsurf");
        QCOMPARE(test::runCli({"example", "fig8", "--as-built", "-o", fig8}).exitCode, 0);
        const QString lifted = path("fig8-lifted.devsurf");
        QCOMPARE(test::runCli({"drag", fig8, "--vertices", "5,6,9,10", "--by", "0,0,85", "--pin",
                               "0,3,12,15", "-o", lifted})
                     .exitCode,
                 0);

        model::CompositeSurface press = io::loadProjectFile(fig8).surfaces.front();
        for (model::VertexId v : {0u, 3u, 12u, 15u}) {
            press.setPinned(v, true);
        }
        solver::SolverWorker worker;
        QSignalSpy finished(&worker, &solver::SolverWorker::finished);
        solver::SolveRequest request;
        request.job.kind = solver::JobKind::VertexDrag;
        request.job.drag = 42;
        request.job.lengths = solver::DragLengths::Automatic;
        request.job.surfaces = {press};
        constexpr int kMoves = 20;
        solver::JobOutcome outcome;
        for (int k = 1; k <= kMoves + 1; ++k) {
            const double t = std::min(k, kMoves) / static_cast<double>(kMoves);
            std::vector<solver::VertexHandle>& handles = request.job.pulled[0];
            handles.clear();
            for (model::VertexId v : {5u, 6u, 9u, 10u}) {
                handles.push_back({v, false, press.position(v) + model::Vec3{0.0, 0.0, 85.0} * t});
            }
            request.job.settle = k > kMoves;
            outcome = runOnWorker(worker, finished, request);
            QVERIFY(outcome.ok);
            QCOMPARE(outcome.settled, k > kMoves);
        }
        const solver::SurfaceAssessment& assessment = outcome.assessments.front();
        QVERIFY(assessment.replay && assessment.replay->taken);
        QVERIFY(io::loadProjectFile(lifted).surfaces.front() == outcome.surfaces.front());
    }
};

DEVSURF_REGISTER_TEST(TstCliWorker);
#include "tst_cli_worker.moc"
