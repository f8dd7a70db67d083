#include "solver/formulation/curve_guards.h"

#include "model/bspline_curve.h"
#include "solver/formulation/point_combinations.h"

namespace devsurf::solver {

void addSpeedGuards(const model::CompositeSurface& surface,
                    const std::map<model::EdgeId, std::vector<int>>& edgeOffsets,
                    MinimumLengthTerm& speeds, std::vector<int>& curveStart) {
    for (const auto& [edge, offsets] : edgeOffsets) {
        const model::EdgeRecord& record = surface.edge(edge);
        const model::BSplineCurve curve =
            model::BSplineCurve::uniform(record.space, record.controlPoints);
        std::vector<double> samples =
            collocationValues(record.space.intervals, 3 * record.space.degree - 2);
        samples.push_back(0.0);
        samples.push_back(1.0);
        curveStart.push_back(speeds.rowCount());
        for (double u : samples) {
            const model::DeBoorRows rows = curve.deBoorRows(u);
            auto combination = [&](const std::vector<double>& coefficients) {
                PointCombination c;
                for (std::size_t i = 0; i < rows.indices.size(); ++i) {
                    c.push_back(
                        {offsets[static_cast<std::size_t>(rows.indices[i])], coefficients[i]});
                }
                return simplified(c);
            };
            speeds.addRow(simplified(plus(combination(rows.firstDerivative[1]),
                                          combination(rows.firstDerivative[0]), -1.0)),
                          0.0);
        }
    }
    curveStart.push_back(speeds.rowCount());
}

} // namespace devsurf::solver
