#pragma once

// New strips laid side by side as one surface over a reference shape that is one patch: the
// automatic approximation's watertight start (docs/tuning.md, "Strips side by side as one
// surface").

#include "model/composite_surface.h"
#include "model/spline_space.h"
#include "model/vec3.h"

#include <vector>

namespace devsurf::model::reference {

// Whether the points, thinned at spacing ρ with a normal each, are one patch seen from one
// side: at least kPatchNormalShare of the normals within kPatchNormalAngle of the PCA plane's
// (either sign), and in every 2ρ cell of that plane the heights no farther apart than the
// cell's steepest slope allows, plus ρ. False for fewer than 3 points or a missing normal.
bool isPatchOverPlane(const std::vector<Vec3>& points, const std::vector<Vec3>& normals,
                      double rho);
inline constexpr double kPatchNormalAngle = 1.3089969389957472; // 75°
inline constexpr double kPatchNormalShare = 0.98;

// `count` strips in a row over the rectangle of the points (or of `whole`, the shape they
// were thinned from, where given) in their PCA plane, enlarged by `margin`, each two sharing a
// curve with no crease condition, so the surface is watertight and may kink there. Bent to the
// points as laid: the height fitted as f(u) + g(w), f a cubic along the curves, g piecewise
// linear across with its kinks at the shared curves, so every strip is a general cylinder and
// the surface is developable. The curves run where the normals turn most (else the longest
// axis) unless another of kCylinderDirections directions fits better by
// kCylinderDirectionGain, among those whose rectangle is at most kSheetAreaSlack times the
// smallest. Named "strips". Throws as initialStrip, or for count < 1.
CompositeSurface initialStripSheet(const std::vector<Vec3>& points,
                                   const std::vector<Vec3>& normals, int count,
                                   const SplineSpace& space, double margin = 0.05,
                                   const std::vector<Vec3>& whole = {});
inline constexpr double kSheetAreaSlack = 1.25;

} // namespace devsurf::model::reference
