#pragma once

#include "model/composite_surface.h"

#include <vector>

namespace devsurf::app {

// The edges of one label an edit adds, as polylines in space for a preview: every such edge
// of after that before does not have (S-edges sampled along their curve, R-edges as segments).
// A crease is previewed by its new S-edges, a ruling by its new R-edges (the halves of cut
// edges are new edges too, of the other label).
std::vector<std::vector<model::Vec3>> addedEdgeLines(const model::CompositeSurface& before,
                                                     const model::CompositeSurface& after,
                                                     model::EdgeLabel label);

} // namespace devsurf::app
