#pragma once

// Drags as the Drag tool runs them, through a session or the solve job, for the solver tests.

#include "model/composite_surface.h"
#include "solver/session/solve_job.h"
#include "solver/session/solve_session.h"

#include <algorithm>
#include <vector>

namespace devsurf::solver::testing {

// A vertex drag as the solve job runs one (keepLengthsSessionOptions): `pulled` lifted by `lift`
// in 20 moves of one iteration each, then the iterations after the release.
struct Dragged {
    model::CompositeSurface surface;
    Summary summary;
    double largestGap = 0.0; // of a pulled vertex from its final target
    double smallestRise = 0.0;
};

inline Dragged dragUp(const model::CompositeSurface& start,
                      const std::vector<model::VertexId>& pulled, double lift) {
    std::vector<VertexHandle> handles;
    for (model::VertexId v : pulled) {
        handles.push_back({v, false, start.position(v)});
    }
    SolveSession session(start, handles, keepLengthsSessionOptions());
    Dragged result;
    const model::Vec3 up(0, 0, lift);
    for (int k = 1; k <= 20; ++k) {
        for (model::VertexId v : pulled) {
            session.setHandleTarget(v, start.position(v) + up * (k / 20.0));
        }
        result.summary = session.step(1);
    }
    session.settle();
    result.summary = session.step(iterationsAfterDrag(true, start.keepsDevelopment()));
    result.surface = session.surface();
    result.smallestRise = lift;
    for (model::VertexId v : pulled) {
        const model::Vec3 target = start.position(v) + up;
        result.largestGap =
            std::max(result.largestGap, model::distance(result.surface.position(v), target));
        result.smallestRise =
            std::min(result.smallestRise, result.surface.position(v).z - start.position(v).z);
    }
    return result;
}

// `vertex` of `start` pulled to `target` in `moves` evenly spaced moves through the solve job,
// as the Drag tool does, then released there; the first outcome that failed, or the release's.
inline JobOutcome dragInJob(const model::CompositeSurface& start, model::VertexId vertex,
                            const model::Vec3& target, int moves) {
    SolveJob job;
    JobOutcome outcome;
    for (int k = 1; k <= moves + 1; ++k) {
        JobRequest request;
        request.kind = JobKind::VertexDrag;
        request.drag = 1;
        request.settle = k > moves;
        request.surfaces = {start};
        const double t = std::min(k, moves) / static_cast<double>(moves);
        request.pulled[0].push_back(
            {vertex, false, start.position(vertex) + (target - start.position(vertex)) * t});
        outcome = job.run(request);
        if (!outcome.ok) {
            break;
        }
    }
    return outcome;
}

} // namespace devsurf::solver::testing
