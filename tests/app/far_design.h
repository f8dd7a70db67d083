#pragma once

#include "model/examples.h"

namespace devsurf::test {

// The annulus with one control point moved up to the validity limit (1 km): valid, but its
// curves sampled to 0.01 mm would need some 168,000 points.
inline model::Project farAnnulus() {
    model::Project far = model::makeExample("annulus");
    model::CompositeSurface& surface = far.surfaces.front();
    for (const auto& [id, edge] : surface.edges()) {
        if (edge.isSpline() && edge.controlPoints.size() > 2) {
            std::vector<model::Vec3> points = edge.controlPoints;
            points[1].z = 0.999e6;
            surface.setControlPoints(id, points);
            break;
        }
    }
    return far;
}

} // namespace devsurf::test
