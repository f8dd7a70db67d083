#pragma once

#include "io/shape/patch_surfaces.h"

#include <vector>

namespace devsurf::test {

// The distance from p to the nearest of the patches: for a ruled patch the nearest point of
// each ruling is exact (a segment), the ruling parameter u is found by a scan and a ternary
// search; for a planar patch the distance to its plane where p projects into the polygon.
double distanceToPatches(const model::Vec3& p, const std::vector<io::PatchSurface>& patches);

} // namespace devsurf::test
