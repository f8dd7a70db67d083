#pragma once

#include "model/composite_surface.h"
#include "model/spline_space.h"
#include "model/vec3.h"

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace devsurf::model::reference {

// The plane fitted to points by PCA: the centroid and the principal axes, longest first
// (axes[2] is the plane's normal).
struct PrincipalFrame {
    Vec3 centroid;
    Vec3 axes[3];
    double low[3] = {0.0, 0.0, 0.0}; // smallest projection on each axis, from the centroid
    double high[3] = {0.0, 0.0, 0.0};
};

// Throws std::invalid_argument for fewer than 3 points or a non-finite coordinate.
PrincipalFrame principalFrame(const std::vector<Vec3>& points);

// The initial strip of §4.2 (Fig. 10a): one SRSR face, a flat trapezoid in the PCA plane of
// `points`, curves a and b along the longest axis, each spanning its half of the points, enlarged
// by `margin` on every side; normal a′ × (b − a) = axes[2]. Throws std::invalid_argument for
// fewer than 3 points, a non-finite coordinate, points on a line, an invalid space or
// margin < 0.
CompositeSurface initialStrip(const std::vector<Vec3>& points, const SplineSpace& space,
                              double margin = 0.05);

// The same, with a and b along the direction in which `normals` (one per point, either sign, or
// none) turn most, where they turn clearly more that way than across (a cylinder: its rulings
// run across) and that way lies far from the longest axis; thresholds below.
CompositeSurface initialStrip(const std::vector<Vec3>& points, const std::vector<Vec3>& normals,
                              const SplineSpace& space, double margin = 0.05);

// The same strip, a rectangle, bent into the general cylinder that fits the points best: the
// height a cubic along the curves plus a tilt across, the curves along the direction above or
// one of kCylinderDirections turned ones, whichever fits best. Exactly developable (b is a
// translate of a). Throws as above.
CompositeSurface initialCylinderStrip(const std::vector<Vec3>& points,
                                      const std::vector<Vec3>& normals, const SplineSpace& space,
                                      double margin = 0.05);
inline constexpr int kCylinderDirections = 12;
// Another direction replaces the first only where its cylinder's squared error is below this
// fraction of the first's.
inline constexpr double kCylinderDirectionGain = 0.8;

// Control points in `space` (open) of the curve `at` (t in [0, 1]), by least squares over
// 4 samples per control point: exact for a curve of the space, such as a polynomial of at
// most its degree.
std::vector<Vec3> fitControlPoints(const SplineSpace& space, const std::function<Vec3(double)>& at);

// A surface of one strip named `name`, its curves a and b given by their control points in
// `space` (open): the face loop a0, a1, b1, b0, so its normal is a′ × (b − a), and a is the
// strip's curve a (model::stripOfFace).
CompositeSurface stripOfCurves(const std::string& name, const SplineSpace& space,
                               const std::vector<Vec3>& a, const std::vector<Vec3>& b);

// Turning ratio of the two directions, least turn over the points (rad), least angle from the
// longest axis (docs/tuning.md).
inline constexpr double kRulingAnisotropy = 2.0;
inline constexpr double kRulingTurnMinimum = 0.05;
inline constexpr double kRulingTurnAngle = 0.5235987755982988; // 30°

// Where a group's normals turn this much more one way than across, its band runs that way.
inline constexpr double kBandAnisotropy = 1.5;

// A shape split into at most `count` compact groups (no empty one) for as many initial strips:
// k-means (at most 50 rounds) from a deterministic farthest-point start; indices into `points`,
// ascending. Compact patches, not slabs: a closed shape's slabs are rings no strip covers.
// Throws std::invalid_argument if count < 1 or count > points.size() / 3.
std::vector<std::vector<std::size_t>> clusterPoints(const std::vector<Vec3>& points, int count);

// The same groups, those over a doubly curved part drawn out into bands `aspect` times as long
// as wide (k-means counting a step across the band `aspect` times), the band running where the
// group's normals (either sign) turn most: a developable strip follows a doubly curved shape
// only across a narrow width. aspect 1: clusterPoints above. Throws as above, or for aspect < 1
// or one normal per point missing.
std::vector<std::vector<std::size_t>> clusterPoints(const std::vector<Vec3>& points,
                                                    const std::vector<Vec3>& normals, int count,
                                                    double aspect);

} // namespace devsurf::model::reference
