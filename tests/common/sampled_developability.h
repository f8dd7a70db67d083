#pragma once

#include "model/composite_surface.h"
#include "model/strip.h"
#include "model/vec3.h"

#include <algorithm>
#include <cmath>

namespace devsurf::test {

// The largest |det(a − b, a′, b′)| / (|a − b| |a′| |b′|) over every strip, 50 values per
// interval (MATH.md §8), from the splines alone: a check of developability independent of the
// solver's own measures.
inline double sampledDevelopability(const model::CompositeSurface& surface) {
    double worst = 0.0;
    for (const model::Strip& strip : model::stripsOf(surface)) {
        const int intervals = static_cast<int>(strip.a.knots().size()) - 2 * strip.a.degree() - 1;
        const int samples = 50 * std::max(1, intervals);
        for (int i = 0; i <= samples; ++i) {
            const double u = static_cast<double>(i) / samples;
            const model::Vec3 ruling = strip.a.evaluate(u) - strip.b.evaluate(u);
            const model::Vec3 da = strip.a.derivative(u, 1);
            const model::Vec3 db = strip.b.derivative(u, 1);
            const double scale = ruling.norm() * da.norm() * db.norm();
            const double det = std::abs(dot(ruling, cross(da, db))) / scale;
            worst = std::max(worst, det);
        }
    }
    return worst;
}

} // namespace devsurf::test
