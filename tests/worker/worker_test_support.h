#pragma once

// What the solver-worker tests share: a rough annulus, waiting for results, one Solve.
#include "model/examples.h"
#include "solver/formulation/perturbation.h"
#include "solver/worker/solver_worker.h"

#include <QSignalSpy>
#include <QString>

#include <cmath>

namespace devsurf::test {

using namespace devsurf::solver;

inline model::CompositeSurface roughAnnulus(unsigned seed = 5) {
    model::CompositeSurface surface = model::makeExample("annulus").surfaces.front();
    perturbSurface(surface, 1e-3 * surfaceDiameter(surface), seed, {});
    return surface;
}

inline SolveResult resultAt(const QSignalSpy& spy, int index) {
    return spy.at(index).at(0).value<SolveResult>();
}

// Waits until a result arrives (or the spy's wait times out, which fails the test).
inline bool waitForResults(QSignalSpy& spy, int count) {
    while (spy.count() < count) {
        if (!spy.wait(60000)) {
            return false;
        }
    }
    return true;
}

// One Solve of `surface` (`iterations` at most) on a worker of its own; a result with ok false
// and an error if none arrives.
inline SolveResult solveOnce(const model::CompositeSurface& surface, int iterations) {
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
inline QString why(const SolveResult& result) {
    return QStringLiteral("error %1: %2")
        .arg(static_cast<int>(result.outcome.failure.error))
        .arg(QString::fromStdString(result.outcome.failure.detail));
}

inline bool allFinite(const model::CompositeSurface& surface) {
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

} // namespace devsurf::test
