#include "crease_conditions.h"

#include "model/creases.h"
#include "model/derived_geometry.h"
#include "model/model_error.h"
#include "model/sampled_mesh.h"
#include "solver/formulation/point_combinations.h"

#include <algorithm>
#include <cmath>
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

// The start value of n_o at crease parameter u: the unit normal of the osculating plane, or where
// the crease is locally straight a unit vector normal to its tangent and to the left strip's
// normal (docs/math.md §5).
model::Vec3 startOsculatingNormal(const model::BSplineCurve& curve, const model::Strip& left,
                                  const model::CreaseSide& side, double u) {
    const model::DeBoorPoints points = curve.deBoorPoints(u);
    const model::Vec3 d0 = points.secondDerivativePoints[0] - points.secondDerivativePoints[1];
    const model::Vec3 d1 = points.secondDerivativePoints[1] - points.secondDerivativePoints[2];
    const model::Vec3 o = cross(d0, d1);
    if (o.norm() > 1e-8 * d0.norm() * d1.norm()) {
        return o / o.norm();
    }
    model::Vec3 tangent = curve.derivative(u, 1);
    const double s = side.reversed ? 1.0 - u : u;
    const model::Vec3 normal = cross(left.a.derivative(s, 1), left.bPoint(s) - left.aPoint(s));
    model::Vec3 candidate = cross(normal, tangent);
    if (candidate.norm() <= 1e-12 * normal.norm() * tangent.norm()) {
        // No usable strip normal: any unit vector normal to the tangent.
        const model::Vec3 axis =
            std::abs(tangent.x) < std::abs(tangent.y) ? model::Vec3(1, 0, 0) : model::Vec3(0, 1, 0);
        candidate = cross(tangent, axis);
    }
    const double length = candidate.norm();
    return length > 0.0 ? candidate / length : model::Vec3(0, 0, 1);
}

} // namespace

int addCreaseConditions(const model::CompositeSurface& surface,
                        const std::vector<model::Strip>& strips,
                        const std::map<model::FaceId, StripNormalSpline>& normals,
                        const std::map<model::EdgeId, std::vector<int>>& edgePoints,
                        int valuesPerInterval, CreaseConditionTerms& terms,
                        const OsculatingNormals& osculating) {
    // Every edge with a condition must be a crease between two strips.
    std::map<model::EdgeId, model::Crease> creases;
    bool any = false;
    for (const auto& [id, record] : surface.edges()) {
        any = any || (record.isSpline() && record.condition != model::CreaseCondition::None);
    }
    if (!any) {
        return 0;
    }
    for (const model::Crease& crease : model::DerivedGeometry::of(surface, 2)->creases()) {
        creases.emplace(crease.edge, crease);
    }
    // Straight creases are formulated after the others, once their normals' block exists.
    struct StraightRows {
        model::EdgeId edge;
        PointCombination normal; // n_L
        PointCombination d[2];   // c²₀ − c²₁, c²₁ − c²₂
        model::Vec3 start;       // n_o at the start
    };
    std::vector<StraightRows> straight;
    int added = 0;
    for (const auto& [id, record] : surface.edges()) {
        if (!record.isSpline() || record.condition == model::CreaseCondition::None) {
            continue;
        }
        const auto it = creases.find(id);
        if (it == creases.end()) {
            throw model::ModelError(
                model::edgeProblem(model::ProblemCode::ConditionOnBoundary, id));
        }
        const model::Crease& crease = it->second;
        const auto left = normals.find(crease.left.face);
        const auto right = normals.find(crease.right.face);
        if (crease.left.strip == model::CreaseSide::kNoStrip ||
            crease.right.strip == model::CreaseSide::kNoStrip || left == normals.end() ||
            right == normals.end()) {
            throw model::ModelError(
                model::edgeProblem(model::ProblemCode::ConditionBesideNonStrip, id));
        }
        if (record.space.degree < 2) {
            model::Problem problem =
                model::edgeProblem(model::ProblemCode::ConditionNeedsDegree, id);
            problem.count = record.space.degree;
            throw model::ModelError(problem);
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
                PointCombination d[2];
                for (int k = 0; k < 2; ++k) {
                    d[k] = simplified(
                        plus(pointCombination(offsets, rows.indices, rows.secondDerivative[k]),
                             pointCombination(offsets, rows.indices, rows.secondDerivative[k + 1]),
                             -1.0));
                }
                if (record.condition == model::CreaseCondition::Straight) {
                    straight.push_back(
                        {id,
                         simplified(sideNormal(crease.left, left->second, u, 1.0)),
                         {d[0], d[1]},
                         startOsculatingNormal(curve, strips[crease.left.strip], crease.left, u)});
                    continue;
                }
                const PointCombination n = sideNormal(crease.left, left->second, u, 1.0);
                const PointCombination m = sideNormal(crease.right, right->second, u, sign);
                for (int k = 0; k < 2; ++k) {
                    if (d[k].empty()) {
                        continue;
                    }
                    terms.bisector.addRow(n, m, d[k]);
                    terms.bisectorFaces.push_back(crease.left.face);
                    ++added;
                }
            }
        }
    }
    if (straight.empty()) {
        return added;
    }
    const int first = osculating.problem.addVariableBlock("osculatingNormals",
                                                          3 * static_cast<int>(straight.size()));
    osculating.state.resize(static_cast<std::size_t>(osculating.problem.variableCount()), 0.0);
    for (std::size_t i = 0; i < straight.size(); ++i) {
        const StraightRows& r = straight[i];
        const int offset = first + 3 * static_cast<int>(i);
        const PointCombination no{{offset, 1.0}};
        for (int k = 0; k < 3; ++k) {
            osculating.state[static_cast<std::size_t>(offset + k)] = r.start[k];
        }
        osculating.unitNormals.addVector(offset);
        const model::FaceId face = creases.at(r.edge).left.face;
        for (const PointCombination* side : {&r.d[0], &r.d[1], &r.normal}) {
            if (!side->empty()) {
                terms.straight.addRow(no, *side);
                terms.straightFaces.push_back(face);
                ++added;
            }
        }
    }
    return added;
}

} // namespace devsurf::solver
