#pragma once

// Drags as the Drag tool runs them, through a session or the solve job, for the solver tests.

#include "model/composite_surface.h"
#include "model/development.h"
#include "model/examples.h"
#include "model/sampled_mesh.h"
#include "model/sheet_domain.h"
#include "solver/session/solve_job.h"
#include "solver/session/solve_session.h"

#include <algorithm>
#include <cmath>
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

// A drag of `moves` evenly spaced moves through the solve job, as the Drag tool runs one, then
// released where the last left it: `aim(request, t)` adds the targets t = k / moves of the way.
// The first outcome that failed, or the release's.
template <typename Aim>
JobOutcome dragThroughJob(const model::CompositeSurface& start, int moves, Aim aim) {
    SolveJob job;
    JobOutcome outcome;
    for (int k = 1; k <= moves + 1; ++k) {
        JobRequest request;
        request.kind = JobKind::VertexDrag;
        request.drag = 1;
        request.untimedPartway = true; // the same search however fast the machine
        request.settle = k > moves;
        request.surfaces = {start};
        aim(request, std::min(k, moves) / static_cast<double>(moves));
        outcome = job.run(request);
        if (!outcome.ok) {
            break;
        }
    }
    return outcome;
}

// `vertex` of `start` pulled to `target` in `moves` moves through the solve job.
inline JobOutcome dragInJob(const model::CompositeSurface& start, model::VertexId vertex,
                            const model::Vec3& target, int moves) {
    const model::Vec3 from = start.position(vertex);
    return dragThroughJob(start, moves, [&](JobRequest& request, double t) {
        request.pulled[0].push_back({vertex, false, from + (target - from) * t});
    });
}

// fig13's top rim point (0, 150, 0), above its pinned crease middle: the vertex its drags pull.
inline model::VertexId fig13Top(const model::CompositeSurface& fig13) {
    for (const auto& [id, p] : fig13.vertices()) {
        if (std::abs(p.x) < 1e-9 && std::abs(p.y - 150.0) < 1e-9) {
            return id;
        }
    }
    return model::kInvalidId;
}

// The flat `sheet` example holding its sheet on a 300 × 300 mm rectangle, its two bottom
// corners pinned; `middle` its vertices of the two middle rows; `held` false if it could not
// hold its sheet.
struct HeldSquare {
    model::CompositeSurface surface;
    std::vector<model::VertexId> middle;
    bool held = false;
};

inline HeldSquare heldSquare() {
    HeldSquare square;
    model::CompositeSurface& s = square.surface;
    s = model::makeExample("sheet").surfaces.front();
    square.held = !model::keepDevelopment(s).has_value();
    model::SheetDomain rectangle;
    rectangle.shape = model::SheetShape::Rectangle;
    rectangle.width = 300.0;
    rectangle.height = 300.0;
    s.setSheetDomain(model::placeDomain(
        rectangle, model::sampleSurface(s, model::kDevelopmentSamplesPerInterval),
        s.development()));
    for (const auto& [id, p] : s.vertices()) {
        if (std::abs(p.y) < 1e-9 && (std::abs(p.x) < 1e-9 || std::abs(p.x - 300.0) < 1e-9)) {
            s.setPinned(id, true);
        }
        if (std::abs(p.y - 100.0) < 1e-9 || std::abs(p.y - 200.0) < 1e-9) {
            square.middle.push_back(id);
        }
    }
    return square;
}

} // namespace devsurf::solver::testing
