#include "development_terms.h"

#include "model/bspline_curve.h"
#include "solver/formulation/domain_terms.h"
#include "solver/formulation/point_combinations.h"

#include <algorithm>
#include <memory>
#include <stdexcept>

namespace devsurf::solver {

namespace {

// A point of a combination of 3D state points at x.
model::Vec3 valueOf(const PointCombination& c, const std::vector<double>& x) {
    model::Vec3 p;
    for (const PointTerm& t : c) {
        const auto o = static_cast<std::size_t>(t.offset);
        p = p + model::Vec3(x[o], x[o + 1], x[o + 2]) * t.coefficient;
    }
    return p;
}

// Every mesh vertex as a linear evaluation of the state: coarse vertices are points; samples
// of an S-edge, which model::sampleSurface takes at u = i / (intervals · samples) of the
// uniform curve in stored orientation, are de Boor combinations of its control points.
std::vector<PointCombination>
meshVertexCombinations(const model::CompositeSurface& surface, const model::SampledMesh& mesh,
                       int samplesPerInterval, const std::map<model::VertexId, int>& vertexOffsets,
                       const std::map<model::EdgeId, std::vector<int>>& edgeOffsets) {
    std::vector<PointCombination> combinations(mesh.vertices.size());
    for (std::size_t i = 0; i < mesh.coarseVertexIds.size(); ++i) {
        combinations[i] = {{vertexOffsets.at(mesh.coarseVertexIds[i]), 1.0}};
    }
    for (const model::SampledMesh::Polyline& line : mesh.splineEdges) {
        const model::EdgeRecord& record = surface.edge(line.edge);
        const std::vector<int>& offsets = edgeOffsets.at(line.edge);
        const model::BSplineCurve curve =
            model::BSplineCurve::uniform(record.space, record.controlPoints);
        const int count = record.space.intervals * samplesPerInterval;
        for (int k = 1; k < count; ++k) {
            const model::DeBoorRows rows = curve.deBoorRows(static_cast<double>(k) / count);
            PointCombination c;
            for (std::size_t j = 0; j < rows.indices.size(); ++j) {
                c.push_back({offsets.at(static_cast<std::size_t>(rows.indices[j])), rows.point[j]});
            }
            combinations[static_cast<std::size_t>(line.vertices[static_cast<std::size_t>(k)])] =
                simplified(c);
        }
    }
    return combinations;
}

} // namespace

model::Development DevelopmentVariables::read(const std::vector<double>& x) const {
    model::Development development;
    development.vertices.reserve(mesh.vertices.size());
    for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
        const auto o = static_cast<std::size_t>(offset) + 2 * i;
        development.vertices.push_back(origin + model::Vec2(x[o], x[o + 1]) * scale);
    }
    development.components = 1;
    return development;
}

bool DevelopmentVariables::setPullTarget(model::VertexId vertex, const model::Vec2& target) {
    const auto it = pullRow.find(vertex);
    if (it == pullRow.end() || pulls == nullptr) {
        return false;
    }
    const model::Vec2 p = (target - origin) * (1.0 / scale);
    pulls->setTarget(it->second, p.x);
    pulls->setTarget(it->second + 1, p.y);
    return true;
}

DevelopmentVariables addDevelopment(const model::CompositeSurface& surface,
                                    const DevelopmentOptions& options,
                                    const std::map<model::VertexId, int>& vertexOffsets,
                                    const std::map<model::EdgeId, std::vector<int>>& edgeOffsets,
                                    double scale, Problem& problem, std::vector<double>& state) {
    const int samplesPerInterval = options.samplesPerInterval;
    const std::vector<model::Vec2>* start = options.start;
    auto isometry = std::make_unique<SquaredDistanceTerm>(2, 3);
    auto fairness = std::make_unique<FairnessTerm>(2);
    DevelopmentVariables result;
    result.mesh = model::sampleSurface(surface, samplesPerInterval);
    result.scale = scale;
    const model::SampledMesh& mesh = result.mesh;
    std::vector<model::Vec2> flat;
    if (start != nullptr) {
        if (start->size() != mesh.vertices.size()) {
            throw std::invalid_argument("the kept development has " +
                                        std::to_string(start->size()) + " vertices, the mesh " +
                                        std::to_string(mesh.vertices.size()));
        }
        flat = *start;
    } else {
        flat = model::unfoldSampledMesh(mesh).vertices;
    }
    for (const model::Vec2& p : flat) {
        result.origin = result.origin + p * (1.0 / static_cast<double>(flat.size()));
    }
    const std::vector<PointCombination> points =
        meshVertexCombinations(surface, mesh, samplesPerInterval, vertexOffsets, edgeOffsets);

    result.offset =
        problem.addVariableBlock("development", 2 * static_cast<int>(mesh.vertices.size()));
    state.resize(static_cast<std::size_t>(problem.variableCount()), 0.0);
    for (std::size_t i = 0; i < flat.size(); ++i) {
        const model::Vec2 p = (flat[i] - result.origin) * (1.0 / scale);
        state[static_cast<std::size_t>(result.offset) + 2 * i] = p.x;
        state[static_cast<std::size_t>(result.offset) + 2 * i + 1] = p.y;
    }
    // Around a cylinder (Fig. 14) the copy is periodic: a face or curve across the cut reads
    // some of its vertices shifted by whole periods, a fixed pair of variables, so that it lies
    // together; the shifts are those of the start, which no iteration moves by half a period.
    const std::optional<model::Vec2> period = model::domainPeriod(options.domain);
    int periodOffset = -1;
    if (period) {
        periodOffset = problem.addVariableBlock("developmentPeriod", 2);
        state.resize(static_cast<std::size_t>(problem.variableCount()), 0.0);
        state[static_cast<std::size_t>(periodOffset)] = period->x / scale;
        state[static_cast<std::size_t>(periodOffset) + 1] = period->y / scale;
        problem.setBlockFixed("developmentPeriod");
    }
    auto shiftOf = [&](int near, int vertex) {
        return model::periodShift(flat[static_cast<std::size_t>(near)],
                                  flat[static_cast<std::size_t>(vertex)], period);
    };
    auto flatOf = [&result](int vertex) {
        return PointCombination{{result.offset + 2 * vertex, 1.0}};
    };
    for (const std::vector<int>& face : mesh.faces) {
        for (std::size_t i = 0; i < face.size(); ++i) {
            for (std::size_t j = i + 1; j < face.size(); ++j) {
                const int a = face[i];
                const int b = face[j];
                const PointCombination space =
                    simplified(plus(points[static_cast<std::size_t>(a)],
                                    points[static_cast<std::size_t>(b)], -1.0));
                const double length = valueOf(space, state).norm();
                if (!(length > 0.0)) {
                    continue; // coincident samples (a pointed end): no pair to keep
                }
                PointCombination inSheet = plus(flatOf(a), flatOf(b), -1.0);
                const int shifts = shiftOf(face[0], a) - shiftOf(face[0], b);
                if (shifts != 0) {
                    inSheet.push_back({periodOffset, static_cast<double>(shifts)});
                }
                const int row = isometry->addRow(inSheet, space, 0.0);
                isometry->setRowScale(row, 1.0 / (length * length));
            }
        }
    }
    for (const model::SampledMesh::Polyline& line : mesh.splineEdges) {
        // Split where a curve crosses the cut: its second differences there would span a period.
        std::vector<int> offsets;
        for (std::size_t k = 0; k < line.vertices.size(); ++k) {
            if (k > 0 && shiftOf(line.vertices[k - 1], line.vertices[k]) != 0) {
                if (offsets.size() >= 3) {
                    fairness->addSequence(offsets);
                }
                offsets.clear();
            }
            offsets.push_back(result.offset + 2 * line.vertices[k]);
        }
        if (offsets.size() >= 3) {
            fairness->addSequence(offsets);
        }
    }
    const FamilyId family = problem.addFamily("development", TermRole::Constraint, options.weight);
    problem.setFamilyJudgedApart(family, true);
    problem.add(family, std::move(isometry));
    if (!options.pulls.empty()) {
        auto pulls = std::make_unique<TargetTerm>();
        const std::vector<model::VertexId>& coarse = mesh.coarseVertexIds;
        for (const SheetHandle& handle : options.pulls) {
            // Coarse vertices come first in the sampled mesh.
            const auto it = std::find(coarse.begin(), coarse.end(), handle.vertex);
            if (it == coarse.end() || result.pullRow.count(handle.vertex) != 0) {
                throw std::invalid_argument("vertex " + std::to_string(handle.vertex) +
                                            " of the sheet does not exist.");
            }
            const int index = static_cast<int>(it - coarse.begin());
            const model::Vec2 p = (handle.target - result.origin) * (1.0 / scale);
            const double xy[2] = {p.x, p.y};
            result.pullRow[handle.vertex] = pulls->addPointTarget(result.offset + 2 * index, 2, xy);
        }
        const FamilyId pullFamily =
            problem.addFamily("sheetPulls", TermRole::Energy, options.pullWeight);
        problem.setFamilyDrivesEpsilon1(pullFamily, true);
        result.pulls = problem.add(pullFamily, std::move(pulls));
    }
    if (options.fixed) {
        problem.setBlockFixed("development");
        return result;
    }
    if (fairness->rowCount() > 0) {
        result.fairness = problem.add(
            problem.addFamily("developmentFairness", TermRole::Energy, options.fairnessWeight),
            std::move(fairness));
    }
    addDomain(options.domain, result, problem, state);
    return result;
}

} // namespace devsurf::solver
