#pragma once

// A drag whose release would end broken follows part of the way instead (SolveJob::run): the
// states the drag passed through are kept, and the latest that settles developable is found.

#include "model/composite_surface.h"
#include "solver/session/drag_lengths.h"
#include "solver/session/solve_job.h"
#include "solver/session/solve_session.h"

#include <atomic>
#include <chrono>
#include <cstddef>
#include <memory>
#include <optional>
#include <vector>

namespace devsurf::solver {

// A surface as a drag left it after `moves` of its moves.
struct Reached {
    std::size_t moves = 0;
    model::CompositeSurface surface;
};

// Keeps `state` and thins the kept ones to every other when there are too many (evenly spread
// over the drag; the latest always).
void keepReached(std::vector<Reached>& reached, Reached state);

// Whether the search fits its budget for a surface whose release took `releaseStep` to settle
// (two settlings of a state passed through, each as long as that several times).
bool partwayFits(std::chrono::steady_clock::duration releaseStep);

struct Partway {
    std::unique_ptr<SolveSession> session; // its surface() is the result
    SurfaceAssessment assessment;          // followed: the share of the moves it follows
};

// The latest state a drag passed through (a bisection over `reached`, within a budget) that,
// released there and settled with `options` as the release is (`after` iterations, several
// times over), does not end broken and is as developable as the press (`atPress`, its
// assessment): the dragged points then lag behind the release's targets (`handles`,
// `points`) instead of the whole drag being taken back. Nothing when no state tried ends well.
std::optional<Partway>
followPartway(const model::CompositeSurface& press, const SurfaceAssessment& atPress,
              const std::vector<Reached>& reached, const std::vector<DragMove>& moves,
              const SessionOptions& options, int after, const std::vector<VertexHandle>& handles,
              const std::vector<ControlPointHandle>& points, const std::atomic<bool>* cancel);

} // namespace devsurf::solver
