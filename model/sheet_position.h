#pragma once

#include "composite_surface.h"
#include "vec3.h"

#include <optional>

namespace devsurf::model {

// Where a point of a surface lies on its development (unfoldSampledMesh of the sampled mesh
// at kSheetSamples per interval): the point is located on the nearest triangle of the patch
// `face` and carried over with its barycentric coordinates. Nullopt when the patch has no
// sampled face or the surface is invalid. Distances between two such positions are measured
// on the flat sheet, as the cut pattern has them.
std::optional<Vec2> sheetPosition(const CompositeSurface& surface, FaceId face, const Vec3& point);

inline constexpr int kSheetSamples = 8;

} // namespace devsurf::model
