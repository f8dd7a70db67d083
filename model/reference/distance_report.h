#pragma once

#include "model/composite_surface.h"
#include "model/vec3.h"

#include <array>
#include <atomic>
#include <stdexcept>
#include <vector>

namespace devsurf::model::reference {

struct DistanceOptions {
    // Target points within this distance of the surface count as covered; 0 or less means 1 %
    // of the target's bounding-box diagonal.
    double tolerance = 0.0;
    // Density of the surface samples: grid steps along each strip per spline interval.
    int samplesPerInterval = 16;
    // Checked every few hundred points; once set, measureDistance throws DistanceCancelled.
    const std::atomic<bool>* cancel = nullptr;
    // The target's triangles (indices into its points), for a mesh: surface → target is then
    // the distance to the mesh. Without them it is the distance to the nearest point, which
    // on a mesh counts the spacing of its vertices as distance (on the Stanford bunny about
    // 0.2 % of the diagonal for a surface lying on it).
    const std::vector<std::array<int, 3>>* triangles = nullptr;
};

// measureDistance stopped because DistanceOptions::cancel was set.
struct DistanceCancelled : std::runtime_error {
    DistanceCancelled() : std::runtime_error("measureDistance: cancelled") {}
};

// A one-sided distance: over the points of one shape, the distance to the other shape.
struct OneSidedDistance {
    double mean = 0.0; // document units
    double percentile95 = 0.0;
    double max = 0.0;
    // The same as percentages of the target's bounding-box diagonal.
    double meanPercent = 0.0;
    double percentile95Percent = 0.0;
    double maxPercent = 0.0;
};

// How far a design is from its target (§4.2, issue 42's distance report).
struct DistanceReport {
    // Target → surface: over the target points, the distance to the closest surface point.
    OneSidedDistance targetToSurface;
    // Surface → target: over the surface (weighted by area), the distance to the target: its
    // mesh where DistanceOptions::triangles are given, else its nearest point. Sampled, so
    // within DistanceReport::surfaceSpacing of the exact figures.
    OneSidedDistance surfaceToTarget;
    double diagonal = 0.0;  // of the target's bounding box
    double tolerance = 0.0; // the one used for coverage
    double coverage = 0.0;  // fraction of the target points within tolerance of the surface
    // Per target point, the distance to the surface (for a colour map); in target order.
    std::vector<double> targetDistances;
    std::size_t surfaceSamples = 0;
    double surfaceSpacing = 0.0; // every surface point is this close to a sample
    bool toMesh = false;         // surface → target measured to the target's triangles
    double hausdorff() const { return std::max(targetToSurface.max, surfaceToTarget.max); }
};

// The distance report of one or more composite surfaces against target points (a thinned or
// whole reference). Target → surface is exact up to Newton's convergence: the nearest surface
// sample (KD-tree), then every piece with a sample close enough to hold a closer point, each
// refined to its true closest point (closestPointOnStrip, closestPointOnTriangle). Surface →
// target takes the dense samples to the nearest target point, or on a mesh to the closest
// point of the triangles around its kMeshNeighbours nearest vertices (the nearest vertex's
// distance where that is nearer). The 95th percentile is the
// smallest distance that at least 95 % of the points (of the area) do not exceed.
// Throws ModelError for an invalid surface or samplesPerInterval outside [1, 1000],
// DistanceCancelled once options.cancel is set, and std::invalid_argument for an empty target, a
// target with non-finite points, a triangle index that is not a target point or a design
// without faces.
DistanceReport measureDistance(const std::vector<CompositeSurface>& surfaces,
                               const std::vector<Vec3>& target,
                               const DistanceOptions& options = {});
inline constexpr std::size_t kMeshNeighbours = 8;
DistanceReport measureDistance(const CompositeSurface& surface, const std::vector<Vec3>& target,
                               const DistanceOptions& options = {});

} // namespace devsurf::model::reference
