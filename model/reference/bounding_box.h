#pragma once

#include "model/vec3.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace devsurf::model::reference {

// The axis-aligned bounding box of points (both corners at the origin if there are none).
struct BoundingBox {
    Vec3 low;
    Vec3 high;

    double diagonal() const { return (high - low).norm(); }
    // How far `p` lies outside the box (0 inside or on it).
    double distanceOutside(const Vec3& p) const {
        double squared = 0.0;
        for (int i = 0; i < 3; ++i) {
            const double d = std::max({low[i] - p[i], 0.0, p[i] - high[i]});
            squared += d * d;
        }
        return std::sqrt(squared);
    }
};

inline BoundingBox boundingBox(const std::vector<Vec3>& points) {
    BoundingBox box;
    if (points.empty()) {
        return box;
    }
    box.low = points.front();
    box.high = points.front();
    for (const Vec3& p : points) {
        for (int i = 0; i < 3; ++i) {
            box.low[i] = std::min(box.low[i], p[i]);
            box.high[i] = std::max(box.high[i], p[i]);
        }
    }
    return box;
}

// The length of the diagonal of the axis-aligned bounding box of `points` (0 if empty): the
// size of a reference shape, which distances and the thinning radius are measured against.
inline double boundingBoxDiagonal(const std::vector<Vec3>& points) {
    return boundingBox(points).diagonal();
}

} // namespace devsurf::model::reference
