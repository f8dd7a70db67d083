#pragma once

// What the initial strips and the strips laid as one surface share (initial_strip.cpp,
// strip_sheet.cpp): the points' plane, the way their normals turn, their extents.

#include "model/reference/initial_strip.h"

#include <optional>
#include <vector>

namespace devsurf::model::reference::detail {

// How the normals turn over the points: a least-squares linear fit of their tilt (their
// components in the frame's plane, each normal turned to the side of axes[2]) against the
// points' position in the plane; its singular values (rad per mm, larger first) and the unit
// direction in the plane of the larger one. None for a missing or zero normal.
struct Turning {
    double most = 0.0;
    double least = 0.0;
    Vec3 direction;
    double alongLongest = 0.0; // |cos| of its angle to axes[0]
};

std::optional<Turning> normalTurning(const std::vector<Vec3>& points,
                                     const std::vector<Vec3>& normals, const PrincipalFrame& frame);

// The arguments of an initial strip checked (std::invalid_argument as initialStrip documents),
// the points' frame, and the direction of a and b in its plane: the longest axis, or the
// direction of most turning.
struct StripPlane {
    PrincipalFrame frame;
    Vec3 along;
};

StripPlane stripPlane(const std::vector<Vec3>& points, const std::vector<Vec3>& normals,
                      const SplineSpace& space, double margin);

// The smallest and largest projection of the points, from `origin`, on `along` (index 0) and
// on `across` (index 1).
void extents(const std::vector<Vec3>& points, const Vec3& origin, const Vec3& along,
             const Vec3& across, double low[2], double high[2]);

} // namespace devsurf::model::reference::detail
