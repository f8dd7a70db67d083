#pragma once

#include "model/composite_surface.h"

namespace devsurf::test {

// One flat strip in the plane z = 0 between a(u) = (100 u, 0, 0) and a quadratic b(u) from
// (0, 50, 0) to (100, 50, 0) whose middle control point lies at y = middleY. With middleY = 100
// the strip is an ordinary flat patch; with middleY = −150, b dips to y = −50 at u = ½ and
// crosses a twice: between the crossings the strip lies folded back onto itself (its sampled
// quads turn round), as a flat sheet pushed within its own plane until it overlaps itself.
inline model::CompositeSurface flatStrip(double middleY) {
    const model::SplineSpace space{2, 1, 1};
    model::CompositeSurface s;
    const auto a0 = s.addVertex({0, 0, 0});
    const auto a1 = s.addVertex({100, 0, 0});
    const auto b1 = s.addVertex({100, 50, 0});
    const auto b0 = s.addVertex({0, 50, 0});
    s.addFace({a0, a1, b1, b0});
    s.setSpline(a0, a1, space, {{0, 0, 0}, {50, 0, 0}, {100, 0, 0}});
    s.setSpline(b0, b1, space, {{0, 50, 0}, {50, middleY, 0}, {100, 50, 0}});
    return s;
}

} // namespace devsurf::test
