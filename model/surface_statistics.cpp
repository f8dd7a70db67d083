#include "surface_statistics.h"

namespace devsurf::model {

std::size_t SurfaceStatistics::faces() const {
    std::size_t total = 0;
    for (const auto& entry : facesByType) {
        total += entry.second;
    }
    return total;
}

SurfaceStatistics surfaceStatistics(const CompositeSurface& surface) {
    SurfaceStatistics stats;
    stats.vertices = surface.vertices().size();
    stats.controlPoints = surface.controlPointCount();
    for (const auto& [id, record] : surface.edges()) {
        if (record.isSpline()) {
            ++stats.splineEdges;
            ++stats.splineSpaces[record.space];
        } else {
            ++stats.rulingEdges;
        }
    }
    for (const auto& entry : surface.faces()) {
        ++stats.facesByType[surface.faceType(entry.first)];
    }
    return stats;
}

} // namespace devsurf::model
