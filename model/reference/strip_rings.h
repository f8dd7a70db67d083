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

// The principal axis the thinned points (with normals, either sign) close around as one layer
// with their normals facing away from it, where four fitted rings explain most of them; the
// tests and thresholds are in docs/tuning.md, "Rings around a closed shape". None for fewer
// than 3 points, a missing normal or ρ ≤ 0.
std::optional<Vec3> tubeAxis(const std::vector<Vec3>& points, const std::vector<Vec3>& normals,
                             double rho);
inline constexpr double kTubeNormalShare = 0.9;
inline constexpr int kTubeAngularBins = 12;
inline constexpr double kTubeFitShare = 0.95;

inline constexpr double kRingMargin = 0.05;

// `count` rings one after another around tubeAxis, kRingSectors faces each, each two sharing a
// closed curve with no crease condition: watertight but for its two ends. Every curve is a
// scaled copy of one fitted closed curve, so every ring is a cone and the surface developable as
// laid. The rings span `whole` along the axis (empty: the points, plus ρ), fitted `margin`
// beyond and then shortened along their cones to the shape's ends, or where it closes (a pole)
// to kRingSmallestScale of the largest curve. Named "rings". Throws std::invalid_argument where
// tubeAxis finds none, for count < 1, an invalid space or margin < 0.
CompositeSurface initialStripRings(const std::vector<Vec3>& points,
                                   const std::vector<Vec3>& normals, double rho, int count,
                                   const SplineSpace& space, double margin = kRingMargin,
                                   const std::vector<Vec3>& whole = {});
inline constexpr int kRingSectors = 4;
inline constexpr double kRingSmallestScale = 0.1;

} // namespace devsurf::model::reference
