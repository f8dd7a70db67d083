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

// How the views draw folds, in the origami convention the printed cutting pattern follows:
// mountain dash-dot, valley dashed, a crease that is not folded solid. Lengths dash, gap,
// dash, gap… in units of kFoldDashUnitPixels on screen; empty for a solid line.
constexpr double kFoldDashUnitPixels = 4.0;
std::vector<double> foldDashes(model::FoldAssignment fold);

// The dashes of polylines: pattern holds the lengths (scene units, all positive) of dash, gap,
// dash, gap…, repeated along every polyline from its start. The lines themselves if the
// pattern is empty, odd or not positive.
std::vector<std::vector<model::Vec3>>
dashedPolylines(const std::vector<std::vector<model::Vec3>>& lines,
                const std::vector<double>& pattern);

} // namespace devsurf::views
