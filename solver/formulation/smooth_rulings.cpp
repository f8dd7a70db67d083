#include "solver/formulation/smooth_rulings.h"

#include "solver/formulation/point_combinations.h"

#include <set>
#include <stdexcept>
#include <string>

namespace devsurf::solver {

PointCombination orientedRulingNormal(const model::CompositeSurface& surface, model::FaceId face,
                                      model::EdgeId edge, const PointCombination& normal,
                                      const model::Vec3& inward, const std::vector<double>& state) {
    const model::EdgeRecord& record = surface.edge(edge);
    const std::vector<model::VertexId>& loop = surface.faceLoop(face);
    bool along = false; // the loop runs from → to
    for (std::size_t i = 0; i < loop.size(); ++i) {
        along = along || (loop[i] == record.from && loop[(i + 1) % loop.size()] == record.to);
    }
    const model::Vec3 ruling =
        (surface.position(record.to) - surface.position(record.from)) * (along ? 1.0 : -1.0);
    const model::Vec3 loopNormal = cross(ruling, inward);
    model::Vec3 value;
    for (const PointTerm& t : normal) {
        for (int k = 0; k < 3; ++k) {
            value[k] += t.coefficient * state[static_cast<std::size_t>(t.offset + k)];
        }
    }
    if (dot(value, loopNormal) >= 0.0) {
        return normal;
    }
    PointCombination flipped = normal;
    for (PointTerm& t : flipped) {
        t.coefficient = -t.coefficient;
    }
    return flipped;
}

int addSmoothRulings(const model::CompositeSurface& surface,
                     const std::vector<model::EdgeId>& requested, const RulingNormals& normals,
                     LinearTerm& term) {
    std::set<model::EdgeId> edges;
    for (model::EdgeId edge : requested) {
        if (!surface.hasEdge(edge) || surface.edge(edge).isSpline()) {
            throw std::invalid_argument("edge " + std::to_string(edge) +
                                        " is not a ruling (R-edge) of the surface.");
        }
        if (surface.facesOfEdge(edge).size() != 2) {
            throw std::invalid_argument("ruling " + std::to_string(edge) +
                                        " is on the boundary; a smooth transition needs a face "
                                        "on either side.");
        }
        edges.insert(edge);
    }
    for (const auto& [id, record] : surface.edges()) {
        if (!record.isSpline() && record.smooth && surface.facesOfEdge(id).size() == 2) {
            edges.insert(id);
        }
    }
    for (model::EdgeId edge : edges) {
        const std::vector<model::FaceId> faces = surface.facesOfEdge(edge);
        const PointCombination& left = normals.at({faces[0], edge});
        const PointCombination& right = normals.at({faces[1], edge});
        term.addPointRelation(3, simplified(plus(left, right, -1.0)));
    }
    return static_cast<int>(edges.size());
}

} // namespace devsurf::solver
