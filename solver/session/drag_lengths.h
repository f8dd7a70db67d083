#pragma once

#include "solver/session/solve_session.h"

#include <atomic>
#include <cstddef>
#include <functional>
#include <memory>
#include <vector>

namespace devsurf::solver {

// How a vertex drag treats the lengths of the strips' control nets: the desktop application's
// Tools ▸ Lengths While Dragging, `devsurf-cli drag [--keep-lengths | --stretch]`.
//
// Automatic keeps lengths (the sheet bends) and, where the drag then fails (judgeDrag: it does
// not converge, folds over, collapses strips or its development overlaps itself), replays the same
// drag from its start letting the sheet stretch, and takes whichever of the two ends with fewer
// problems (keeping lengths on a tie). Measured with devsurf-cli drag (20 moves, then 20
// iterations keeping lengths or 10 stretching):
// - Keeping lengths folds curved creases where stretching pulls them straight or collapses
//   rulings: fig6 with a free corner lifted 75 mm folds 11° … 13° along its bowed crease
//   (1e-11; stretching: 10°, rulings at 0.07 of their length, a face folded over), and 66°
//   with the middle of its free edge lifted (stretching 38° along a straight crease); fig8 with
//   its bottom corners pinned and its middle lifted 85 mm folds 46° along curved creases
//   (2e-8; stretching 17.5° along straight ones). Without conditions, the annulus with its
//   outer rim pinned and an inner vertex lifted 100 mm ends at 5e-15 with rulings at 0.98 of
//   their length (stretching: 2.4, angle defects of 3.4 rad, rulings at 0.06).
// - Where the motion needs the sheet to stretch, keeping lengths fails and the replay
//   stretching is taken: fig8 with all four corners pinned (their distances are those of the
//   flat sheet) and its middle lifted 30 or 85 mm ends at 9e-4 and 1e-4 with face 7 folded
//   over and an overlapping development keeping lengths, at 1e-14 folded 14° … 41° along
//   straight creases stretching; the same turned by 30° afterwards ends with three problems
//   keeping lengths, with an overlapping development only stretching.
enum class DragLengths { Automatic, Keep, Stretch };

// The largest constraint residual at the end of a drag above which it counts as not converged
// (judgeDrag). A drag keeping lengths settles slowly where the net had to give a little (the
// lifted Fig. 8: 2e-8 after 20 iterations, 2e-5 when lifted in 5 moves); 1e-4 and more means
// it did not find a developable shape near the mouse.
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
};

// At most this many of a drag's moves are replayed (evenly chosen, the last always): a drag
// in the desktop application solves one move per mouse event it keeps up with, hundreds in a
// long drag.
inline constexpr std::size_t kReplayedMoves = 40;

// The indices of the moves replayed out of `count`, in order.
std::vector<std::size_t> replayedMoves(std::size_t count, std::size_t limit = kReplayedMoves);

struct ReplayedDrag {
    std::unique_ptr<SolveSession> session; // at the replay's end (its surface() the result)
    Summary settling;                      // of the iterations after the moves
    bool stopped = false;                  // a move or iteration stopped before a degenerate one
    int iterations = 0;                    // all it ran
};

// Replays a drag on `start` (the surface at the press) letting the sheet stretch: a fresh
// session pulled along `moves` (replayedMoves of them, one iteration each), then settle() and
// `after` iterations. Throws std::invalid_argument as SolveSession does. `cancel` is checked
// between iterations (the settling summary is then Cancelled); `perIteration` is called after
// each.
ReplayedDrag replayStretching(const model::CompositeSurface& start,
                              const std::vector<DragMove>& moves, int after,
                              const std::atomic<bool>* cancel = nullptr,
                              const std::function<void(const IterationStats&)>& perIteration = {});

} // namespace devsurf::solver
