#include "solver/formulation/surface_formulation.h"

#include "model/bspline_curve.h"
#include "model/model_error.h"
#include "model/strip.h"
#include "solver/core/bilinear_term.h"
#include "solver/core/bisector_term.h"
#include "solver/core/fairness_term.h"
#include "solver/core/linear_term.h"
#include "solver/core/minimum_length_term.h"
#include "solver/core/squared_distance_term.h"
#include "solver/core/target_term.h"
#include "solver/core/unit_norm_term.h"
#include "solver/formulation/crease_conditions.h"
#include "solver/formulation/curve_guards.h"
#include "solver/formulation/normal_spline_start.h"
#include "solver/formulation/point_combinations.h"
#include "solver/formulation/smooth_rulings.h"
#include "solver/formulation/strip_isometry.h"
#include "solver/formulation/vertex_developability.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <set>
#include <stdexcept>

namespace devsurf::solver {

using model::EdgeId;
using model::FaceId;
using model::FaceType;
using model::Vec3;
using model::VertexId;

namespace {

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
    std::unique_ptr<BisectorTerm> creaseConditions = std::make_unique<BisectorTerm>();
    std::unique_ptr<BilinearTerm> straightCreases = std::make_unique<BilinearTerm>(3);
    std::map<FaceId, StripNormalSpline> stripNormals; // per strip, for the crease conditions
    std::unique_ptr<LinearTerm> smoothness = std::make_unique<LinearTerm>();
    std::unique_ptr<SquaredDistanceTerm> vertexStars = std::make_unique<SquaredDistanceTerm>(2, 3);
    std::unique_ptr<MinimumLengthTerm> spokeGuard = std::make_unique<MinimumLengthTerm>(3);
    std::unique_ptr<TargetTerm> handles = std::make_unique<TargetTerm>();
    std::unique_ptr<TargetTerm> pointHandles = std::make_unique<TargetTerm>(); // soft, if any
    std::unique_ptr<TargetTerm> pulls = std::make_unique<TargetTerm>(); // soft vertex handles
    std::unique_ptr<TargetTerm> proximity = std::make_unique<TargetTerm>();
    std::unique_ptr<TargetTerm> normalProximity = std::make_unique<TargetTerm>();
    std::unique_ptr<FairnessTerm> fairness = std::make_unique<FairnessTerm>(3);
    std::unique_ptr<FairnessTerm> normalFairness = std::make_unique<FairnessTerm>(3);
    std::unique_ptr<SquaredDistanceTerm> isometry = std::make_unique<SquaredDistanceTerm>(3);
    std::unique_ptr<UnitNormTerm> unitControlNormals = std::make_unique<UnitNormTerm>(3);
    std::unique_ptr<MinimumLengthTerm> rulingGuard = std::make_unique<MinimumLengthTerm>(3);
    std::unique_ptr<MinimumLengthTerm> speedGuard = std::make_unique<MinimumLengthTerm>(3);

    std::vector<model::Strip> strips;
    std::vector<FaceId> planarFaces;
    int normalControlsOffset = 0;
    int coneNormalsOffset = 0;
    int planeNormalsOffset = 0;
    int derivativePointsOffset = 0;
    std::map<EdgeId, std::vector<int>> edgeOffsets; // collectEdgeOffsets

    int valuesPerInterval(const model::Strip& strip) const {
        return options.developabilityValuesPerInterval > 0 ? options.developabilityValuesPerInterval
                                                           : 3 * strip.a.degree() - 2;
    }

    model::SplineSpace normalSpace(const model::Strip& strip) const {
        return normalSplineSpace(surface.edge(strip.aSide.edge).space,
                                 options.exactNormalSpace &&
                                     developableStarts.count(strip.face) != 0);
    }

    // The strips for which isDevelopableStart holds, sampled once per strip in collect() (50
    // values per interval: most of the time a session on a large design took to build).
    std::set<FaceId> developableStarts;

    std::vector<int> sidePoints(const model::StripSide& side) const { return f.sidePoints(side); }

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
            throw model::ModelError(problems.front());
        }
        for (const auto& [id, loop] : surface.faces()) {
            (void)loop;
            const FaceType type = surface.faceType(id);
            if (type == FaceType::Planar) {
                planarFaces.push_back(id);
            } else {
                strips.push_back(model::stripOfFace(surface, id));
                if (isDevelopableStart(strips.back(), options.developableStartLimit)) {
                    developableStarts.insert(id);
                }
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
            f.m_scale = stateUnit(surface, (high - low).norm(), options.controlSpacingUnit);
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
                normalControls += normalSpace(strip).controlPointCount(false);
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

    bool touchesCreaseCondition(const model::Strip& strip) const {
        for (const model::StripSide& side : {strip.aSide, strip.bSide}) {
            if (side.edge != model::kInvalidId &&
                surface.edge(side.edge).condition != model::CreaseCondition::None) {
                return true;
            }
        }
        return false;
    }

    // The R-edges of a strip or cone face, each with the end (u = 0 or 1) it is the ruling of,
    // its normal oriented like the face loop (the curve a runs into the face from u = 0).
    void registerRulingNormals(const model::Strip& strip, VertexId startVertex,
                               const PointCombination& atStart, const PointCombination& atEnd) {
        for (EdgeId edge : surface.faceEdges(strip.face)) {
            const model::EdgeRecord& record = surface.edge(edge);
            if (record.isSpline()) {
                continue;
            }
            const bool atU0 = record.from == startVertex || record.to == startVertex;
            const Vec3 inward = atU0 ? strip.a.derivative(0.0, 1) : -strip.a.derivative(1.0, 1);
            f.m_rulingNormals[{strip.face, edge}] = orientedRulingNormal(
                surface, strip.face, edge, atU0 ? atStart : atEnd, inward, f.m_initialState);
        }
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
                setVector(offset, initialStripNormal(strip, u));
                (i == 0 ? first : last) = n;
            }
            registerRulingNormals(strip, a0, first, last);
            return;
        }
        const std::vector<int> bPoints = sidePoints(strip.bSide);
        const model::SplineSpace space = normalSpace(strip);
        const int controls = space.controlPointCount(false);
        const int normalOffset = normalControlsOffset + 3 * normalControl;
        normalControl += controls;
        const model::BSplineCurve normalCurve = model::BSplineCurve::uniform(
            space, std::vector<Vec3>(static_cast<std::size_t>(controls)));
        stripNormals[strip.face] = {normalOffset, normalCurve};

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
            // (4): ⟨n, b¹₁ − a¹₁⟩ = ⟨n, a¹₁ − a¹₀⟩ = ⟨n, b¹₁ − b¹₀⟩ = 0. A side that is
            // identically zero (b¹₁ − b¹₀ where b is the point of an SRS face) gives no row.
            for (const PointCombination& side :
                 {simplified(plus(b11, a11, -1.0)), simplified(plus(a11, a10, -1.0)),
                  simplified(plus(b11, b10, -1.0))}) {
                if (!side.empty()) {
                    developability->addRow(n, side);
                    f.m_developabilityFaces.push_back(strip.face);
                }
            }
        }
        // The rulings at the collocation values and the ends, guarded against collapsing
        // (their minimum lengths are set by setReferenceState).
        std::vector<double> rulings = values;
        rulings.push_back(0.0);
        rulings.push_back(1.0);
        for (double u : rulings) {
            const model::DeBoorRows ra = strip.a.deBoorRows(u);
            const model::DeBoorRows rb = strip.b.deBoorRows(u);
            rulingGuard->addRow(simplified(plus(combination(aPoints, ra.indices, ra.point),
                                                combination(bPoints, rb.indices, rb.point), -1.0)),
                                0.0);
        }

        // n(0)ᵀn(0) = 1 hard, unit control normals soft.
        const PointCombination n0 = evaluation(normalOffset, normalCurve.deBoorRows(0.0));
        const PointCombination n1 = evaluation(normalOffset, normalCurve.deBoorRows(1.0));
        // The hard unit length at u = 0, or at u = 1 where the start normal nearly vanishes at
        // u = 0 (the tip of an SRS face, where N = 0).
        std::vector<double> samples = values;
        samples.push_back(0.0);
        samples.push_back(1.0);
        const std::vector<Vec3> fitted =
            fitStartNormals(strip, normalCurve, samples, developableStarts.count(strip.face) != 0,
                            options.linearNoisyStartNormals);
        const model::BSplineCurve startNormal = model::BSplineCurve::uniform(space, fitted);
        const bool unitAtStart =
            startNormal.evaluate(0.0).norm() >= 1e-3 * startNormal.evaluate(1.0).norm();
        unitNormals->addVector(unitAtStart ? n0 : n1);
        std::vector<int> normalSequence;
        for (int i = 0; i < controls; ++i) {
            unitControlNormals->addVector(normalOffset + 3 * i);
            normalSequence.push_back(normalOffset + 3 * i);
        }
        // Fairness of the normal spline's control sequence (its own family, see
        // FormulationOptions::normalFairnessWeight and normalFairnessAtCreaseConditions).
        if (options.normalFairnessAtCreaseConditions || !touchesCreaseCondition(strip)) {
            normalFairness->addSequence(normalSequence);
        }

        // Initial control normals (see fitStartNormals).
        for (int i = 0; i < controls; ++i) {
            setVector(normalOffset + 3 * i, fitted[static_cast<std::size_t>(i)]);
        }
        registerRulingNormals(strip, a0, n0, n1);
    }

    void addStrips() {
        int normalControl = 0;
        int coneNormal = 0;
        int derivativePoint = 0;
        for (const model::Strip& strip : strips) {
            addStrip(strip, normalControl, coneNormal, derivativePoint);
        }
    }

    // State offsets of every coarse vertex, once the points are placed.
    std::map<VertexId, int> vertexOffsets() const {
        std::map<VertexId, int> offsets;
        for (const auto& [vertex, point] : f.m_vertexPoint) {
            offsets[vertex] = f.pointOffset(point);
        }
        return offsets;
    }

    // State offsets of every S-edge's control points (stored orientation), once the points
    // are placed.
    void collectEdgeOffsets() {
        for (const auto& [edge, points] : f.m_edgePoints) {
            std::vector<int>& o = edgeOffsets[edge];
            for (int point : points) {
                o.push_back(f.pointOffset(point));
            }
        }
    }

    // (7), (8) and "straight when unfolded" on the creases that carry such a condition
    // (docs/math.md §5), at as many values per interval as (4) uses on a strip.
    void addCreaseConditions() {
        const int values = strips.empty() ? 7 : valuesPerInterval(strips.front());
        CreaseConditionTerms terms{*creaseConditions, f.m_creaseFaces, *straightCreases,
                                   f.m_straightCreaseFaces};
        solver::addCreaseConditions(surface, strips, stripNormals, edgeOffsets, values, terms,
                                    {f.m_problem, f.m_initialState, *unitNormals});
    }

    // Vertex developability at the interior vertices where creases meet (docs/math.md §7).
    void addVertexDevelopability() {
        if (!options.vertexDevelopability) {
            return;
        }
        solver::addVertexDevelopability(surface, vertexOffsets(), edgeOffsets, f.m_problem,
                                        f.m_initialState, *vertexStars, *spokeGuard, options);
    }

    // The development as variables (§5, eq. 12), fixed where it is kept as given.
    void addDevelopment() {
        if (options.developmentSamplesPerInterval > 0) {
            const std::vector<model::Vec2>& start = options.developmentStart;
            const DevelopmentOptions development{options.developmentSamplesPerInterval,
                                                 start.empty() ? nullptr : &start,
                                                 options.fixedDevelopment,
                                                 options.developmentWeight,
                                                 options.developmentFairnessWeight,
                                                 options.developmentDomain,
                                                 options.sheetHandles,
                                                 options.sheetHandleWeight};
            f.m_development =
                solver::addDevelopment(surface, development, vertexOffsets(), edgeOffsets,
                                       f.m_scale, f.m_problem, f.m_initialState);
        }
    }

    // RR…R faces: ⟨n_f, v_{i+1} − v_i⟩ = 0 for every edge, |n_f| = 1 (docs/math.md §3).
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
                f.m_planarityFaces.push_back(face);
            }
            setVector(offset, normalised(newell));
            unitNormals->addVector(offset);
            for (EdgeId edge : surface.faceEdges(face)) {
                f.m_rulingNormals[{face, edge}] = PointCombination{{offset, 1.0}};
            }
        }
    }

    void addSmoothRulings() {
        solver::addSmoothRulings(surface, options.smoothRulings, f.m_rulingNormals, *smoothness);
    }

    // Every point towards the reference state (targets set by setReferenceState).
    void addProximity() {
        if (options.proximityWeight <= 0.0) {
            return;
        }
        const double zero[3] = {0.0, 0.0, 0.0};
        for (int i = 0; i < f.m_pointCount; ++i) {
            proximity->addPointTarget(f.pointOffset(i), 3, zero);
        }
        const VariableBlock& block = f.m_problem.block("normalControls");
        f.m_normalControlsOffset = block.offset;
        for (int i = 0; i < block.size; i += 3) {
            if (options.normalProximityWeight > 0.0) {
                normalProximity->addPointTarget(block.offset + i, 3, zero);
            }
        }
    }

    // Fairness of every curve's control points; the isometry of every strip's control net. A
    // crease held on a curve drawn in the sheet takes its shape from that curve: its fairness,
    // pulling it straight against the curve, made the iteration alternate (docs/tuning.md).
    void addFairness() {
        const model::SheetDomain& sheet = options.developmentDomain;
        const bool curvesHold = options.developmentSamplesPerInterval > 0 &&
                                !options.fixedDevelopment && !sheet.isFree();
        for (const auto& [edge, points] : edgeOffsets) {
            if (!(curvesHold && sheet.creaseCurveOf.count(edge) != 0)) {
                fairness->addSequence(points);
            }
        }
        if (options.isometryWeight > 0.0 || options.lengthDampingWeight > 0.0) {
            addStripIsometry(strips, edgeOffsets, f.m_initialState, *isometry);
        }
    }

    void hand() {
        Problem& p = f.m_problem;
        f.m_developability = developability->rowCount() > 0 ? developability.get() : nullptr;
        f.m_planarity = planarity->rowCount() > 0 ? planarity.get() : nullptr;
        f.m_coneNormals = normalDefinitions->rowCount() > 0 ? normalDefinitions.get() : nullptr;
        f.m_creaseConditions = creaseConditions->rowCount() > 0 ? creaseConditions.get() : nullptr;
        f.m_straightCreases = straightCreases->rowCount() > 0 ? straightCreases.get() : nullptr;
        f.m_pointFairness = fairness->rowCount() > 0 ? fairness.get() : nullptr;
        f.m_normalFairness = normalFairness->rowCount() > 0 ? normalFairness.get() : nullptr;
        f.m_unitControlNormals =
            unitControlNormals->rowCount() > 0 ? unitControlNormals.get() : nullptr;
        const bool rulings = options.rulingGuard > 0.0 && rulingGuard->rowCount() > 0;
        const bool speeds = options.speedGuard > 0.0 && speedGuard->rowCount() > 0;
        f.m_rulingGuard = rulings ? rulingGuard.get() : nullptr;
        f.m_speedGuard = speeds ? speedGuard.get() : nullptr;
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
        if (const double w = options.creaseWeight; f.m_creaseConditions || f.m_straightCreases) {
            const FamilyId id = p.addFamily("creaseConditions", TermRole::Constraint, w); // both
            p.add(id, std::move(creaseConditions));
            p.add(id, std::move(straightCreases));
        }
        add("smoothRulings", TermRole::Constraint, options.smoothnessWeight, std::move(smoothness));
        add("vertexDevelopability", TermRole::Constraint, options.vertexDevelopabilityWeight,
            std::move(vertexStars));
        add("vertexSpokeGuard", TermRole::Constraint, options.vertexDevelopabilityWeight,
            std::move(spokeGuard));
        TargetTerm* hard = handles->rowCount() > 0 ? handles.get() : nullptr;
        f.m_handleTerm = pulls->rowCount() > 0 ? pulls.get() : hard;
        f.m_controlHandleTerm = pointHandles->rowCount() > 0 ? pointHandles.get() : hard;
        add("handles", TermRole::Constraint, options.handleWeight, std::move(handles));
        if (pulls->rowCount() > 0) {
            add("pulls", TermRole::Energy, options.pulledHandleWeight, std::move(pulls));
            f.m_pullEnergy = p.findFamily("pulls");
            p.setFamilyDrivesEpsilon1(f.m_pullEnergy, true);
        }
        if (pointHandles->rowCount() > 0) {
            add("creaseHandles", TermRole::Energy, options.controlPointHandleWeight,
                std::move(pointHandles));
            f.m_controlHandleEnergy = p.findFamily("creaseHandles");
            p.setFamilyDrivesEpsilon1(f.m_controlHandleEnergy, true);
        }
        if (rulings) {
            add("rulingGuard", TermRole::Constraint, options.guardWeight, std::move(rulingGuard));
        }
        if (speeds) {
            add("speedGuard", TermRole::Constraint, options.guardWeight, std::move(speedGuard));
        }
        if (proximity->rowCount() > 0) {
            f.m_proximity = proximity.get();
        }
        const bool pull = options.proximityEnergyWeight > 0.0; // else weighted by μ
        add("proximity", pull ? TermRole::Energy : TermRole::Proximity,
            pull ? options.proximityEnergyWeight : options.proximityWeight, std::move(proximity));
        f.m_proximityEnergy = pull && f.m_proximity ? p.findFamily("proximity") : -1;
        if (normalProximity->rowCount() > 0) {
            f.m_normalProximity = normalProximity.get();
        }
        add("normalProximity", TermRole::Proximity, options.normalProximityWeight,
            std::move(normalProximity));
        add("fairness", TermRole::Energy, options.fairnessWeight, std::move(fairness));
        f.m_isometry = isometry->rowCount() > 0 ? isometry.get() : nullptr;
        const bool energy = options.isometryWeight > 0.0; // else damping (lengthDampingWeight)
        add("isometry", energy ? TermRole::Energy : TermRole::Damping,
            energy ? options.isometryWeight : options.lengthDampingWeight, std::move(isometry));
        f.m_isometryFamily = f.m_isometry ? p.findFamily("isometry") : -1;
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
    builder.collectEdgeOffsets();
    builder.allocateNormals();
    builder.addStrips();
    if (m_options.approximation) {
        addApproximationFit(surface, builder.strips, builder.stripNormals);
    }
    builder.addCreaseConditions();
    builder.addPlanarFaces();
    builder.addSmoothRulings();
    builder.addVertexDevelopability();
    builder.addDevelopment();
    addHandles(m_options.pulledHandleWeight > 0.0 ? *builder.pulls : *builder.handles,
               m_options.controlPointHandleWeight > 0.0 ? *builder.pointHandles : *builder.handles);
    addSpeedGuards(surface, builder.edgeOffsets, *builder.speedGuard, m_speedCurveStart);
    builder.addProximity();
    builder.addFairness();
    builder.hand();
    if (m_approximation) {
        m_approximationFamilies =
            addApproximation(*m_approximation, m_options.approximationWeights, m_problem);
    }
    if (!m_options.curvePairs.empty()) {
        addCurvePairs(surface);
    }
    setReferenceState(m_initialState);
}

std::vector<int> SurfaceFormulation::sidePoints(const model::StripSide& side) const {
    std::vector<int> points = m_edgePoints.at(side.edge);
    if (side.reversed) {
        std::reverse(points.begin(), points.end());
    }
    return points;
}

} // namespace devsurf::solver
