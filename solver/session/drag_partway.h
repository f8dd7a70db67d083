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
#include <functional>
#include <memory>
#include <optional>
#include <vector>

namespace devsurf::solver {

// A surface as a drag left it after `moves` of its moves.
struct Reached {
    std::size_t moves = 0;
    model::CompositeSurface surface;
    // The largest constraint residual of the move's iteration that reached it.
    double residual = 0.0;
};

// Keeps `state` among the states a drag passed through: those whose move count is a multiple
// of `stride` (doubled, thinning them, whenever more than fit are kept) and the latest, so
// that they stay evenly spread over the whole drag.
void keepReached(std::vector<Reached>& reached, std::size_t& stride, Reached state);

// The states a drag passed through, kept as keepReached keeps them, except that the latest is
// copied only when the release asks for it (keepLatest): most moves' states are dropped again
// by the next move, and copying each cost a large model's moves milliseconds.
class PassedThrough {
public:
    // After a move: `surface` as the drag left it after `moves` moves, `residual` the largest
    // constraint residual of that move's iteration. A state copied for a count stays; of a
    // count not copied, the latest move's state is the one keepLatest keeps.
    void moved(std::size_t moves, const model::CompositeSurface& surface, double residual);
    // Keeps the latest state if moved() did not: `surface` must be as the last move left it.
    void keepLatest(const model::CompositeSurface& surface);
    const std::vector<Reached>& states() const { return m_states; }
    void clear();

private:
    std::vector<Reached> m_states;
    std::size_t m_stride = 1;
    bool m_latestPending = false; // the latest move's state, not yet copied
    std::size_t m_latestMoves = 0;
    double m_latestResidual = 0.0;
};

// Whether the search fits its budget for a surface whose release took `releaseStep` to settle
// (two settlings of a state passed through, each as long as that several times).
bool partwayFits(std::chrono::steady_clock::duration releaseStep);

// How followPartway looks for the state to release at.
enum class PartwaySearch {
    // Where partwayFits: a bisection over the states passed through, each settled several
    // times as long as the release, within a time budget.
    Thorough,
    // For a model too large for that: a bisection of fewer probes, each settled as long as the
    // release with the pulls soft, over the states before the moves' residual jumped.
    Brief,
    // Thorough without the time budget (JobRequest::untimedPartway).
    Untimed,
};

struct Partway {
    std::unique_ptr<SolveSession> session; // its surface() is the result
    SurfaceAssessment assessment;          // followed: the share of the moves it follows
};

// The latest state a drag passed through (a bisection over `reached`, within a budget) that,
// released there and settled with `options` as the release is (`after` iterations, several
// times over), does not end broken and is as developable as the press (`atPress`, its
// assessment): the dragged points (vertices, control points, places in the held sheet) then
// lag behind the release's targets (`release`) instead of the whole drag being taken back.
// Nothing when no state tried ends well.
std::optional<Partway>
followPartway(const model::CompositeSurface& press, const SurfaceAssessment& atPress,
              const std::vector<Reached>& reached, const std::vector<DragMove>& moves,
              const SessionOptions& options, int after, const DragMove& release,
              const std::atomic<bool>* cancel, PartwaySearch search = PartwaySearch::Thorough,
              const std::function<void(const IterationStats&)>& onIteration = {});

// The most iterations followPartway runs (for progress): its probes times their settling.
int partwayIterationLimit(PartwaySearch search, int after);

} // namespace devsurf::solver
