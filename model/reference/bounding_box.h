#pragma once

#include "model/vec3.h"

#include <algorithm>
#include <vector>

namespace devsurf::model::reference {

// The length of the diagonal of the axis-aligned bounding box of `points` (0 if empty): the
// size of a reference shape, which distances and the thinning radius are measured against.
inline double boundingBoxDiagonal(const std::vector<Vec3>& points) {
    if (points.empty()) {
        return 0.0;
    }
    Vec3 low = points.front();
    Vec3 high = points.front();
    for (const Vec3& p : points) {
        for (int i = 0; i < 3; ++i) {
            low[i] = std::min(low[i], p[i]);
            high[i] = std::max(high[i], p[i]);
        }
    }
    return (high - low).norm();
}

} // namespace devsurf::model::reference
