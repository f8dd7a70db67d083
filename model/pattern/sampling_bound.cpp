#include "sampling_bound.h"

#include "model/pattern/pattern_pieces.h"

#include <algorithm>

namespace devsurf::model::pattern {

long curveSampleCount(const CompositeSurface& surface, double tolerance) {
    long intervals = 0;
    for (const auto& [id, edge] : surface.edges()) {
        if (edge.isSpline()) {
            intervals += edge.space.intervals;
        }
    }
    return intervals * samplesForTolerance(surface, tolerance);
}

std::optional<OversampledSurface> oversampledSurface(const Project& project, double tolerance) {
    for (std::size_t i = 0; i < project.surfaces.size(); ++i) {
        const CompositeSurface& surface = project.surfaces[i];
        const long samples = curveSampleCount(surface, tolerance);
        if (samples <= kMaxCurveSamples) {
            continue;
        }
        OversampledSurface found;
        found.surface = static_cast<int>(i);
        found.samples = samples;
        for (const auto& [id, edge] : surface.edges()) {
            for (const Vec3& p : edge.controlPoints) {
                found.reach = std::max(found.reach, p.norm());
            }
        }
        for (double coarser : {0.1, 1.0, 10.0}) {
            if (coarser > tolerance && curveSampleCount(surface, coarser) <= kMaxCurveSamples) {
                found.coarser = coarser;
                break;
            }
        }
        return found;
    }
    return std::nullopt;
}

} // namespace devsurf::model::pattern
