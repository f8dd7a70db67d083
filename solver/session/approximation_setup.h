#pragma once

#include "model/composite_surface.h"
#include "model/problem.h"
#include "model/reference/thinning.h"
#include "model/vec3.h"
#include "solver/session/solve_job.h"

#include <cstddef>
#include <functional>
#include <optional>
#include <vector>

namespace devsurf::solver {

// The setup of an approximation (§4.2) that `devsurf-cli approximate` and Tools ▸ Approximate
// Reference Shape… share, so that both pull the same strips towards the same points: the
// thinning radius, the thinning, the K-means flat strips, the points per surface and the
// job's request. The steps are separate functions so that the command line can say what it
// found between them; prepareApproximation() runs them all.

// The thinning radius when none is given, in % of the target's bounding-box diagonal: a strip
// of a few spline intervals is then pulled by tens to hundreds of points.
inline constexpr double kDefaultRhoPercent = 2.0;

// The falloff of the pull with distance (ApproximationTarget::falloff), in thinning radii.
inline constexpr double kFalloffRhos = 3.0;

// The default thinning radius of a target with this bounding-box diagonal: kDefaultRhoPercent
// of it, or more where the target is so sparse that a ball of that radius holds too few points
// to fit a plane to (model::reference::defaultThinningRadius).
double defaultApproximationRadius(const std::vector<model::Vec3>& points, double diagonal);

// The target thinned with radius ρ (rho ≤ 0: the default above).
struct ThinnedTarget {
    double diagonal = 0.0; // of the whole target's bounding box
    double rho = 0.0;
    model::reference::ThinningResult thinned;
};
ThinnedTarget thinTarget(const std::vector<model::Vec3>& points, double rho,
                         const model::reference::ThinningProgress& progress = {});

// Whether `thinned` keeps enough points for `strips` strips (3 each).
bool enoughPointsFor(const ThinnedTarget& target, int strips);

// The new strips' groups are bands this many times as long as wide (clusterPoints with the
// thinned normals): a developable strip follows a doubly curved shape closely only across a
// narrow width. Longer bands come nearer the shape but overhang it more (docs/tuning.md,
// "Bands bent into cylinders").
inline constexpr double kStripBandAspect = 2.0;

// The margin of a new strip's cylinder start (ApproximationTarget::dampedStart) around its
// points, as a fraction of its extent: the damped pull barely grows a strip, so the margin
// closes the gaps between strips; where it overhangs the shape, the trim below cuts it back.
inline constexpr double kCylinderStartMargin = 0.07;

// A new strip's side is trimmed once pulled while it stands off the shape by more than this
// many thinning radii on average (ApproximationTarget::trimTolerance; docs/tuning.md, "Strips
// trimmed where they overhang").
inline constexpr double kTrimToleranceRhos = 0.45;

// `count` flat strips with `intervals` spline intervals (cubic, degree-2 rulings space), one on
// each band of the thinned points (model::reference::clusterPoints with kStripBandAspect,
// initialStrip with the thinned normals), named "strip N" from N = firstNumber. A cluster on a line
// gets no strip, so fewer may come back (none if every point lies on one line). Requires
// enoughPointsFor(target, count).
std::vector<model::CompositeSurface> initialStrips(const ThinnedTarget& target, int count,
                                                   int intervals, int firstNumber = 1);

// Where the thinned target is one patch over its plane (model::reference::isPatchOverPlane),
// `count` ≥ 2 strips side by side as one surface over it (initialStripSheet with the thinned
// normals, `intervals` intervals, over the rectangle of `points`, the whole target, without a
// margin), named "strips N" with N = firstNumber: watertight by construction. None for any
// other target.
std::optional<model::CompositeSurface> initialStripSheet(const ThinnedTarget& target,
                                                         const std::vector<model::Vec3>& points,
                                                         int count, int intervals,
                                                         int firstNumber = 1);

// Where the thinned target closes around an axis (model::reference::tubeAxis), `count` ≥ 2
// rings one after another around it as one surface (initialStripRings with the thinned normals,
// `intervals` intervals per quarter), named "rings N" with N = firstNumber: watertight but for
// its two ends. None for any other target.
// `points` is the whole target, whose extent along the axis the rings span.
std::optional<model::CompositeSurface> initialStripRings(const ThinnedTarget& target,
                                                         const std::vector<model::Vec3>& points,
                                                         int count, int intervals,
                                                         int firstNumber = 1);

// Every thinned point goes to the surface nearest to it (its nearest dense sample).
struct SurfaceTargets {
    std::vector<std::vector<model::Vec3>> points; // per surface
    std::vector<std::vector<model::Vec3>> normals;
};
SurfaceTargets assignToSurfaces(const std::vector<model::CompositeSurface>& surfaces,
                                const model::reference::ThinningResult& thinned);

// A surface pulled by fewer points stays as it is: too far from the target.
inline constexpr std::size_t kFewestTargetPoints = 3;

// The Approximate job for `surfaces` pulled towards their points (unset iterations: the job's
// default, kApproximationIterations). `newStrips`: the surfaces are strips laid by
// initialStrips, each given the cylinder over its points as its damped start
// (ApproximationTarget::dampedStart).
JobRequest approximationRequest(const std::vector<model::CompositeSurface>& surfaces,
                                const SurfaceTargets& targets, double rho,
                                std::optional<int> iterations, bool newStrips = false);

// Everything at once, for a front end that runs it off its GUI thread.
struct ApproximationOptions {
    int strips = 4;    // new flat strips, when `start` is empty
    int intervals = 4; // spline intervals per new strip
    double rho = 0.0;  // thinning radius; ≤ 0: defaultApproximationRadius
    std::optional<int> iterations;
    // New strips over a target that is one patch are laid side by side as one surface
    // (initialStripSheet), over one that closes around an axis as rings one after another
    // (initialStripRings); false: separate strips over its patches always.
    bool oneSurface = true;
};

struct ApproximationSetup {
    enum class Error {
        None,
        Cancelled,
        TooFewPoints, // thinning kept fewer than 3 points per strip
        Collinear,    // every cluster lies on a line: no strip
        NothingNear,  // no surface has kFewestTargetPoints points nearest to it
    };
    Error error = Error::None;
    ThinnedTarget target;
    std::vector<model::CompositeSurface> surfaces; // the start: `start` or the new strips
    bool newStrips = false;
    // The new strips were laid as one surface (ApproximationOptions::oneSurface): `surfaces`
    // holds that one surface, new (newStrips) but pulled as a design's surfaces are, without
    // the cylinder start and trim of single strips. As rings around the target's axis, or
    // side by side over its patch.
    int stripsInOneSurface = 0;
    bool stripsAsRings = false;
    SurfaceTargets targets;
    JobRequest request;
    double milliseconds = 0.0; // the setup's time
};

// Called now and then with the fraction done (0 … 1); returning false cancels.
using SetupProgress = std::function<bool(double fraction)>;

// Thins `points`, starts from `start` (the design's surfaces) or, if it is empty, from
// options.strips new flat strips numbered from firstNumber, assigns the points and builds the
// request. `progress` is called during the thinning and between the steps.
ApproximationSetup prepareApproximation(const std::vector<model::Vec3>& points,
                                        const std::vector<model::CompositeSurface>& start,
                                        const ApproximationOptions& options,
                                        const SetupProgress& progress = {}, int firstNumber = 1);

} // namespace devsurf::solver
