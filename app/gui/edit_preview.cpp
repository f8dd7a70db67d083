#include "edit_preview.h"

#include "model/bspline_curve.h"

#include <algorithm>

namespace devsurf::app {

std::vector<std::vector<model::Vec3>> addedEdgeLines(const model::CompositeSurface& before,
                                                     const model::CompositeSurface& after,
                                                     model::EdgeLabel label) {
    constexpr int kSamplesPerInterval = 12;
    std::vector<std::vector<model::Vec3>> lines;
    for (const auto& [id, record] : after.edges()) {
        // A cut ruling keeps its id but ends at a new vertex; only wholly new edges are shown.
        if (before.hasEdge(id) || record.label != label) {
            continue;
        }
        if (!record.isSpline()) {
            lines.push_back({after.position(record.from), after.position(record.to)});
            continue;
        }
        const model::BSplineCurve curve =
            model::BSplineCurve::uniform(record.space, record.controlPoints);
        const int samples = kSamplesPerInterval * std::max(1, record.space.intervals);
        std::vector<model::Vec3> points;
        for (int i = 0; i <= samples; ++i) {
            const double u =
                curve.domainBegin() + (curve.domainEnd() - curve.domainBegin()) * i / samples;
            points.push_back(curve.evaluate(u));
        }
        lines.push_back(std::move(points));
    }
    return lines;
}

} // namespace devsurf::app
