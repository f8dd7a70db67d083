#pragma once

// Internal to views/: where the views mark what the solver imposes on edges, as plain data.

#include "scene_geometry.h"

#include <vector>

namespace devsurf::views {

// A crease with a condition, marked by a badge at the middle of its drawn curve (half its
// length along it).
struct ConditionMark {
    int surface = 0;
    model::EdgeId edge = model::kInvalidId;
    model::CreaseCondition condition = model::CreaseCondition::None;
    model::Vec3 point;
};

std::vector<ConditionMark> conditionMarks(const std::vector<SurfaceScene>& scenes);

// The point half way along a polyline by length (its first point if it has no length).
model::Vec3 midpointByLength(const std::vector<model::Vec3>& points);

} // namespace devsurf::views
