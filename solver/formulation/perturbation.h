#pragma once

#include "model/composite_surface.h"

#include <vector>

namespace devsurf::solver {

// Diagonal of the bounding box of all vertices and control points (the "diameter" the
// benchmark and docs/math.md §8 scale by).
double surfaceDiameter(const model::CompositeSurface& surface);

// The mean length of the segments of all edges' control polygons (0 if there are none).
double meanControlSpacing(const model::CompositeSurface& surface);

// Adds independent Gaussian noise of standard deviation `sigma` (model units) to every
// coordinate of every vertex and interior control point, except the vertices in `keep`.
// Deterministic for a given seed.
void perturbSurface(model::CompositeSurface& surface, double sigma, unsigned seed,
                    const std::vector<model::VertexId>& keep = {});

// `count` boundary vertices spread over the boundary (the first by id, then each farthest from
// those already chosen): the anchors the benchmark fixes. Fewer if the boundary has fewer.
std::vector<model::VertexId> spreadBoundaryVertices(const model::CompositeSurface& surface,
                                                    int count);

} // namespace devsurf::solver
