#include "bench_models.h"

#include "model/examples.h"
#include "model/math_constants.h"

#include <algorithm>
#include <cmath>

namespace devsurf::bench {

using model::Vec3;

using devsurf::model::kPi;

model::CompositeSurface makeTwoStripSheet(int intervals, double bow) {
    const double width = 300.0;
    const double height = 100.0;
    const model::SplineSpace space{3, 2, intervals};
    model::CompositeSurface s;
    s.setName("two-strips");
    model::VertexId left[3];
    model::VertexId right[3];
    for (int j = 0; j < 3; ++j) {
        left[j] = s.addVertex({0.0, height * j, 0.0});
        right[j] = s.addVertex({width, height * j, 0.0});
    }
    for (int j = 0; j < 2; ++j) {
        s.addFace({left[j], right[j], right[j + 1], left[j + 1]});
    }
    // Control points at the Greville abscissae of the clamped knot vector: a straight line
    // parametrised exactly like the built-in sheet's creases.
    const std::vector<double> knots = space.knots(false);
    const int count = space.controlPointCount(false);
    for (int j = 0; j < 3; ++j) {
        std::vector<Vec3> points;
        for (int i = 0; i < count; ++i) {
            double greville = 0.0;
            for (int k = 1; k <= space.degree; ++k) {
                greville += knots[static_cast<std::size_t>(i + k)];
            }
            const double x = width * greville / space.degree;
            const double y = height * j + (j == 1 ? bow * std::sin(kPi * x / width) : 0.0);
            points.push_back({x, y, 0.0});
        }
        points.front() = s.position(left[j]);
        points.back() = s.position(right[j]);
        const model::EdgeId edge = s.setSpline(left[j], right[j], space, points);
        if (j == 1 && bow != 0.0) {
            s.setCreaseCondition(edge, model::CreaseCondition::CurvedFold);
        }
    }
    return s;
}

std::vector<BenchModel> benchModels(const std::vector<std::string>& names) {
    auto wanted = [&names](const std::string& name) {
        return names.empty() || std::find(names.begin(), names.end(), name) != names.end();
    };
    std::vector<BenchModel> models;
    if (wanted("fig8-sheet")) {
        models.push_back({"fig8-sheet",
                          model::makeExample("sheet", 3).surfaces.front(),
                          {"8", 60, 9, 6147, 4.7e-5, 1.6e-4, 0.06}});
    }
    if (wanted("fig13-two-strips")) {
        models.push_back(
            {"fig13-two-strips", makeTwoStripSheet(9), {"13", 36, 2, 3795, 1.4e-4, 4.4e-4, 0.04}});
    }
    if (wanted("fig12-annulus")) {
        models.push_back({"fig12-annulus",
                          model::makeExample("annulus", 6).surfaces.front(),
                          {"12", 270, 48, 29574, 1.8e-3, 5.8e-3, 0.36}});
    }
    if (wanted("large-annulus")) {
        models.push_back({"large-annulus",
                          model::makeExample("annulus", 30).surfaces.front(),
                          {"15a", 320, 32, 39648, 7.2e-5, 7.5e-4, 0.8}});
    }
    return models;
}

} // namespace devsurf::bench
