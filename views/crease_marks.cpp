#include "crease_marks.h"

namespace devsurf::views {

model::Vec3 midpointByLength(const std::vector<model::Vec3>& points) {
    if (points.empty()) {
        return {};
    }
    double length = 0.0;
    for (std::size_t i = 0; i + 1 < points.size(); ++i) {
        length += model::distance(points[i], points[i + 1]);
    }
    double remaining = 0.5 * length;
    for (std::size_t i = 0; i + 1 < points.size(); ++i) {
        const double step = model::distance(points[i], points[i + 1]);
        if (step > 0.0 && remaining <= step) {
            const double t = remaining / step;
            return points[i] * (1.0 - t) + points[i + 1] * t;
        }
        remaining -= step;
    }
    return points.front();
}

std::vector<ConditionMark> conditionMarks(const std::vector<SurfaceScene>& scenes) {
    std::vector<ConditionMark> marks;
    for (const SurfaceScene& scene : scenes) {
        for (const EdgeCurve& edge : scene.edges) {
            if (edge.crease && edge.condition != model::CreaseCondition::None &&
                !edge.points.empty()) {
                marks.push_back(
                    {scene.surface, edge.id, edge.condition, midpointByLength(edge.points)});
            }
        }
    }
    return marks;
}

} // namespace devsurf::views
