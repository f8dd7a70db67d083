#pragma once

#include "model/composite_surface.h"

#include <utility>
#include <vector>

namespace devsurf::app {

// The largest normalised developability residual |det(a−b, a′, b′)| / (|a−b| |a′| |b′|) of every
// strip patch, sampled along the strip from the geometry alone (cones and planar patches are
// developable by construction and are not listed). Sorted worst first.
std::vector<std::pair<model::FaceId, double>>
faceDevelopability(const model::CompositeSurface& surface, int samplesPerInterval = 20);

} // namespace devsurf::app
