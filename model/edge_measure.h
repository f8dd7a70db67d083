#pragma once

// Lengths and angles of the coarse mesh's edges as built (Tools ▸ Measure).

#include "composite_surface.h"

#include <optional>

namespace devsurf::model {

// The length (mm) of an edge in space: an S-edge's spline (chords of 1/1000 of its parameter
// range, relative error below 1e-6 for the designs' curvatures), an R-edge's segment.
double edgeLength(const CompositeSurface& surface, EdgeId edge);

// The angle (degrees, 0 … 180) between two edges at a vertex they share, between their
// tangents pointing away from it; nullopt when they share no vertex or are the same edge.
struct EdgeAngle {
    VertexId vertex = kInvalidId;
    double degrees = 0.0;
};
std::optional<EdgeAngle> edgeAngle(const CompositeSurface& surface, EdgeId a, EdgeId b);

} // namespace devsurf::model
