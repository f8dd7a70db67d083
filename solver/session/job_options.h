#pragma once

// The recipe of a solve job's request: which session options each of its surfaces is solved
// with (keeping lengths, a crease drag's energies, an approximation's pull, a Solve's stop and
// fixed vertices).

#include "solver/session/solve_job.h"
#include "solver/session/solve_session.h"

namespace devsurf::solver {

// A vertex drag or rotation that keeps lengths (Automatic or Keep).
bool keepsLengths(const JobRequest& request);

// The entry of `map` for surface `key`, or an empty one.
template <typename Map> typename Map::mapped_type entryOf(const Map& map, int key) {
    const auto it = map.find(key);
    return it == map.end() ? typename Map::mapped_type{} : it->second;
}

// The session options of surface `surface` of `request`; `damped`: an approximation's damped
// recipe (kDampedApproximationWeightScale).
SessionOptions optionsFor(const JobRequest& request, int surface, bool damped = false);

} // namespace devsurf::solver
