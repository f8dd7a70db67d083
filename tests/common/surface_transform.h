#pragma once

// Test helpers that move a whole surface: every vertex and every control point.

#include "model/composite_surface.h"

#include <cmath>
#include <functional>
#include <map>
#include <vector>

namespace devsurf::test {

// Moves every vertex and control point of the surface by f.
inline void transformSurface(model::CompositeSurface& surface,
                             const std::function<model::Vec3(const model::Vec3&)>& f) {
    std::map<model::EdgeId, std::vector<model::Vec3>> controls;
    for (const auto& [id, record] : surface.edges()) {
        if (record.isSpline()) {
            std::vector<model::Vec3> points;
            for (const model::Vec3& p : record.controlPoints) {
                points.push_back(f(p));
            }
            controls.emplace(id, points);
        }
    }
    for (const auto& [id, position] : std::map(surface.vertices())) {
        surface.moveVertex(id, f(position));
    }
    for (auto& [id, points] : controls) {
        surface.setControlPoints(id, points);
    }
}

// Folds the part of a flat surface in z = 0 beyond the line y = y0 about that line by `angle`
// (radians): positive turns it towards +z.
inline void foldBeyond(model::CompositeSurface& surface, double y0, double angle) {
    transformSurface(surface, [y0, angle](const model::Vec3& p) {
        if (p.y <= y0) {
            return p;
        }
        const double r = p.y - y0;
        return model::Vec3(p.x, y0 + r * std::cos(angle), r * std::sin(angle));
    });
}

} // namespace devsurf::test
