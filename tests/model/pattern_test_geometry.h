#pragma once

// The pattern tests' own plane geometry, independent of the pattern code.

#include "model/vec3.h"

#include <vector>

namespace devsurf::model {

// The signed area of a closed polygon (positive counter-clockwise).
inline double shoelace(const std::vector<Vec2>& polygon) {
    double area = 0.0;
    for (std::size_t i = 0; i < polygon.size(); ++i) {
        const Vec2& p = polygon[i];
        const Vec2& q = polygon[(i + 1) % polygon.size()];
        area += p.x * q.y - p.y * q.x;
    }
    return area / 2;
}

} // namespace devsurf::model
