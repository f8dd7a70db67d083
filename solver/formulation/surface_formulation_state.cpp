// SurfaceFormulation's states: handle targets, writing a state back to the surface, the
// reference state (row scales, relative fairness, degeneracy guards) and the per-face
// residuals reported where a solve falls short.
#include "solver/formulation/surface_formulation.h"

#include "solver/core/bilinear_term.h"
#include "solver/core/bisector_term.h"
#include "solver/core/fairness_term.h"
#include "solver/core/minimum_length_term.h"
#include "solver/core/squared_distance_term.h"
#include "solver/core/target_term.h"
#include "solver/core/unit_norm_term.h"
#include "solver/formulation/perturbation.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>
#include <string>

namespace devsurf::solver {

using model::Vec3;
using model::VertexId;

namespace {

std::string str(std::uint32_t id) {
    return std::to_string(id);
}

// Lengths below this (in the state's coordinates) are treated as zero: no guard, no scale.
constexpr double kNegligibleLength = 1e-9;

} // namespace

void useRoughStartConfiguration(FormulationOptions& formulation, Options& solver) {
    formulation.normalizedRows = true;
    formulation.proximityWeight = 1.0;
    formulation.rulingGuard = 0.3;
    formulation.speedGuard = 0.15;
    formulation.guardWeight = 0.1;
    solver.proximityFactor = 1.0;
    solver.proximityMaximum = 1.0;
    solver.proximityThreshold = 1e-2;
    solver.eps2Minimum = 3e-4;
}

double stateUnit(const model::CompositeSurface& surface, double diameter,
                 double controlSpacingUnit) {
    if (!(diameter > 0.0) || !std::isfinite(diameter)) {
        return 1.0;
    }
    if (controlSpacingUnit > 0.0) {
        const double spacing = meanControlSpacing(surface) / controlSpacingUnit;
        if (spacing > 0.0 && spacing < diameter) {
            return spacing;
        }
    }
    return diameter;
}

void SurfaceFormulation::normaliseUnitNormals(double* x) const {
    // Every 3-block of these variable blocks is one unit normal (a row of "unitNormals").
    for (const char* name : {"coneNormals", "planeNormals", "osculatingNormals"}) {
        if (!m_problem.hasBlock(name)) {
            continue;
        }
        const VariableBlock& block = m_problem.block(name);
        for (int offset = block.offset; offset + 3 <= block.offset + block.size; offset += 3) {
            double* n = x + offset;
            const double length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
            if (length > 0.0 && std::isfinite(length)) {
                for (int k = 0; k < 3; ++k) {
                    n[k] /= length;
                }
            }
        }
    }
}

void SurfaceFormulation::addHandles(TargetTerm& handles, TargetTerm& controlPointHandles) {
    for (const VertexHandle& handle : m_options.handles) {
        const auto it = m_vertexPoint.find(handle.vertex);
        if (it == m_vertexPoint.end()) {
            throw std::invalid_argument("vertex " + str(handle.vertex) +
                                        " of a handle does not exist.");
        }
        const int offset = pointOffset(it->second);
        if (handle.fixed) {
            for (int k = 0; k < 3; ++k) {
                m_problem.setFixed(offset + k);
            }
            continue;
        }
        const Vec3 t = (handle.target - m_centre) / m_scale;
        const double target[3] = {t.x, t.y, t.z};
        m_handleRow[handle.vertex] = handles.addPointTarget(offset, 3, target);
    }
    for (const ControlPointHandle& handle : m_options.controlPointHandles) {
        const auto it = m_edgePoints.find(handle.edge);
        if (it == m_edgePoints.end() || handle.index < 1 ||
            handle.index + 1 >= static_cast<int>(it->second.size())) {
            throw std::invalid_argument("edge " + str(handle.edge) +
                                        " has no interior control point " +
                                        std::to_string(handle.index) + ".");
        }
        const Vec3 t = (handle.target - m_centre) / m_scale;
        const double target[3] = {t.x, t.y, t.z};
        m_controlHandleRow[{handle.edge, handle.index}] = controlPointHandles.addPointTarget(
            pointOffset(it->second[static_cast<std::size_t>(handle.index)]), 3, target);
    }
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

bool SurfaceFormulation::setControlPointTarget(model::EdgeId edge, int index, const Vec3& target) {
    auto it = m_controlHandleRow.find({edge, index});
    if (it == m_controlHandleRow.end() || !m_controlHandleTerm) {
        return false;
    }
    for (int k = 0; k < 3; ++k) {
        m_controlHandleTerm->setTarget(it->second + k, (target[k] - m_centre[k]) / m_scale);
    }
    return true;
}

bool SurfaceFormulation::setSheetHandleTarget(VertexId vertex, const model::Vec2& target) {
    return m_development.setPullTarget(vertex, target);
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
    std::vector<std::pair<VertexId, Vec3>> vertices;
    vertices.reserve(m_vertexPoint.size());
    for (const auto& [vertex, point] : m_vertexPoint) {
        vertices.emplace_back(vertex, positions[static_cast<std::size_t>(point)]);
    }
    surface.moveVertices(vertices);
    for (const auto& [edge, points] : m_edgePoints) {
        std::vector<Vec3> controls;
        controls.reserve(points.size());
        for (int p : points) {
            controls.push_back(positions[static_cast<std::size_t>(p)]);
        }
        surface.setControlPoints(edge, std::move(controls));
    }
    // A development confined to a sheet changes with the surface; a fixed one stays as it is.
    if (m_development.offset >= 0 && !m_options.fixedDevelopment && surface.keepsDevelopment()) {
        surface.setDevelopment(m_development.read(x).vertices);
    }
    return true;
}

void SurfaceFormulation::rebaseDevelopmentFairness(const std::vector<double>& x) {
    if (m_development.fairness && x.size() == m_initialState.size()) {
        m_development.fairness->setReference(x.data());
    }
}

void SurfaceFormulation::rebaseIsometry(const std::vector<double>& x) {
    if (!m_isometry) {
        return;
    }
    // As damping (FormulationOptions::lengthDampingWeight) a row measures the change of its
    // length, to first order, so a step pays for changing a length as for moving a point by as
    // much, whatever the length: the squared rows' Jacobians grow with the length, and damped
    // by them, a model of a few long segments (two cubic strips of one interval each) stopped
    // converging where one of many short ones needed that weight.
    const bool damping = isometryDamps();
    for (int row = 0; row < m_isometry->rowCount(); ++row) {
        const double length = m_isometry->leftLength(row, x.data());
        m_isometry->setSquaredDistance(row, length * length);
        if (damping) {
            m_isometry->setRowScale(row, length > kNegligibleLength ? 0.5 / length : 0.0);
        }
    }
}

void SurfaceFormulation::scaleIsometryWeight(double factor) {
    if (m_isometryFamily >= 0) {
        m_problem.setFamilyWeight(m_isometryFamily,
                                  m_problem.family(m_isometryFamily).weight * factor);
    }
}

void SurfaceFormulation::fadeDragEnergies(double factor, bool sheetPulls) {
    const FamilyId sheet = sheetPulls ? m_problem.findFamily("sheetPulls") : -1;
    for (const FamilyId family : {m_controlHandleEnergy, m_proximityEnergy, m_pullEnergy, sheet}) {
        if (family >= 0) {
            m_problem.setFamilyWeight(family, m_problem.family(family).weight * factor);
            m_problem.setFamilyDrivesEpsilon1(family, false);
        }
    }
}

void SurfaceFormulation::setReferenceState(const std::vector<double>& x) {
    if (x.size() != m_initialState.size()) {
        throw std::invalid_argument("the reference state has " + std::to_string(x.size()) +
                                    " values, expected " + std::to_string(m_initialState.size()) +
                                    ".");
    }
    if (m_creaseConditions && m_options.weighCreaseNormals) {
        m_creaseConditions->weighSidesAt(x.data());
    }
    const double* scaleAt = m_options.normalizedRows ? x.data() : nullptr;
    for (BilinearTerm* term : {m_developability, m_planarity, m_coneNormals, m_straightCreases}) {
        if (term) {
            term->scaleRowsAt(scaleAt);
        }
    }
    if (m_creaseConditions) {
        m_creaseConditions->scaleRowsAt(scaleAt);
    }
    if (m_proximity) {
        // Rows are created point by point, coordinate by coordinate, from the first point.
        for (int row = 0; row < m_proximity->rowCount(); ++row) {
            m_proximity->setTarget(row, x[static_cast<std::size_t>(m_pointsOffset + row)]);
        }
    }
    if (m_normalProximity) {
        for (int row = 0; row < m_normalProximity->rowCount(); ++row) {
            m_normalProximity->setTarget(row,
                                         x[static_cast<std::size_t>(m_normalControlsOffset + row)]);
        }
    }
    const double* reference = m_options.relativeFairness ? x.data() : nullptr;
    if (m_pointFairness) {
        m_pointFairness->setReference(reference);
    }
    if (m_normalFairness) {
        m_normalFairness->setReference(reference);
    }
    if (m_development.fairness) {
        m_development.fairness->setReference(reference);
    }
    if (m_unitControlNormals) {
        // Each control normal keeps its reference length (or, absolute, unit length).
        for (int row = 0; row < m_unitControlNormals->rowCount(); ++row) {
            double squared = 1.0;
            if (reference) {
                const double length = m_unitControlNormals->leftLength(row, x.data());
                squared = length * length;
            }
            m_unitControlNormals->setSquaredDistance(row, squared);
        }
    }
    // Rulings: a fraction of their reference length. Rulings of (nearly) zero length, such as
    // the pointed end of an SRS face, get no guard.
    if (m_rulingGuard) {
        for (int row = 0; row < m_rulingGuard->rowCount(); ++row) {
            const double length = m_rulingGuard->length(row, x.data());
            m_rulingGuard->setMinimum(
                row, length > kNegligibleLength ? m_options.rulingGuard * length : 0.0);
        }
    }
    // Speeds: a fraction of the smaller of the reference speed there and the curve's mean
    // reference speed, so a curve that already runs slowly somewhere is not pushed to speed up.
    if (m_speedGuard) {
        for (std::size_t c = 0; c + 1 < m_speedCurveStart.size(); ++c) {
            const int begin = m_speedCurveStart[c];
            const int end = m_speedCurveStart[c + 1];
            double sum = 0.0;
            for (int row = begin; row < end; ++row) {
                sum += m_speedGuard->length(row, x.data());
            }
            const double mean = end > begin ? sum / (end - begin) : 0.0;
            for (int row = begin; row < end; ++row) {
                const double speed = std::min(m_speedGuard->length(row, x.data()), mean);
                m_speedGuard->setMinimum(
                    row, speed > kNegligibleLength ? m_options.speedGuard * speed : 0.0);
            }
        }
    }
    if (isometryDamps()) {
        rebaseIsometry(x); // damping rows measure the change from x
    }
}

std::vector<SurfaceFormulation::FaceResidual>
SurfaceFormulation::faceResiduals(const std::vector<double>& x) const {
    std::map<model::FaceId, double> worst;
    auto collect = [&](const auto* term, const std::vector<model::FaceId>& faces) {
        if (!term || x.size() != m_initialState.size()) {
            return;
        }
        for (int row = 0; row < term->rowCount(); ++row) {
            const double residual = term->rowResidual(row, x.data());
            double& value = worst[faces[static_cast<std::size_t>(row)]];
            value = std::max(value, std::abs(residual));
        }
    };
    collect(m_developability, m_developabilityFaces);
    collect(m_planarity, m_planarityFaces);
    collect(m_creaseConditions, m_creaseFaces);
    collect(m_straightCreases, m_straightCreaseFaces);
    std::vector<FaceResidual> result;
    for (const auto& [face, residual] : worst) {
        result.push_back({face, residual});
    }
    std::stable_sort(
        result.begin(), result.end(),
        [](const FaceResidual& a, const FaceResidual& b) { return a.residual > b.residual; });
    return result;
}

} // namespace devsurf::solver
