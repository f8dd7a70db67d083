#pragma once

#include "model/composite_surface.h"
#include "straight_control_points.h"

#include <cmath>
#include <vector>

namespace devsurf::test {

// A band of strips winding one and a half times around the z-axis while rising: it does not
// meet itself in space, but its development (close to a flat ring) does.
inline model::CompositeSurface helicalBand() {
    constexpr double kPi = 3.14159265358979323846;
    const int steps = 18;
    const model::SplineSpace space{3, 2, 1};
    model::CompositeSurface s;
    s.setName("helix");
    std::vector<model::VertexId> inner;
    std::vector<model::VertexId> outer;
    for (int i = 0; i <= steps; ++i) {
        const double phi = 3.0 * kPi * i / steps;
        const double z = 2.0 * i;
        inner.push_back(s.addVertex({100 * std::cos(phi), 100 * std::sin(phi), z}));
        outer.push_back(s.addVertex({160 * std::cos(phi), 160 * std::sin(phi), z}));
    }
    for (int i = 0; i < steps; ++i) {
        s.addFace({inner[i], outer[i], outer[i + 1], inner[i + 1]});
    }
    for (int i = 0; i < steps; ++i) {
        for (const auto* chain : {&inner, &outer}) {
            const model::VertexId a = (*chain)[i];
            const model::VertexId b = (*chain)[i + 1];
            s.setSpline(a, b, space, straightControlPoints(space, s.position(a), s.position(b)));
        }
    }
    return s;
}

} // namespace devsurf::test
