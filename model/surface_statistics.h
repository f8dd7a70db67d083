#pragma once

#include "composite_surface.h"

#include <map>

namespace devsurf::model {

// The counts a designer checks first: what `devsurf-cli info` prints.
struct SurfaceStatistics {
    std::size_t vertices = 0;
    std::size_t splineEdges = 0;
    std::size_t rulingEdges = 0;
    std::size_t controlPoints = 0;
    std::map<FaceType, std::size_t> facesByType;     // every type present, invalid included
    std::map<SplineSpace, std::size_t> splineSpaces; // S-edges per spline space
    std::size_t faces() const;
};

SurfaceStatistics surfaceStatistics(const CompositeSurface& surface);

} // namespace devsurf::model
