#pragma once

// A drag as the Drag tool runs it through the solve job, for the solver tests.

#include "model/composite_surface.h"
#include "solver/session/solve_job.h"

#include <algorithm>

namespace devsurf::solver::testing {

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
