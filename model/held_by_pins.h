#pragma once

#include "composite_surface.h"

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace devsurf::model {

// Pinned vertices that hold part of a sheet flat whatever it bends. Two pinned vertices as far
// apart in space as along the straight line joining them in the development, that line lying in
// the sheet, hold that line straight: any other curve of the sheet between them is longer than
// their distance. Three such vertices pairwise hold the triangle between them: it is congruent to
// its development, so every chord across it is held straight as well. Bending alone (a drag that
// keeps lengths) cannot move a vertex on such a line or inside such a triangle; only stretching
// can. Example: the four corners of a flat square pinned hold the whole square.
struct HeldVertex {
    VertexId vertex = kInvalidId;
    std::vector<VertexId> pins; // two (the vertex lies on their line) or three
};

// The first of `vertices` (in their order) that its surface's pinned vertices hold, and the pins
// that hold it; nothing when none is held, when the surface has fewer than two pinned vertices,
// or when it does not unfold into one piece (its development is then not a single plane region).
// Distances count as equal within `relativeTolerance` of the pins' distance. With more than 300
// pins only lines between two of them are considered. Cost: a development of the surface
// (0.2 ms for fig8, about 0.1 s for 5,000 vertices).
std::optional<HeldVertex> findVertexHeldByPins(const CompositeSurface& surface,
                                               const std::vector<VertexId>& vertices,
                                               double relativeTolerance = 1e-6);

// The pairs of pinned vertices that hold the straight line between them (as above), each pair
// once, smaller id first in pin order; a pair joined by a ruling (an R-edge) is left out, a
// ruling being straight anyway. Held, a strip that such a line crosses across its rulings
// stays flat, and a curved crease beside a flat strip cannot fold. Empty when the surface has
// fewer than two pins or does not unfold into one piece.
std::vector<std::pair<VertexId, VertexId>> findTautPinLines(const CompositeSurface& surface,
                                                            double relativeTolerance = 1e-6);

} // namespace devsurf::model
