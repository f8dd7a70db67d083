#pragma once

// fig8 folded along its curved creases as the README shows it: its middle vertices lifted
// 85 mm in 20 moves keeping lengths (its bottom corners pinned), then `settle` iterations
// after the release.

#include "model/examples.h"
#include "solver/session/solve_session.h"

#include <vector>

namespace devsurf::test {

inline model::CompositeSurface liftedFig8(int settle) {
    const model::CompositeSurface flat = model::makeExample("fig8").surfaces.front();
    const std::vector<model::VertexId> middle{5, 6, 9, 10};
    std::vector<solver::VertexHandle> pulled;
    for (model::VertexId v : middle) {
        pulled.push_back({v, false, flat.position(v)});
    }
    solver::SolveSession drag(flat, pulled, solver::keepLengthsSessionOptions());
    for (int k = 1; k <= 20; ++k) {
        for (model::VertexId v : middle) {
            drag.setHandleTarget(v, flat.position(v) + model::Vec3{0.0, 0.0, 85.0 * k / 20.0});
        }
        drag.step(1);
    }
    drag.settle();
    drag.step(settle);
    return drag.surface();
}

} // namespace devsurf::test
