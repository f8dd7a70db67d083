#include "solver/session/approximation_setup.h"

#include "model/model_error.h"
#include "model/reference/bounding_box.h"
#include "model/reference/initial_strip.h"
#include "model/reference/point_index.h"
#include "model/reference/strip_rings.h"
#include "model/reference/strip_sheet.h"
#include "model/reference/strip_trim.h"
#include "model/reference/surface_samples.h"
#include "model/strip_joining.h"

#include <algorithm>
#include <chrono>
#include <map>
#include <memory>
#include <set>
#include <stdexcept>
#include <string>

namespace devsurf::solver {

double defaultApproximationRadius(const std::vector<model::Vec3>& points, double diagonal) {
    return std::max(kDefaultRhoPercent / 100.0 * diagonal,
                    model::reference::defaultThinningRadius(points));
}

ThinnedTarget thinTarget(const std::vector<model::Vec3>& points, double rho,
                         const model::reference::ThinningProgress& progress) {
    ThinnedTarget target;
    target.diagonal = model::reference::boundingBoxDiagonal(points);
    target.rho = rho > 0.0 ? rho : defaultApproximationRadius(points, target.diagonal);
    target.thinned = model::reference::thinReference(points, target.rho, progress);
    return target;
}

bool enoughPointsFor(const ThinnedTarget& target, int strips) {
    return target.thinned.points.size() >= 3 * static_cast<std::size_t>(std::max(strips, 1));
}

std::vector<model::CompositeSurface> initialStrips(const ThinnedTarget& target, int count,
                                                   int intervals, int firstNumber) {
    std::vector<model::Vec3> positions;
    positions.reserve(target.thinned.points.size());
    for (const model::reference::ThinnedPoint& p : target.thinned.points) {
        positions.push_back(p.position);
    }
    const model::SplineSpace space{3, 2, intervals};
    std::vector<model::CompositeSurface> strips;
    std::vector<model::Vec3> pointNormals;
    pointNormals.reserve(target.thinned.points.size());
    for (const model::reference::ThinnedPoint& p : target.thinned.points) {
        pointNormals.push_back(p.normal);
    }
    for (const std::vector<std::size_t>& cluster :
         model::reference::clusterPoints(positions, pointNormals, count, kStripBandAspect)) {
        std::vector<model::Vec3> patch;
        std::vector<model::Vec3> normals;
        patch.reserve(cluster.size());
        normals.reserve(cluster.size());
        for (std::size_t i : cluster) {
            patch.push_back(positions[i]);
            normals.push_back(target.thinned.points[i].normal);
        }
        model::CompositeSurface strip;
        try {
            // Rulings along the direction in which the thinned normals turn least, where they
            // show one: a strip laid across a cylinder's rulings cannot bend onto it.
            strip = model::reference::initialStrip(patch, normals, space);
        } catch (const std::invalid_argument&) {
            continue; // a cluster on a line or of fewer than 3 points: no strip
        }
        strip.setName("strip " + std::to_string(firstNumber + static_cast<int>(strips.size())));
        strips.push_back(std::move(strip));
    }
    return strips;
}

namespace {

void thinnedPositionsAndNormals(const ThinnedTarget& target, std::vector<model::Vec3>& positions,
                                std::vector<model::Vec3>& normals) {
    positions.reserve(target.thinned.points.size());
    normals.reserve(target.thinned.points.size());
    for (const model::reference::ThinnedPoint& p : target.thinned.points) {
        positions.push_back(p.position);
        normals.push_back(p.normal);
    }
}

} // namespace

std::optional<model::CompositeSurface> initialStripSheet(const ThinnedTarget& target,
                                                         const std::vector<model::Vec3>& points,
                                                         int count, int intervals,
                                                         int firstNumber) {
    std::vector<model::Vec3> positions;
    std::vector<model::Vec3> normals;
    thinnedPositionsAndNormals(target, positions, normals);
    if (count < 2 || !model::reference::isPatchOverPlane(positions, normals, target.rho)) {
        return std::nullopt;
    }
    try {
        // Over the whole target's rectangle, no margin: it ends where the target does.
        model::CompositeSurface sheet = model::reference::initialStripSheet(
            positions, normals, count, model::SplineSpace{3, 2, intervals}, 0.0, points);
        sheet.setName("strips " + std::to_string(firstNumber));
        return sheet;
    } catch (const std::invalid_argument&) {
        return std::nullopt; // the points on a line: strips over their patches instead
    }
}

std::optional<model::CompositeSurface> initialStripRings(const ThinnedTarget& target,
                                                         const std::vector<model::Vec3>& points,
                                                         int count, int intervals,
                                                         int firstNumber) {
    std::vector<model::Vec3> positions;
    std::vector<model::Vec3> normals;
    thinnedPositionsAndNormals(target, positions, normals);
    if (count < 2) {
        return std::nullopt;
    }
    try {
        model::CompositeSurface rings = model::reference::initialStripRings(
            positions, normals, target.rho, count, model::SplineSpace{3, 2, intervals},
            model::reference::kRingMargin, points);
        rings.setName("rings " + std::to_string(firstNumber));
        return rings;
    } catch (const std::invalid_argument&) {
        return std::nullopt; // no axis it closes around: strips over its patches instead
    }
}

SurfaceTargets assignToSurfaces(const std::vector<model::CompositeSurface>& surfaces,
                                const model::reference::ThinningResult& thinned) {
    const model::reference::SurfaceSamples samples = model::reference::sampleDensely(surfaces, 8);
    const model::reference::PointIndex index(samples.positions);
    SurfaceTargets targets;
    targets.points.resize(surfaces.size());
    targets.normals.resize(surfaces.size());
    for (const model::reference::ThinnedPoint& p : thinned.points) {
        const std::size_t sample = index.nearest(p.position).index;
        const std::size_t s = samples.pieces[samples.piece[sample]].surface;
        targets.points[s].push_back(p.position);
        targets.normals[s].push_back(p.normal);
    }
    return targets;
}

namespace {

// The cylinder over a new strip's points in the strip's spline space, named as the strip; none
// where the points do not spread in two directions.
std::optional<model::CompositeSurface> cylinderStart(const model::CompositeSurface& strip,
                                                     const std::vector<model::Vec3>& points,
                                                     const std::vector<model::Vec3>& normals) {
    for (const auto& [id, edge] : strip.edges()) {
        if (!edge.isSpline()) {
            continue;
        }
        try {
            model::CompositeSurface start = model::reference::initialCylinderStrip(
                points, normals, edge.space, kCylinderStartMargin);
            start.setName(strip.name());
            return start;
        } catch (const std::invalid_argument&) {
            return std::nullopt;
        }
    }
    return std::nullopt;
}

} // namespace

JobRequest approximationRequest(const std::vector<model::CompositeSurface>& surfaces,
                                const SurfaceTargets& targets, double rho,
                                std::optional<int> iterations, bool newStrips) {
    JobRequest request;
    request.kind = JobKind::Approximate;
    request.iterations = iterations;
    request.surfaces = surfaces;
    // New strips are trimmed where they overhang the whole target, not only their own points:
    // a strip lying over its neighbour's points lies on the shape.
    std::shared_ptr<const model::reference::OverhangMeasure> overhang;
    if (newStrips) {
        std::vector<model::Vec3> all;
        std::vector<model::Vec3> allNormals;
        for (std::size_t s = 0; s < targets.points.size() && s < targets.normals.size(); ++s) {
            all.insert(all.end(), targets.points[s].begin(), targets.points[s].end());
            allNormals.insert(allNormals.end(), targets.normals[s].begin(),
                              targets.normals[s].end());
        }
        if (!all.empty() && all.size() == allNormals.size()) {
            overhang = std::make_shared<const model::reference::OverhangMeasure>(
                std::move(all), std::move(allNormals), rho);
        }
    }
    for (std::size_t s = 0; s < surfaces.size() && s < targets.points.size(); ++s) {
        if (targets.points[s].size() < kFewestTargetPoints) {
            continue; // too far from the target to be pulled: stays as it is
        }
        auto t = std::make_shared<ApproximationTarget>();
        t->points = targets.points[s];
        t->normals = targets.normals[s];
        t->borderReach = rho;
        t->falloff = kFalloffRhos * rho;
        if (newStrips) {
            t->dampedStart = cylinderStart(surfaces[s], t->points, t->normals);
            t->overhang = overhang;
            t->trimTolerance = kTrimToleranceRhos * rho;
        }
        request.targets[static_cast<int>(s)] = std::move(t);
    }
    return request;
}

ApproximationSetup prepareApproximation(const std::vector<model::Vec3>& points,
                                        const std::vector<model::CompositeSurface>& start,
                                        const ApproximationOptions& options,
                                        const SetupProgress& progress, int firstNumber) {
    const auto begin = std::chrono::steady_clock::now();
    // The thinning is most of the setup's time: 90 % of the bar.
    const auto report = [&progress](double fraction) { return !progress || progress(fraction); };
    bool stop = false;
    const auto cancelled = [&](double fraction) {
        stop = stop || !report(fraction);
        return stop;
    };
    ApproximationSetup setup;
    setup.newStrips = start.empty();
    const int strips = setup.newStrips ? options.strips : 1;
    setup.target = thinTarget(points, options.rho, [&](std::size_t done, std::size_t total) {
        return !cancelled(total > 0 ? 0.9 * static_cast<double>(done) / total : 0.0);
    });
    if (setup.target.thinned.cancelled || cancelled(0.9)) {
        setup.error = ApproximationSetup::Error::Cancelled;
        return setup;
    }
    if (!enoughPointsFor(setup.target, strips)) {
        setup.error = ApproximationSetup::Error::TooFewPoints;
        return setup;
    }
    std::optional<model::CompositeSurface> sheet;
    if (setup.newStrips && options.oneSurface && strips >= 2) {
        sheet = initialStripSheet(setup.target, points, strips, options.intervals, firstNumber);
        if (!sheet) {
            sheet = initialStripRings(setup.target, points, strips, options.intervals, firstNumber);
            setup.stripsAsRings = sheet.has_value();
        }
    }
    if (sheet) {
        // One surface, pulled as a design's surfaces are: no cylinder start, no trim (both
        // are for surfaces of one strip).
        setup.surfaces = {std::move(*sheet)};
        setup.stripsInOneSurface = strips;
    } else {
        setup.surfaces = setup.newStrips
                             ? initialStrips(setup.target, strips, options.intervals, firstNumber)
                             : start;
    }
    if (setup.surfaces.empty()) {
        setup.error = ApproximationSetup::Error::Collinear;
        return setup;
    }
    if (cancelled(0.95)) {
        setup.error = ApproximationSetup::Error::Cancelled;
        return setup;
    }
    setup.targets = assignToSurfaces(setup.surfaces, setup.target.thinned);
    setup.request =
        approximationRequest(setup.surfaces, setup.targets, setup.target.rho, options.iterations,
                             setup.newStrips && setup.stripsInOneSurface == 0);
    if (setup.request.targets.empty()) {
        setup.error = ApproximationSetup::Error::NothingNear;
    }
    setup.milliseconds =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - begin).count();
    return setup;
}

} // namespace devsurf::solver
