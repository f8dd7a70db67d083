#include "solver/session/solve_session.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <set>
#include <stdexcept>
#include <string>

namespace devsurf::solver {

namespace {

bool isFinite(const model::Vec3& p) {
    return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
}

// Throws if a coordinate of the surface is not finite (the solver would only fail later).
void requireFiniteGeometry(const model::CompositeSurface& surface) {
    for (const auto& [id, position] : surface.vertices()) {
        if (!isFinite(position)) {
            throw std::invalid_argument("vertex " + std::to_string(id) +
                                        " has a coordinate that is not a finite number.");
        }
    }
    for (const auto& [id, edge] : surface.edges()) {
        for (const model::Vec3& point : edge.controlPoints) {
            if (!isFinite(point)) {
                throw std::invalid_argument("edge " + std::to_string(id) +
                                            " has a control point that is not a finite number.");
            }
        }
    }
}

} // namespace

Options defaultSessionSolverOptions() {
    Options options;
    options.eps2 = 1e-3;
    return options;
}

SolveSession::SolveSession(const model::CompositeSurface& surface,
                           const std::vector<VertexHandle>& pulled, const SessionOptions& options)
    : m_options(options), m_surface(surface) {
    requireFiniteGeometry(surface);
    std::vector<VertexHandle>& handles = m_options.formulation.handles;
    std::set<model::VertexId> handled;
    for (const VertexHandle& handle : handles) {
        handled.insert(handle.vertex);
    }
    for (model::VertexId vertex : surface.pinnedVertices()) {
        if (handled.insert(vertex).second) {
            handles.push_back({vertex, true, {}});
        } else {
            // A pinned vertex is fixed, whatever the options said.
            for (VertexHandle& handle : handles) {
                if (handle.vertex == vertex) {
                    handle.fixed = true;
                }
            }
        }
    }
    for (const VertexHandle& handle : pulled) {
        if (!surface.hasVertex(handle.vertex)) {
            throw std::invalid_argument("there is no vertex " + std::to_string(handle.vertex) +
                                        " to pull.");
        }
        if (!isFinite(handle.target)) {
            throw std::invalid_argument("the target of vertex " + std::to_string(handle.vertex) +
                                        " is not a finite point.");
        }
        if (surface.isPinned(handle.vertex) || !handled.insert(handle.vertex).second) {
            continue;
        }
        handles.push_back({handle.vertex, false, handle.target});
        m_pulled.push_back(handle.vertex);
    }
    m_formulation = std::make_unique<SurfaceFormulation>(surface, m_options.formulation);
    m_x = m_formulation->initialState();
}

SolveSession::~SolveSession() = default;

bool SolveSession::setHandleTarget(model::VertexId vertex, const model::Vec3& target) {
    if (!isFinite(target) ||
        std::find(m_pulled.begin(), m_pulled.end(), vertex) == m_pulled.end()) {
        return false;
    }
    return m_formulation->setHandleTarget(vertex, target);
}

Summary SolveSession::step(int n, const std::atomic<bool>* cancel,
                           const std::function<void(const IterationStats&)>& perIteration) {
    const auto start = std::chrono::steady_clock::now();
    Summary total;
    total.status = Status::IterationLimit;
    total.variables = m_formulation->problem().variableCount();
    Options options = m_options.solver;
    options.maxIterations = 1;
    options.cancel = nullptr;
    options.progress = nullptr;
    options.recordIterations = true;
    bool improved = false;
    for (int i = 0; i < n; ++i) {
        if (cancel && cancel->load()) {
            total.status = Status::Cancelled;
            total.message = "cancelled";
            break;
        }
        // One iteration per solve() call, the schedule continued from the iterations done:
        // the same arithmetic whether the caller asks for one iteration or many.
        options.scheduleOffset = m_iterationsDone;
        const Summary summary = m_projection.solve(m_formulation->problem(), m_x, options);
        if (i == 0) {
            total.initialMaxConstraintResidual = summary.initialMaxConstraintResidual;
            total.initialEnergy = summary.initialEnergy;
            total.finalMaxConstraintResidual = summary.initialMaxConstraintResidual;
            total.finalEnergy = summary.initialEnergy;
            total.structureReused = summary.structureReused;
        }
        total.rows = summary.rows;
        total.jacobianNonZeros = summary.jacobianNonZeros;
        total.normalMatrixNonZeros = summary.normalMatrixNonZeros;
        total.supernodal = summary.supernodal;
        total.factorizedInPlace = summary.factorizedInPlace;
        total.analysisMs += summary.analysisMs;
        if (!summary.succeeded() || summary.iterations.empty()) {
            total.status = summary.succeeded() ? Status::InvalidProblem : summary.status;
            total.message =
                summary.message.empty() ? "the iteration did not complete" : summary.message;
            break;
        }
        ++m_iterationsDone;
        improved = true;
        IterationStats stats = summary.iterations.front();
        stats.iteration = i;
        total.iterations.push_back(stats);
        total.iterationsCompleted = i + 1;
        total.finalMaxConstraintResidual = summary.finalMaxConstraintResidual;
        total.finalEnergy = summary.finalEnergy;
        if (perIteration) {
            perIteration(stats);
        }
    }
    if (improved) {
        std::string error;
        if (!m_formulation->writeBack(m_x, m_surface, &error)) {
            total.status = Status::NonFiniteValue;
            total.message = error;
        }
    }
    total.tolerance = m_options.solver.reportTolerance;
    total.toleranceReached = total.finalMaxConstraintResidual <= total.tolerance;
    total.totalMs =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    return total;
}

std::vector<SurfaceFormulation::FaceResidual> SolveSession::worstFaces() const {
    return m_formulation->faceResiduals(m_x);
}

} // namespace devsurf::solver
