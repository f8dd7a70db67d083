#pragma once

// Joining surfaces into one composite (§4.2, "Composite"), as the solve job's JobKind::Join:
// the surfaces side by side in one (model::placeSideBySide); per two of its parts the boundary
// edges that face each other, two curves or two rulings (model::nearestBoundaryCurves), paired
// by the linearised "on the other's tangent line" condition (JobRequest::curvePairs) and pulled
// towards the reference shape at the same time where the request gives one; then welded
// (model::weldEdges), and the result pulled towards the reference once more as one surface (an
// Approximate job), or solved where there is none. Tools ▸ Join Surfaces and `devsurf-cli
// approximate --join` run it.

#include "model/composite_surface.h"
#include "model/reference_shape.h"
#include "solver/session/approximation_setup.h"
#include "solver/session/solve_job.h"

#include <atomic>
#include <optional>
#include <vector>

namespace devsurf::solver {

// The points of every reference shape thinned as an approximation thins them (thinTarget with
// the default radius): what a join is pulled towards. None when there are no shapes.
std::optional<ThinnedTarget>
thinReferenceShapes(const std::vector<model::ReferenceShape>& shapes,
                    const model::reference::ThinningProgress& progress = {});

// Facing edges are paired when their separation is at most this fraction of their length.
inline constexpr double kJoinReach = 0.2;

struct JoinPlan {
    model::CompositeSurface surface; // the surfaces of `joined`, side by side
    std::vector<CurvePair> pairs;    // nearest first; each edge in one pair at most
    std::vector<double> separations; // per pair (mm), before the pairing
    std::vector<int> joined;         // the surfaces in a pair, ascending indices into the input
};
// Requires at least one surface. A surface none of whose edges is in a pair is left out of the
// joined surface (none in a pair: `surface` is empty, `pairs` too).
JoinPlan planJoin(const std::vector<model::CompositeSurface>& surfaces);

struct JoinedSurface {
    model::CompositeSurface surface;
    int welded = 0;                      // pairs welded into shared edges
    double largestGap = 0.0;             // over the welded pairs (model::Weld::gap, mm)
    std::vector<model::Problem> refused; // why the other pairs were not
};
// Welds every pair of `surface` (in order) that model::weldEdges accepts.
JoinedSurface weldPairs(const model::CompositeSurface& surface,
                        const std::vector<CurvePair>& pairs);

// The Join job (SolveJob::run with JobKind::Join): needs at least two surfaces in the request.
// Fewer, or none facing another: ok, the surfaces unchanged and JoinReport::separations empty.
// Both steps, the pairing and the last one, run request.iterations (unset:
// kApproximationIterations); a step pulls towards joinTarget where at least kFewestTargetPoints
// of its points lie nearest the surface, else it is a Solve. The outcome's assessment is the
// last step's. Cancel and failures as any job.
JobOutcome runJoinJob(SolveJob& job, const JobRequest& request, const std::atomic<bool>* cancel,
                      const JobProgressFn& progress);

} // namespace devsurf::solver
