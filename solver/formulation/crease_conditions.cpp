#include "crease_conditions.h"

#include "model/creases.h"
#include "model/sampled_mesh.h"
#include "solver/formulation/point_combinations.h"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace devsurf::solver {

namespace {

// Σ coefficients[i] · P[indices[i]] over the edge's control points.
PointCombination pointCombination(const std::vector<int>& offsets, const std::vector<int>& indices,
                                  const std::vector<double>& coefficients) {
    PointCombination c;
    for (std::size_t i = 0; i < indices.size(); ++i) {
        c.push_back({offsets.at(static_cast<std::size_t>(indices[i])), coefficients[i]});
    }
    return c;
}

// The oriented normal of one side at the crease parameter u (the strip's own parameter is
// 1 − u where its curve runs against the edge), times `sign`.
PointCombination sideNormal(const model::CreaseSide& side, const StripNormalSpline& normal,
                            double u, double sign) {
    const double s = side.reversed ? 1.0 - u : u;
    const model::DeBoorRows rows = normal.curve.deBoorRows(s);
    const double orientation = side.flipNormal ? -sign : sign;
    PointCombination c;
    for (std::size_t i = 0; i < rows.indices.size(); ++i) {
        c.push_back({normal.offset + 3 * rows.indices[i], orientation * rows.point[i]});
    }
    return c;
}

std::string edgeName(model::EdgeId edge) {
    return "edge " + std::to_string(edge);
}

} // namespace

int addCreaseConditions(const model::CompositeSurface& surface,
                        const std::vector<model::Strip>& strips,
                        const std::map<model::FaceId, StripNormalSpline>& normals,
                        const std::map<model::EdgeId, std::vector<int>>& edgePoints,
                        int valuesPerInterval, BilinearTerm& term,
                        std::vector<model::FaceId>& rowFaces) {
    // Every edge with a condition must be a crease between two strips.
    std::map<model::EdgeId, model::Crease> creases;
    bool any = false;
    for (const auto& [id, record] : surface.edges()) {
        any = any || (record.isSpline() && record.condition != model::CreaseCondition::None);
    }
    if (!any) {
        return 0;
    }
    for (const model::Crease& crease :
         model::creasesOf(surface, strips, model::sampleSurface(surface, 2))) {
        creases.emplace(crease.edge, crease);
    }
    int added = 0;
    for (const auto& [id, record] : surface.edges()) {
        if (!record.isSpline() || record.condition == model::CreaseCondition::None) {
            continue;
        }
        const std::string name = model::creaseConditionName(record.condition);
        const auto it = creases.find(id);
        if (it == creases.end()) {
            throw std::invalid_argument(edgeName(id) + " has the condition '" + name +
                                        "' but is a boundary curve, not a crease.");
        }
        if (record.condition == model::CreaseCondition::Straight) {
            throw std::invalid_argument(edgeName(id) +
                                        ": the condition 'straight when unfolded' is not solved "
                                        "yet; use curved-fold, geodesic or none.");
        }
        const model::Crease& crease = it->second;
        const auto left = normals.find(crease.left.face);
        const auto right = normals.find(crease.right.face);
        if (crease.left.strip == model::CreaseSide::kNoStrip ||
            crease.right.strip == model::CreaseSide::kNoStrip || left == normals.end() ||
            right == normals.end()) {
            throw std::invalid_argument(edgeName(id) + " has the condition '" + name +
                                        "' but a cone or planar patch lies beside it; crease "
                                        "conditions need a strip on either side.");
        }
        if (record.space.degree < 2) {
            throw std::invalid_argument(edgeName(id) + " has the condition '" + name +
                                        "' but its curve is of degree " +
                                        std::to_string(record.space.degree) +
                                        "; a crease condition needs degree 2 or more.");
        }
        const model::BSplineCurve curve =
            model::BSplineCurve::uniform(record.space, record.controlPoints);
        const std::vector<int>& offsets = edgePoints.at(id);
        // n_L + n_R for a curved fold, n_L − n_R for a geodesic.
        const double sign = record.condition == model::CreaseCondition::CurvedFold ? 1.0 : -1.0;
        const int intervals = record.space.intervals;
        for (int i = 0; i < intervals; ++i) {
            for (int j = 0; j < valuesPerInterval; ++j) {
                const double u = (i + (j + 0.5) / valuesPerInterval) / intervals;
                const model::DeBoorRows rows = curve.deBoorRows(u);
                const PointCombination n =
                    simplified(plus(sideNormal(crease.left, left->second, u, 1.0),
                                    sideNormal(crease.right, right->second, u, sign)));
                for (int k = 0; k < 2; ++k) {
                    const PointCombination d = simplified(
                        plus(pointCombination(offsets, rows.indices, rows.secondDerivative[k]),
                             pointCombination(offsets, rows.indices, rows.secondDerivative[k + 1]),
                             -1.0));
                    if (d.empty() || n.empty()) {
                        continue;
                    }
                    term.addRow(n, d);
                    rowFaces.push_back(crease.left.face);
                    ++added;
                }
            }
        }
    }
    return added;
}

} // namespace devsurf::solver
