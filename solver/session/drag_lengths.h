#pragma once

#include "solver/session/solve_session.h"

#include <atomic>
#include <cstddef>
#include <functional>
#include <memory>
#include <vector>

namespace devsurf::solver {

// How a vertex drag treats the lengths of the strips' control nets (Tools ▸ Lengths While
// Dragging, `devsurf-cli drag [--keep-lengths | --stretch]`): Keep bends the sheet, Stretch lets
// it stretch, Automatic keeps lengths and, where that fails (judgeDrag), replays the drag from
// its press stretching and takes the result with fewer problems (keeping lengths on a tie).
// Measurements: docs/tuning.md, "Lengths while dragging".
enum class DragLengths { Automatic, Keep, Stretch };

// The largest constraint residual at the end of a drag above which it counts as not converged
// (judgeDrag): 1e-4 and more means it found no developable shape near the mouse.
inline constexpr double kDragConvergedResidual = 1e-4;

// A drag's result whose rulings shrink below this fraction of their length at the press, or
// whose curves slow below kDragSlowestSpeed of their mean speed there, has collapsed strips
// (the limits of the solver's rough-start targets).
inline constexpr double kDragShortestRuling = 0.25;
inline constexpr double kDragSlowestSpeed = 0.1;

// What went wrong at the end of a drag, from the geometry of its result.
struct DragOutcome {
    bool stopped = false;   // stopped at the last valid state before a degenerate iterate
    double residual = 0.0;  // largest constraint residual of the last iteration
    int foldOverPlaces = 0; // solver::foldOvers
    std::vector<model::FaceId> overlapping; // model::selfOverlappingPatches
    // measureShapeChange from the press to the result.
    double shortestRuling = 1.0;
    double slowestSpeed = 1.0;
    bool measurable = true; // false: the result is too degenerate to sample
    bool collapsed() const {
        return shortestRuling < kDragShortestRuling || slowestSpeed < kDragSlowestSpeed;
    }
    // How many of: stopped, not converged (residual > kDragConvergedResidual), folded over,
    // overlapping development, collapsed strips, not measurable.
    int problems() const;
};

// `start`: the surface at the press (the same combinatorics as `result`).
DragOutcome judgeDrag(const model::CompositeSurface& start, const model::CompositeSurface& result,
                      double residual, bool stopped);

// Whether an Automatic drag takes its replay stretching (`stretched`) over the drag keeping
// lengths (`kept`): fewer problems.
bool prefersStretched(const DragOutcome& kept, const DragOutcome& stretched);

// The targets of a drag's handles after one of its moves.
struct DragMove {
    std::vector<VertexHandle> vertices;
    std::vector<ControlPointHandle> controlPoints;
    std::vector<SheetHandle> sheet; // places in the held sheet (the development view's drag)
};

// At most this many of a drag's moves are replayed (evenly chosen, the last always): a long drag
// in the desktop application solves hundreds.
inline constexpr std::size_t kReplayedMoves = 40;

// The indices of the moves replayed out of `count`, in order.
std::vector<std::size_t> replayedMoves(std::size_t count, std::size_t limit = kReplayedMoves);

struct ReplayedDrag {
    std::unique_ptr<SolveSession> session; // at the replay's end (its surface() the result)
    Summary settling;                      // of the iterations after the moves
    bool stopped = false;                  // a move or iteration stopped before a degenerate one
    int iterations = 0;                    // all it ran
};

// Replays a drag on `start` (the surface at the press) with `options`: a fresh session pulled
// along `moves` (replayedMoves of them, one iteration each), then settle() and `after`
// iterations. Throws std::invalid_argument as SolveSession does. `cancel` is checked between
// iterations (the settling summary is then Cancelled); `perIteration` is called after each.
ReplayedDrag replayDrag(const model::CompositeSurface& start, const std::vector<DragMove>& moves,
                        const SessionOptions& options, int after,
                        const std::atomic<bool>* cancel = nullptr,
                        const std::function<void(const IterationStats&)>& perIteration = {});

// replayDrag letting the sheet stretch (SessionOptions{}).
ReplayedDrag replayStretching(const model::CompositeSurface& start,
                              const std::vector<DragMove>& moves, int after,
                              const std::atomic<bool>* cancel = nullptr,
                              const std::function<void(const IterationStats&)>& perIteration = {});

// A drag keeping lengths whose release ended with problems, to be settled once more (its
// settle() called; the caller steps it as long as the release): a fresh session from `last`, the
// drag's state after its last move, pulled to the release's `handles` and `points`, the
// keep-lengths energy fading only after iterations whose residual did not rise (on a fine model
// the release can alternate as it fades, docs/tuning.md "Settled again"), and vertex
// developability imposed at every star where `press` had them all closed (a fresh session
// imposes it only where it holds at its start). It gives up where hopeless
// (SolveSession::gaveUp). Throws as SolveSession's constructor does.
std::unique_ptr<SolveSession> secondSettling(const model::CompositeSurface& press,
                                             const model::CompositeSurface& last,
                                             const std::vector<VertexHandle>& handles,
                                             const std::vector<ControlPointHandle>& points,
                                             SessionOptions options);

} // namespace devsurf::solver
