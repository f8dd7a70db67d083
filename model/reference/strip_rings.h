#pragma once

// New strips laid as rings one after another around a reference shape that closes around an
// axis (a tube, a vase, a sphere without its poles): the automatic approximation's watertight
// start where the shape is no patch (docs/tuning.md, "Rings around a closed shape").

#include "model/composite_surface.h"
#include "model/spline_space.h"
#include "model/vec3.h"

#include <optional>
#include <vector>

namespace devsurf::model::reference {

// The axis the points close around, if any: a principal axis (model::reference::principalFrame)
// about which, in the plane across it, the points surround a centre line that runs through the
// mean of every slab. On that axis at least kTubeNormalShare of the normals lie within
// kPatchNormalAngle of the direction away from the centre line (either sign), in every slab
// between its lines each of kTubeAngularBins angles around it holds points, in every cell of about
// 2ρ × 2ρ (around × along) the distances from the centre line are no farther apart than the cell's
// steepest slope allows, plus ρ: one layer all around; and four rings fitted as initialStripRings
// fits them give the distance of at least kTubeFitShare of the points within 2ρ or a tenth (no limb
// or bulge stands off). The axis of the three that passes and fits rings best; none for fewer than
// 3 points, a missing normal or ρ ≤ 0.
std::optional<Vec3> tubeAxis(const std::vector<Vec3>& points, const std::vector<Vec3>& normals,
                             double rho);
inline constexpr double kTubeNormalShare = 0.9;
inline constexpr int kTubeAngularBins = 12;
inline constexpr double kTubeFitShare = 0.95;

inline constexpr double kRingMargin = 0.05;

// `count` rings one after another along tubeAxis, each a band of kRingSectors faces closed
// around it; each two rings share a closed curve with no crease condition, so the surface is
// watertight (open only at its two ends) and may kink there. Bent to the points as laid: the
// curves are scaled copies ρ_k C(θ) of one closed curve about centres on a polyline along the
// axis, the scales, the centres and C fitted to the points' distances from that line by
// alternating least squares (C a short Fourier series), so every ring is a general cone (or
// cylinder) and the surface is developable. The rings are fitted over `whole` (the shape the
// points were thinned from; empty: the points, enlarged by ρ) along the axis enlarged by
// `margin` at both ends, and the end rings then shortened along their cones: to the shape's
// ends where it stays open, or where the shape closes (a sphere's pole: the end's fitted scale
// below kRingSmallestScale of the largest) to where the cone reaches that scale. Every curve is
// at least kRingSmallestScale of the largest. Named "rings". Throws std::invalid_argument where
// tubeAxis finds none, for count < 1, an invalid space, margin < 0 or a `whole` without extent
// along the axis.
CompositeSurface initialStripRings(const std::vector<Vec3>& points,
                                   const std::vector<Vec3>& normals, double rho, int count,
                                   const SplineSpace& space, double margin = kRingMargin,
                                   const std::vector<Vec3>& whole = {});
inline constexpr int kRingSectors = 4;
inline constexpr double kRingSmallestScale = 0.1;

} // namespace devsurf::model::reference
