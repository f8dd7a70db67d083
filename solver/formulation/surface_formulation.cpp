#include "solver/formulation/surface_formulation.h"

#include "model/bspline_curve.h"
#include "model/strip.h"
#include "solver/core/bilinear_term.h"
#include "solver/core/fairness_term.h"
#include "solver/core/linear_term.h"
#include "solver/core/target_term.h"
#include "solver/core/unit_norm_term.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <stdexcept>

namespace devsurf::solver {

using model::EdgeId;
using model::FaceId;
using model::FaceType;
using model::Vec3;
using model::VertexId;

namespace {

// Merges repeated offsets and drops zero coefficients, so that Jacobian rows stay short.
PointCombination simplified(const PointCombination& in) {
    PointCombination out;
    for (const PointTerm& t : in) {
        auto it = std::find_if(out.begin(), out.end(),
                               [&t](const PointTerm& o) { return o.offset == t.offset; });
        if (it == out.end()) {
            out.push_back(t);
        } else {
            it->coefficient += t.coefficient;
        }
    }
    out.erase(std::remove_if(out.begin(), out.end(),
                             [](const PointTerm& t) { return t.coefficient == 0.0; }),
              out.end());
    return out;
}

PointCombination plus(PointCombination a, const PointCombination& b, double scale = 1.0) {
    for (const PointTerm& t : b) {
        a.push_back({t.offset, scale * t.coefficient});
    }
    return a;
}

std::string str(std::uint32_t id) {
    return std::to_string(id);
}

// The u values of the collocation of (4): `count` distinct interior values per interval.
std::vector<double> collocationValues(int intervals, int count) {
    std::vector<double> values;
    for (int i = 0; i < intervals; ++i) {
        for (int j = 0; j < count; ++j) {
            values.push_back((i + (j + 0.5) / count) / intervals);
        }
    }
    return values;
}

Vec3 normalised(const Vec3& v) {
    const double length = v.norm();
    return length > 0.0 ? v / length : v;
}

} // namespace

// Everything the constructor assembles before the terms are handed to the problem.
struct SurfaceFormulation::Builder {
    Builder(SurfaceFormulation& formulation, const model::CompositeSurface& s,
            const FormulationOptions& o)
        : f(formulation), surface(s), options(o) {}

    SurfaceFormulation& f;
    const model::CompositeSurface& surface;
    const FormulationOptions& options;

    std::unique_ptr<BilinearTerm> developability = std::make_unique<BilinearTerm>(3);
    std::unique_ptr<LinearTerm> derivativeDefinitions = std::make_unique<LinearTerm>();
    std::unique_ptr<UnitNormTerm> unitNormals = std::make_unique<UnitNormTerm>(3);
    std::unique_ptr<BilinearTerm> normalDefinitions = std::make_unique<BilinearTerm>(3);
    std::unique_ptr<BilinearTerm> planarity = std::make_unique<BilinearTerm>(3);
    std::unique_ptr<LinearTerm> smoothness = std::make_unique<LinearTerm>();
    std::unique_ptr<TargetTerm> handles = std::make_unique<TargetTerm>();
    std::unique_ptr<FairnessTerm> fairness = std::make_unique<FairnessTerm>(3);
    std::unique_ptr<FairnessTerm> normalFairness = std::make_unique<FairnessTerm>(3);
    std::unique_ptr<UnitNormTerm> unitControlNormals = std::make_unique<UnitNormTerm>(3);

    std::vector<model::Strip> strips;
    std::vector<FaceId> planarFaces;
    int normalControlsOffset = 0;
    int coneNormalsOffset = 0;
    int planeNormalsOffset = 0;
    int derivativePointsOffset = 0;

    int valuesPerInterval(const model::Strip& strip) const {
        return options.developabilityValuesPerInterval > 0 ? options.developabilityValuesPerInterval
                                                           : 3 * strip.a.degree() - 2;
    }

    // Point indices of a strip side's curve in the order the strip traverses it.
    std::vector<int> sidePoints(const model::StripSide& side) const {
        std::vector<int> points = f.m_edgePoints.at(side.edge);
        if (side.reversed) {
            std::reverse(points.begin(), points.end());
        }
        return points;
    }

    VertexId startVertex(const model::StripSide& side) const {
        const model::EdgeRecord& record = surface.edge(side.edge);
        return side.reversed ? record.to : record.from;
    }

    PointCombination combination(const std::vector<int>& points, const std::vector<int>& indices,
                                 const std::vector<double>& coefficients) const {
        PointCombination c;
        for (std::size_t i = 0; i < indices.size(); ++i) {
            c.push_back(
                {f.pointOffset(points[static_cast<std::size_t>(indices[i])]), coefficients[i]});
        }
        return simplified(c);
    }

    static PointCombination evaluation(int offset, const model::DeBoorRows& rows) {
        PointCombination c;
        for (std::size_t i = 0; i < rows.indices.size(); ++i) {
            c.push_back({offset + 3 * rows.indices[i], rows.point[i]});
        }
        return simplified(c);
    }

    void collect() {
        if (const auto problems = surface.validate(); !problems.empty()) {
            throw std::invalid_argument("the surface is not valid: " + problems.front());
        }
        for (const auto& [id, loop] : surface.faces()) {
            (void)loop;
            const FaceType type = surface.faceType(id);
            if (type == FaceType::Planar) {
                planarFaces.push_back(id);
            } else {
                strips.push_back(model::stripOfFace(surface, id));
            }
        }
    }

    void addPoints() {
        Vec3 low(std::numeric_limits<double>::max(), std::numeric_limits<double>::max(),
                 std::numeric_limits<double>::max());
        Vec3 high = -low;
        auto extend = [&](const Vec3& p) {
            for (int k = 0; k < 3; ++k) {
                low[k] = std::min(low[k], p[k]);
                high[k] = std::max(high[k], p[k]);
            }
        };
        for (const auto& [id, position] : surface.vertices()) {
            f.m_vertexPoint[id] = static_cast<int>(f.m_originalPoints.size());
            f.m_originalPoints.push_back(position);
            extend(position);
        }
        for (const auto& [id, record] : surface.edges()) {
            if (!record.isSpline()) {
                continue;
            }
            std::vector<int> points{f.m_vertexPoint.at(record.from)};
            for (std::size_t i = 1; i + 1 < record.controlPoints.size(); ++i) {
                points.push_back(static_cast<int>(f.m_originalPoints.size()));
                f.m_originalPoints.push_back(record.controlPoints[i]);
                extend(record.controlPoints[i]);
            }
            points.push_back(f.m_vertexPoint.at(record.to));
            f.m_edgePoints[id] = std::move(points);
        }
        f.m_pointCount = static_cast<int>(f.m_originalPoints.size());
        if (f.m_pointCount > 0) {
            f.m_centre = (low + high) * 0.5;
            const double diameter = (high - low).norm();
            f.m_scale = diameter > 0.0 && std::isfinite(diameter) ? diameter : 1.0;
        }
        f.m_pointsOffset = f.m_problem.addVariableBlock("points", 3 * f.m_pointCount);
    }

    void allocateNormals() {
        int normalControls = 0;
        int coneNormals = 0;
        int derivativePoints = 0;
        for (const model::Strip& strip : strips) {
            const int intervals = surface.edge(strip.aSide.edge).space.intervals;
            if (strip.isCone()) {
                coneNormals += intervals + 1;
                ++f.m_coneCount;
            } else {
                normalControls += intervals + 3;
                derivativePoints += 4 * intervals * valuesPerInterval(strip);
                ++f.m_stripCount;
            }
        }
        f.m_planarCount = static_cast<int>(planarFaces.size());
        normalControlsOffset = f.m_problem.addVariableBlock("normalControls", 3 * normalControls);
        coneNormalsOffset = f.m_problem.addVariableBlock("coneNormals", 3 * coneNormals);
        planeNormalsOffset = f.m_problem.addVariableBlock("planeNormals", 3 * f.m_planarCount);
        if (options.auxiliaryDerivativePoints) {
            derivativePointsOffset =
                f.m_problem.addVariableBlock("derivativePoints", 3 * derivativePoints);
        }
        f.m_initialState.assign(static_cast<std::size_t>(f.m_problem.variableCount()), 0.0);
        for (int i = 0; i < f.m_pointCount; ++i) {
            const Vec3& p = f.m_originalPoints[static_cast<std::size_t>(i)];
            for (int k = 0; k < 3; ++k) {
                f.m_initialState[static_cast<std::size_t>(f.pointOffset(i) + k)] =
                    (p[k] - f.m_centre[k]) / f.m_scale;
            }
        }
    }

    void setVector(int offset, const Vec3& v) {
        for (int k = 0; k < 3; ++k) {
            f.m_initialState[static_cast<std::size_t>(offset + k)] = v[k];
        }
    }

    // The R-edges of a strip or cone face, each with the end (u = 0 or 1) it is the ruling of.
    void registerRulingNormals(FaceId face, VertexId startVertex, const PointCombination& atStart,
                               const PointCombination& atEnd) {
        for (EdgeId edge : surface.faceEdges(face)) {
            const model::EdgeRecord& record = surface.edge(edge);
            if (record.isSpline()) {
                continue;
            }
            const bool atU0 = record.from == startVertex || record.to == startVertex;
            f.m_rulingNormals[{face, edge}] = atU0 ? atStart : atEnd;
        }
    }

    // An initial unit normal of a strip at u: a′ × (b − a), which points to the side the face
    // loop orients (stripOfFace runs a along the loop and b against it), so neighbouring
    // strips start consistently oriented (MATH.md §2, §5).
    static Vec3 stripNormal(const model::Strip& strip, double u) {
        const Vec3 tangent = strip.a.derivative(u, 1);
        Vec3 n = cross(tangent, strip.bPoint(u) - strip.aPoint(u));
        if (n.norm() < 1e-12 * (1.0 + tangent.squaredNorm()) && !strip.isCone()) {
            n = cross(tangent, strip.b.derivative(u, 1)); // a collapsed ruling (SRS end)
        }
        return normalised(n);
    }

    void addStrip(const model::Strip& strip, int& normalControl, int& coneNormal,
                  int& derivativePoint) {
        const std::vector<int> aPoints = sidePoints(strip.aSide);
        const VertexId a0 = startVertex(strip.aSide);
        const int intervals = surface.edge(strip.aSide.edge).space.intervals;
        if (strip.isCone()) {
            // Cones need no condition (§3.1); their normals at the interval ends exist for
            // smooth transitions, defined by ⟨n, a′⟩ = ⟨n, apex − a⟩ = 0 and |n| = 1.
            const int apex = f.pointOffset(f.m_vertexPoint.at(strip.apexVertex));
            PointCombination first;
            PointCombination last;
            for (int i = 0; i <= intervals; ++i) {
                const double u = static_cast<double>(i) / intervals;
                const model::DeBoorRows rows = strip.a.deBoorRows(u);
                const int offset = coneNormalsOffset + 3 * coneNormal++;
                const PointCombination n{{offset, 1.0}};
                const PointCombination tangent =
                    plus(combination(aPoints, rows.indices, rows.firstDerivative[1]),
                         combination(aPoints, rows.indices, rows.firstDerivative[0]), -1.0);
                const PointCombination toApex =
                    plus({{apex, 1.0}}, combination(aPoints, rows.indices, rows.point), -1.0);
                normalDefinitions->addRow(n, simplified(tangent));
                normalDefinitions->addRow(n, simplified(toApex));
                unitNormals->addVector(offset);
                setVector(offset, stripNormal(strip, u));
                (i == 0 ? first : last) = n;
            }
            registerRulingNormals(strip.face, a0, first, last);
            return;
        }
        const std::vector<int> bPoints = sidePoints(strip.bSide);
        const model::SplineSpace normalSpace{3, 2, intervals};
        const int controls = intervals + 3;
        const int normalOffset = normalControlsOffset + 3 * normalControl;
        normalControl += controls;
        const model::BSplineCurve normalCurve = model::BSplineCurve::uniform(
            normalSpace, std::vector<Vec3>(static_cast<std::size_t>(controls)));

        // (4) at 3m − 2 values per interval.
        const std::vector<double> values = collocationValues(intervals, valuesPerInterval(strip));
        for (double u : values) {
            const model::DeBoorRows ra = strip.a.deBoorRows(u);
            const model::DeBoorRows rb = strip.b.deBoorRows(u);
            const PointCombination n = evaluation(normalOffset, normalCurve.deBoorRows(u));
            PointCombination a10 = combination(aPoints, ra.indices, ra.firstDerivative[0]);
            PointCombination a11 = combination(aPoints, ra.indices, ra.firstDerivative[1]);
            PointCombination b10 = combination(bPoints, rb.indices, rb.firstDerivative[0]);
            PointCombination b11 = combination(bPoints, rb.indices, rb.firstDerivative[1]);
            if (options.auxiliaryDerivativePoints) {
                PointCombination* points[4] = {&a10, &a11, &b10, &b11};
                for (PointCombination* p : points) {
                    const int offset = derivativePointsOffset + 3 * derivativePoint++;
                    derivativeDefinitions->addPointRelation(3, plus({{offset, 1.0}}, *p, -1.0));
                    double value[3] = {0.0, 0.0, 0.0};
                    for (const PointTerm& t : *p) {
                        for (int k = 0; k < 3; ++k) {
                            value[k] += t.coefficient *
                                        f.m_initialState[static_cast<std::size_t>(t.offset + k)];
                        }
                    }
                    setVector(offset, Vec3(value[0], value[1], value[2]));
                    *p = PointCombination{{offset, 1.0}};
                }
            }
            // (4): ⟨n, b¹₁ − a¹₁⟩ = ⟨n, a¹₁ − a¹₀⟩ = ⟨n, b¹₁ − b¹₀⟩ = 0.
            developability->addRow(n, simplified(plus(b11, a11, -1.0)));
            developability->addRow(n, simplified(plus(a11, a10, -1.0)));
            developability->addRow(n, simplified(plus(b11, b10, -1.0)));
        }

        // n(0)ᵀn(0) = 1 hard, unit control normals soft.
        const PointCombination n0 = evaluation(normalOffset, normalCurve.deBoorRows(0.0));
        const PointCombination n1 = evaluation(normalOffset, normalCurve.deBoorRows(1.0));
        unitNormals->addVector(n0);
        std::vector<int> normalSequence;
        for (int i = 0; i < controls; ++i) {
            unitControlNormals->addVector(normalOffset + 3 * i);
            normalSequence.push_back(normalOffset + 3 * i);
        }
        // Fairness of the normal spline's control sequence (its own family, see
        // FormulationOptions::normalFairnessWeight).
        normalFairness->addSequence(normalSequence);
        registerRulingNormals(strip.face, a0, n0, n1);

        // Initial control normals, fitted by least squares to N(u) = a′ × (b − a) sampled at
        // the collocation values and the ends. If N itself lies in the normal spline's space
        // (e.g. a generalised cylinder over a cubic) its exact fit, scaled to |n(0)| = 1, is
        // kept and the strip stays put. Otherwise the unit field N/|N| is fitted: it gives every
        // row of (4) the same scale from the start, whereas on a noisy start |N| varies by
        // orders of magnitude along a strip and fitting N made the first steps large where |N|
        // is large (measured: 10× the initial residual).
        std::vector<double> samples = values;
        samples.push_back(0.0);
        samples.push_back(1.0);
        std::vector<Vec3> field;
        double typical = 0.0;
        for (double u : samples) {
            field.push_back(cross(strip.a.derivative(u, 1), strip.bPoint(u) - strip.aPoint(u)));
            typical = std::max(typical, field.back().norm());
        }
        const auto rowCount = static_cast<Eigen::Index>(samples.size());
        Eigen::MatrixXd basis = Eigen::MatrixXd::Zero(rowCount, controls);
        Eigen::MatrixXd unitField(rowCount, 3);
        Eigen::MatrixXd scaledField(rowCount, 3); // N / |N(0)|, used only if N is regular
        const double startLength = field[field.size() - 2].norm();
        bool regularEverywhere = typical > 0.0;
        for (std::size_t s = 0; s < samples.size(); ++s) {
            const auto row = static_cast<Eigen::Index>(s);
            const model::DeBoorRows rows = normalCurve.deBoorRows(samples[s]);
            for (std::size_t i = 0; i < rows.indices.size(); ++i) {
                basis(row, rows.indices[i]) += rows.point[i];
            }
            // A degenerate sample (a collapsed ruling) gets a unit normal from a′ × b′.
            const bool regular = field[s].norm() > 1e-9 * typical;
            regularEverywhere = regularEverywhere && regular;
            const Vec3 unit = regular ? field[s] / field[s].norm() : stripNormal(strip, samples[s]);
            for (int k = 0; k < 3; ++k) {
                unitField(row, k) = unit[k];
                scaledField(row, k) = field[s][k] / startLength;
            }
        }
        const Eigen::MatrixXd normal =
            basis.transpose() * basis + 1e-12 * Eigen::MatrixXd::Identity(controls, controls);
        const Eigen::LDLT<Eigen::MatrixXd> factor = normal.ldlt();
        Eigen::MatrixXd fitted;
        bool exactFit = false;
        if (regularEverywhere) {
            fitted = factor.solve(basis.transpose() * scaledField);
            const double misfit = (basis * fitted - scaledField).cwiseAbs().maxCoeff();
            exactFit = misfit <= 1e-9 * scaledField.cwiseAbs().maxCoeff();
        }
        if (!exactFit) {
            fitted = factor.solve(basis.transpose() * unitField);
        }
        for (int i = 0; i < controls; ++i) {
            setVector(normalOffset + 3 * i, Vec3(fitted(i, 0), fitted(i, 1), fitted(i, 2)));
        }
    }

    void addStrips() {
        int normalControl = 0;
        int coneNormal = 0;
        int derivativePoint = 0;
        for (const model::Strip& strip : strips) {
            addStrip(strip, normalControl, coneNormal, derivativePoint);
        }
    }

    // RR…R faces: ⟨n_f, v_{i+1} − v_i⟩ = 0 for every edge, |n_f| = 1 (MATH.md §3).
    void addPlanarFaces() {
        for (std::size_t i = 0; i < planarFaces.size(); ++i) {
            const FaceId face = planarFaces[i];
            const auto& loop = surface.faceLoop(face);
            const int offset = planeNormalsOffset + 3 * static_cast<int>(i);
            Vec3 newell;
            for (std::size_t k = 0; k < loop.size(); ++k) {
                const Vec3& p = surface.position(loop[k]);
                const Vec3& q = surface.position(loop[(k + 1) % loop.size()]);
                newell += cross(p, q);
                const int from = f.pointOffset(f.m_vertexPoint.at(loop[k]));
                const int to = f.pointOffset(f.m_vertexPoint.at(loop[(k + 1) % loop.size()]));
                planarity->addRow({{offset, 1.0}}, {{to, 1.0}, {from, -1.0}});
            }
            setVector(offset, normalised(newell));
            unitNormals->addVector(offset);
            for (EdgeId edge : surface.faceEdges(face)) {
                f.m_rulingNormals[{face, edge}] = PointCombination{{offset, 1.0}};
            }
        }
    }

    void addSmoothRulings() {
        for (EdgeId edge : options.smoothRulings) {
            if (!surface.hasEdge(edge) || surface.edge(edge).isSpline()) {
                throw std::invalid_argument("edge " + str(edge) +
                                            " is not a ruling (R-edge) of the surface.");
            }
            const std::vector<FaceId> faces = surface.facesOfEdge(edge);
            if (faces.size() != 2) {
                throw std::invalid_argument("ruling " + str(edge) +
                                            " is on the boundary; a smooth transition needs a "
                                            "face on either side.");
            }
            const PointCombination& left = f.m_rulingNormals.at({faces[0], edge});
            const PointCombination& right = f.m_rulingNormals.at({faces[1], edge});
            smoothness->addPointRelation(3, simplified(plus(left, right, -1.0)));
        }
    }

    void addHandles() {
        for (const VertexHandle& handle : options.handles) {
            auto it = f.m_vertexPoint.find(handle.vertex);
            if (it == f.m_vertexPoint.end()) {
                throw std::invalid_argument("vertex " + str(handle.vertex) +
                                            " of a handle does not exist.");
            }
            const int offset = f.pointOffset(it->second);
            if (handle.fixed) {
                for (int k = 0; k < 3; ++k) {
                    f.m_problem.setFixed(offset + k);
                }
                continue;
            }
            double target[3];
            for (int k = 0; k < 3; ++k) {
                target[k] = (handle.target[k] - f.m_centre[k]) / f.m_scale;
            }
            f.m_handleRow[handle.vertex] = handles->addPointTarget(offset, 3, target);
        }
    }

    void addFairness() {
        for (const auto& [edge, points] : f.m_edgePoints) {
            (void)edge;
            std::vector<int> offsets;
            for (int p : points) {
                offsets.push_back(f.pointOffset(p));
            }
            fairness->addSequence(offsets);
        }
    }

    void hand() {
        Problem& p = f.m_problem;
        auto add = [&p](const std::string& name, TermRole role, double weight, auto term) {
            if (term->rowCount() > 0) {
                p.add(p.addFamily(name, role, weight), std::move(term));
            }
        };
        add("developability", TermRole::Constraint, options.developabilityWeight,
            std::move(developability));
        add("derivativePoints", TermRole::Constraint, options.developabilityWeight,
            std::move(derivativeDefinitions));
        add("unitNormals", TermRole::Constraint, options.normalWeight, std::move(unitNormals));
        add("coneNormals", TermRole::Constraint, options.normalWeight,
            std::move(normalDefinitions));
        add("planarity", TermRole::Constraint, options.planarityWeight, std::move(planarity));
        add("smoothRulings", TermRole::Constraint, options.smoothnessWeight, std::move(smoothness));
        if (handles->rowCount() > 0) {
            f.m_handleTerm = handles.get();
        }
        add("handles", TermRole::Constraint, options.handleWeight, std::move(handles));
        add("fairness", TermRole::Energy, options.fairnessWeight, std::move(fairness));
        add("normalFairness", TermRole::Energy, options.normalFairnessWeight,
            std::move(normalFairness));
        add("unitControlNormals", TermRole::Energy, options.unitControlNormalWeight,
            std::move(unitControlNormals));
    }
};

SurfaceFormulation::SurfaceFormulation(const model::CompositeSurface& surface,
                                       const FormulationOptions& options)
    : m_options(options) {
    Builder builder(*this, surface, m_options);
    builder.collect();
    builder.addPoints();
    builder.allocateNormals();
    builder.addStrips();
    builder.addPlanarFaces();
    builder.addSmoothRulings();
    builder.addHandles();
    builder.addFairness();
    builder.hand();
}

bool SurfaceFormulation::setHandleTarget(VertexId vertex, const Vec3& target) {
    auto it = m_handleRow.find(vertex);
    if (it == m_handleRow.end() || !m_handleTerm) {
        return false;
    }
    for (int k = 0; k < 3; ++k) {
        m_handleTerm->setTarget(it->second + k, (target[k] - m_centre[k]) / m_scale);
    }
    return true;
}

Vec3 SurfaceFormulation::toModel(const double* p) const {
    return Vec3(m_centre.x + m_scale * p[0], m_centre.y + m_scale * p[1],
                m_centre.z + m_scale * p[2]);
}

Vec3 SurfaceFormulation::vertexPosition(const std::vector<double>& x, VertexId vertex) const {
    const int point = m_vertexPoint.at(vertex);
    const auto offset = static_cast<std::size_t>(pointOffset(point));
    if (std::equal(x.begin() + static_cast<std::ptrdiff_t>(offset),
                   x.begin() + static_cast<std::ptrdiff_t>(offset + 3),
                   m_initialState.begin() + static_cast<std::ptrdiff_t>(offset))) {
        return m_originalPoints[static_cast<std::size_t>(point)];
    }
    return toModel(x.data() + offset);
}

bool SurfaceFormulation::writeBack(const std::vector<double>& x, model::CompositeSurface& surface,
                                   std::string* error) const {
    auto fail = [error](const std::string& message) {
        if (error) {
            *error = message;
        }
        return false;
    };
    if (x.size() != m_initialState.size()) {
        return fail("the solver state has " + std::to_string(x.size()) + " values, expected " +
                    std::to_string(m_initialState.size()) + ".");
    }
    for (std::size_t i = 0; i < x.size(); ++i) {
        if (!std::isfinite(x[i])) {
            return fail("the solver state contains a non-finite value (variable " +
                        std::to_string(i) + "); the surface was left unchanged.");
        }
    }
    for (const auto& [vertex, point] : m_vertexPoint) {
        (void)point;
        if (!surface.hasVertex(vertex)) {
            return fail("the surface has no vertex " + str(vertex) + " any more.");
        }
    }
    for (const auto& [edge, points] : m_edgePoints) {
        if (!surface.hasEdge(edge) || !surface.edge(edge).isSpline() ||
            surface.edge(edge).controlPoints.size() != points.size()) {
            return fail("the S-edge " + str(edge) + " of the surface has changed.");
        }
    }
    std::vector<Vec3> positions(static_cast<std::size_t>(m_pointCount));
    for (int i = 0; i < m_pointCount; ++i) {
        const auto offset = static_cast<std::size_t>(pointOffset(i));
        const bool unchanged = x[offset] == m_initialState[offset] &&
                               x[offset + 1] == m_initialState[offset + 1] &&
                               x[offset + 2] == m_initialState[offset + 2];
        positions[static_cast<std::size_t>(i)] =
            unchanged ? m_originalPoints[static_cast<std::size_t>(i)] : toModel(&x[offset]);
    }
    for (const auto& [vertex, point] : m_vertexPoint) {
        surface.moveVertex(vertex, positions[static_cast<std::size_t>(point)]);
    }
    for (const auto& [edge, points] : m_edgePoints) {
        std::vector<Vec3> controls;
        controls.reserve(points.size());
        for (int p : points) {
            controls.push_back(positions[static_cast<std::size_t>(p)]);
        }
        surface.setControlPoints(edge, std::move(controls));
    }
    return true;
}

} // namespace devsurf::solver
