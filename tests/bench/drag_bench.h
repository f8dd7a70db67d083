#pragma once

#include "solver/session/solve_session.h"

#include <functional>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

namespace devsurf::bench {

// The interactive benchmark (`devsurf-bench --drag`): a scripted drag through the solver worker
// with the coalescing of the desktop application, results applied to a Document as the drag's
// one merging undo command, and the event loop of the thread that owns the document watched for
// stalls; then the same watch during a Solve of the largest model.
struct DragBenchOptions {
    int moves = 200;
    double moveIntervalMs = 8.0; // mouse events at 125 Hz
    double liftFraction = 0.1;   // the whole drag lifts the vertex by this times the diameter
    // Unset: as the desktop application's default (solver::DragLengths::Automatic: keeping
    // lengths, replayed stretching where that fails).
    std::optional<bool> keepLengths;
    int afterIterations = 0; // after the release; 0: as the application (20 keeping lengths, 10)
    int solveIterations = 10;
    // The pointer rests on the vertex before the press, as in the desktop application: the drag
    // is prepared first (solver::JobRequest::prepare) and its moves start once that is done.
    // False: the first move starts the drag cold (what a press without a rest costs).
    bool prepare = true;
    // The dragged vertex's place in the sheet moves instead (the development view's drag), on
    // a surface that holds its sheet: by liftFraction times the diameter, perpendicular to its
    // direction from the development's centroid (along an annulus's rim).
    bool inSheet = false;
    // The drags to run by name (fig12-annulus, annulus-14, fig12-annulus-held,
    // annulus-14-held, and large-annulus for the Solve's stall); empty: all.
    std::vector<std::string> models;
    std::function<void(const std::string&)> log;
};

struct DragBenchRow {
    std::string model;
    int variables = 0;
    int moves = 0;
    int solved = 0;             // requests the worker ran (the others were coalesced away)
    int applied = 0;            // results pushed to the document during the moves
    double prepareMs = -1.0;    // the drag prepared while the pointer rests (-1: not prepared)
    double firstResultMs = 0.0; // first move to its result applied (includes the analysis
                                // unless the drag was prepared)
    double medianMs = 0.0;      // move event to a result covering it applied to the document
    double p95Ms = 0.0;
    double appliedPerSecond = 0.0;
    double largestStallMs = 0.0; // largest gap between ticks of a 1 ms timer
    double releaseMs = 0.0;      // release to the last iterations applied
    double residualAfter = 0.0;  // largest constraint residual after the release iterations
    int foldOvers = 0;           // places where the result folds over onto itself (foldOvers)
    // Patches at which the result's development overlaps itself (SolveResult::selfOverlaps).
    int overlappingPatches = 0;
    // The release's result is the drag replayed stretching (SolveResult::stretched).
    bool replayedStretching = false;
    // The release ended broken and was taken back to the press (SurfaceAssessment::takenBack);
    // the residual, fold-overs and overlaps above are then those of the refused result.
    bool takenBack = false;
    // Of a release taken back: the share of the moves the kept result follows (0: back to the
    // press; SurfaceAssessment::followed), how far its dragged vertex lags behind the mouse
    // its largest constraint residual and the patches where its development overlaps itself.
    double followed = 0.0;
    double heldBackMm = 0.0;
    double keptResidual = 0.0;
    int keptOverlappingPatches = 0;
    std::string error; // empty unless the drag failed
};

struct SolveStallRow {
    std::string model;
    int variables = 0;
    int iterations = 0;
    double solveMs = 0.0;        // submit to the result applied
    double largestStallMs = 0.0; // largest gap between ticks of a 1 ms timer
    std::string error;
};

struct DragBenchReport {
    std::vector<DragBenchRow> drags;
    SolveStallRow solve;
};

// Runs on the calling thread's event loop (a QCoreApplication is made if there is none).
DragBenchReport runDragBench(const DragBenchOptions& options);
// The drag of runDragBench on one surface (as given: one that keeps its development is dragged
// holding its sheet), through the worker on the calling thread's event loop.
DragBenchRow runSurfaceDrag(const std::string& name, const model::CompositeSurface& surface,
                            const DragBenchOptions& options);
void printDragBench(const DragBenchReport& report, bool json, std::ostream& out);

} // namespace devsurf::bench
