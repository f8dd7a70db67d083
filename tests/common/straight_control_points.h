#pragma once

#include "model/spline_space.h"
#include "model/vec3.h"

#include <vector>

namespace devsurf::test {

// A straight control sequence from a to b in a spline space, evenly spaced, whose ends are a
// and b bit for bit (so the curve starts and ends at its vertices).
inline std::vector<model::Vec3> straightControlPoints(const model::SplineSpace& space,
                                                      const model::Vec3& a, const model::Vec3& b) {
    const int count = space.controlPointCount(false);
    std::vector<model::Vec3> points;
    for (int i = 0; i < count; ++i) {
        const double t = static_cast<double>(i) / (count - 1);
        points.push_back(a * (1 - t) + b * t);
    }
    points.front() = a;
    points.back() = b;
    return points;
}

} // namespace devsurf::test
