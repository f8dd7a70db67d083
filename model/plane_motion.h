#pragma once

// Rigid motions of the plane (a mirror allowed) and the one that best maps one list of points
// onto another: laying a fresh unfolding onto a kept development, a sheet onto a pattern piece.

#include "vec3.h"

#include <optional>
#include <vector>

namespace devsurf::model {

// A rigid motion of the plane, a mirror allowed: p ↦ R(angle)·(mirror(p) − from) + to, with
// mirror(x, y) = (−x, y) when mirrored.
struct PlaneMotion {
    bool mirrored = false;
    double angle = 0.0;
    Vec2 from;
    Vec2 to;

    Vec2 apply(const Vec2& p) const;
    Vec2 applyInverse(const Vec2& p) const;
};

// The rigid motion (a mirror allowed) that best maps `from` onto `to` (2D Procrustes: least
// squared distances); none for fewer than two pairs or lists of different lengths.
std::optional<PlaneMotion> fitPlaneMotion(const std::vector<Vec2>& from,
                                          const std::vector<Vec2>& to);

} // namespace devsurf::model
