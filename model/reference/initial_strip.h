#pragma once

#include "model/composite_surface.h"
#include "model/spline_space.h"
#include "model/vec3.h"

#include <cstddef>
#include <vector>

namespace devsurf::model::reference {

// The plane fitted to a set of points by PCA: the centroid and the principal axes, longest
// first (axes[2] is the plane's normal); extent[i] is the spread of the points along axes[i]
// (largest minus smallest projection).
struct PrincipalFrame {
    Vec3 centroid;
    Vec3 axes[3];
    double low[3] = {0.0, 0.0, 0.0}; // smallest projection on each axis, from the centroid
    double high[3] = {0.0, 0.0, 0.0};
};

// Throws std::invalid_argument for fewer than 3 points or a non-finite coordinate.
PrincipalFrame principalFrame(const std::vector<Vec3>& points);

// The initial strip of §4.2 (Fig. 10a): a flat rectangle in the PCA plane of `points`, its
// curves a and b along the longest principal axis (straight splines in `space`), its rulings
// along the second axis, covering the points' projection enlarged by `margin` times its size
// on every side. One SRSR face; valid (validate() is empty). The face is oriented so that its
// normal a′ × (b − a) is the third principal axis. Throws std::invalid_argument for fewer than
// 3 points, a non-finite coordinate, points without spread in two directions, an invalid space
// or a negative margin.
CompositeSurface initialStrip(const std::vector<Vec3>& points, const SplineSpace& space,
                              double margin = 0.05);

// The same strip turned in its plane to the points' curvature where `normals` (one per point,
// either sign) show it: where the normal turns clearly more in one direction of the plane than
// in the other (by kRulingAnisotropy), as on a cylinder, a developable surface's rulings run
// along the other, so a and b run along the direction of most turning if that lies more than
// kRulingTurnAngle from the longest axis. Otherwise (a sphere, a plane, empty normals) as
// above. Throws as above, and std::invalid_argument for a count of normals other than zero or
// that of the points.
CompositeSurface initialStrip(const std::vector<Vec3>& points, const std::vector<Vec3>& normals,
                              const SplineSpace& space, double margin = 0.05);

// How much more the normal must turn along one direction of the plane than along the other,
// and how far it must turn over the points at least (rad), for initialStrip to lay the rulings
// along the direction of least turning; and how far (rad) the direction of most turning must
// lie from the longest axis for the strip to be turned at all.
inline constexpr double kRulingAnisotropy = 2.0;
inline constexpr double kRulingTurnMinimum = 0.05;
inline constexpr double kRulingTurnAngle = 0.5235987755982988; // 30°

// A simple automatic split of a shape into `count` groups for as many initial strips: k-means
// on the positions (Lloyd's iteration, at most 50 rounds) from a deterministic farthest-point
// start (the point farthest from the centroid, then each time the point farthest from the
// centres chosen). Its groups are compact patches, which a flat strip can start on even on a
// closed shape (slabs of a closed shape are rings, which no strip covers: measured on the
// bunny, slab strips diverged). The groups (at most `count`; none empty) hold indices into
// `points`, ascending. Throws std::invalid_argument if count < 1 or count > points.size() / 3.
std::vector<std::vector<std::size_t>> clusterPoints(const std::vector<Vec3>& points, int count);

} // namespace devsurf::model::reference
