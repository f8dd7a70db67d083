#include "crease_marks.h"

#include <algorithm>
#include <cmath>

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

std::vector<double> foldDashes(model::FoldAssignment fold) {
    switch (fold) {
    case model::FoldAssignment::Mountain:
        return {6.0, 2.0, 1.0, 2.0};
    case model::FoldAssignment::Valley:
        return {4.0, 2.0};
    case model::FoldAssignment::Flat:
        break;
    }
    return {};
}

std::vector<std::vector<model::Vec3>>
dashedPolylines(const std::vector<std::vector<model::Vec3>>& lines,
                const std::vector<double>& pattern) {
    if (pattern.empty() || pattern.size() % 2 != 0 ||
        !std::all_of(pattern.begin(), pattern.end(), [](double d) { return d > 0.0; })) {
        return lines;
    }
    std::vector<std::vector<model::Vec3>> dashes;
    for (const std::vector<model::Vec3>& line : lines) {
        if (line.empty()) {
            continue;
        }
        std::size_t k = 0;        // the pattern entry being drawn: even a dash, odd a gap
        double left = pattern[0]; // its length still to go
        std::vector<model::Vec3> dash{line.front()};
        for (std::size_t i = 0; i + 1 < line.size(); ++i) {
            const model::Vec3& a = line[i];
            const model::Vec3& b = line[i + 1];
            const double length = model::distance(a, b);
            if (!std::isfinite(length)) {
                continue;
            }
            double done = 0.0; // along this segment
            while (length - done > left) {
                done += left;
                const model::Vec3 p = a + (b - a) * (done / length);
                if (k % 2 == 0) {
                    dash.push_back(p);
                    dashes.push_back(std::move(dash));
                    dash.clear();
                } else {
                    dash.assign(1, p);
                }
                k = (k + 1) % pattern.size();
                left = pattern[k];
            }
            left -= length - done;
            if (k % 2 == 0) {
                dash.push_back(b);
            }
        }
        if (k % 2 == 0 && dash.size() >= 2) {
            dashes.push_back(std::move(dash));
        }
    }
    return dashes;
}

} // namespace devsurf::views
