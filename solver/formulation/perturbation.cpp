#include "solver/formulation/perturbation.h"

#include <algorithm>
#include <limits>
#include <random>
#include <set>

namespace devsurf::solver {

using model::Vec3;
using model::VertexId;

double surfaceDiameter(const model::CompositeSurface& surface) {
    Vec3 low(std::numeric_limits<double>::max(), std::numeric_limits<double>::max(),
             std::numeric_limits<double>::max());
    Vec3 high = -low;
    bool any = false;
    auto extend = [&](const Vec3& p) {
        any = true;
        for (int k = 0; k < 3; ++k) {
            low[k] = std::min(low[k], p[k]);
            high[k] = std::max(high[k], p[k]);
        }
    };
    for (const auto& [id, position] : surface.vertices()) {
        (void)id;
        extend(position);
    }
    for (const auto& [id, record] : surface.edges()) {
        (void)id;
        for (const Vec3& p : record.controlPoints) {
            extend(p);
        }
    }
    return any ? (high - low).norm() : 0.0;
}

double meanControlSpacing(const model::CompositeSurface& surface) {
    double sum = 0.0;
    int count = 0;
    for (const auto& [id, record] : surface.edges()) {
        (void)id;
        for (std::size_t i = 0; i + 1 < record.controlPoints.size(); ++i) {
            sum += model::distance(record.controlPoints[i], record.controlPoints[i + 1]);
            ++count;
        }
    }
    return count > 0 ? sum / count : 0.0;
}

void perturbSurface(model::CompositeSurface& surface, double sigma, unsigned seed,
                    const std::vector<VertexId>& keep) {
    std::mt19937 rng(seed);
    std::normal_distribution<double> noise(0.0, sigma);
    auto jitter = [&](const Vec3& p) { return p + Vec3(noise(rng), noise(rng), noise(rng)); };
    const std::set<VertexId> kept(keep.begin(), keep.end());
    // Vertices first (moveVertices carries the end control points along), then the interior
    // control points, both in id order so the result depends on the seed only.
    std::vector<std::pair<VertexId, Vec3>> vertices(surface.vertices().begin(),
                                                    surface.vertices().end());
    std::vector<std::pair<VertexId, Vec3>> moves;
    for (const auto& [id, position] : vertices) {
        const Vec3 moved = jitter(position);
        if (kept.count(id) == 0) {
            moves.emplace_back(id, moved);
        }
    }
    surface.moveVertices(moves);
    std::vector<model::EdgeId> edges;
    for (const auto& [id, record] : surface.edges()) {
        if (record.isSpline()) {
            edges.push_back(id);
        }
    }
    for (model::EdgeId id : edges) {
        std::vector<Vec3> points = surface.edge(id).controlPoints;
        for (std::size_t i = 1; i + 1 < points.size(); ++i) {
            points[i] = jitter(points[i]);
        }
        surface.setControlPoints(id, std::move(points));
    }
}

std::vector<VertexId> spreadBoundaryVertices(const model::CompositeSurface& surface, int count) {
    std::vector<VertexId> boundary;
    std::set<VertexId> seen;
    for (const auto& [id, record] : surface.edges()) {
        if (surface.facesOfEdge(id).size() == 1) {
            for (VertexId v : {record.from, record.to}) {
                if (seen.insert(v).second) {
                    boundary.push_back(v);
                }
            }
        }
    }
    std::sort(boundary.begin(), boundary.end());
    std::vector<VertexId> chosen;
    if (boundary.empty() || count <= 0) {
        return chosen;
    }
    chosen.push_back(boundary.front());
    while (static_cast<int>(chosen.size()) < count && chosen.size() < boundary.size()) {
        VertexId best = model::kInvalidId;
        double bestDistance = -1.0;
        for (VertexId v : boundary) {
            if (std::find(chosen.begin(), chosen.end(), v) != chosen.end()) {
                continue;
            }
            double nearest = std::numeric_limits<double>::max();
            for (VertexId c : chosen) {
                nearest = std::min(nearest, distance(surface.position(v), surface.position(c)));
            }
            if (nearest > bestDistance) {
                bestDistance = nearest;
                best = v;
            }
        }
        chosen.push_back(best);
    }
    return chosen;
}

} // namespace devsurf::solver
