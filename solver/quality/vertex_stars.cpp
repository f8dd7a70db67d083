#include "solver/quality/vertex_stars.h"

#include "model/math_constants.h"
#include "model/model_error.h"

#include <cmath>
#include <map>
#include <set>

namespace devsurf::solver {

using devsurf::model::kTwoPi;

std::vector<VertexStar> creaseVertexStars(const model::CompositeSurface& surface) {
    // For every vertex the (next, previous) neighbours of each face corner at it: the face's
    // sector runs from the edge to `next` to the edge to `previous`.
    struct Corner {
        model::VertexId next;
        model::VertexId previous;
    };
    std::map<model::VertexId, std::vector<Corner>> corners;
    std::set<model::VertexId> repeated; // vertices that occur twice in one loop
    for (const auto& [face, loop] : surface.faces()) {
        (void)face;
        const std::size_t n = loop.size();
        std::set<model::VertexId> seen;
        for (std::size_t i = 0; i < n; ++i) {
            if (!seen.insert(loop[i]).second) {
                repeated.insert(loop[i]);
            }
            corners[loop[i]].push_back({loop[(i + 1) % n], loop[(i + n - 1) % n]});
        }
    }
    std::vector<VertexStar> stars;
    for (const auto& [vertex, list] : corners) {
        if (repeated.count(vertex) != 0) {
            continue;
        }
        // Chain the corners: the face after a corner is the one whose `next` is its `previous`.
        std::vector<model::VertexId> order{list.front().next};
        std::vector<bool> used(list.size(), false);
        used[0] = true;
        model::VertexId current = list.front().previous;
        bool closed = false;
        for (std::size_t step = 0; step < list.size(); ++step) {
            if (current == order.front()) {
                closed = true;
                break;
            }
            order.push_back(current);
            bool found = false;
            for (std::size_t k = 0; k < list.size(); ++k) {
                if (!used[k] && list[k].next == current) {
                    used[k] = true;
                    current = list[k].previous;
                    found = true;
                    break;
                }
            }
            if (!found) {
                break;
            }
        }
        if (!closed || order.size() != list.size()) {
            continue; // a boundary vertex, or not a single fan
        }
        VertexStar star;
        star.vertex = vertex;
        bool crease = false;
        for (model::VertexId other : order) {
            const model::EdgeId edge = surface.edgeBetween(vertex, other);
            const model::EdgeRecord& record = surface.edge(edge);
            StarSpoke spoke;
            spoke.edge = edge;
            spoke.spline = record.isSpline();
            if (spoke.spline) {
                spoke.controlIndex = record.from == vertex ? 1 : record.controlPoints.size() - 2;
                crease = crease || surface.facesOfEdge(edge).size() == 2;
            } else {
                spoke.otherEnd = other;
            }
            star.spokes.push_back(spoke);
        }
        if (crease) {
            stars.push_back(std::move(star));
        }
    }
    return stars;
}

model::Vec3 spokePoint(const model::CompositeSurface& surface, const StarSpoke& spoke) {
    if (spoke.spline) {
        return surface.edge(spoke.edge).controlPoints[spoke.controlIndex];
    }
    return surface.position(spoke.otherEnd);
}

std::vector<VertexAngleDefect> vertexAngleDefects(const model::CompositeSurface& surface) {
    if (const auto problems = surface.validate(); !problems.empty()) {
        throw model::ModelError(problems.front());
    }
    std::vector<VertexAngleDefect> defects;
    for (const VertexStar& star : creaseVertexStars(surface)) {
        const model::Vec3& centre = surface.position(star.vertex);
        double sum = 0.0;
        const std::size_t n = star.spokes.size();
        for (std::size_t i = 0; i < n; ++i) {
            sum += angleBetween(spokePoint(surface, star.spokes[i]) - centre,
                                spokePoint(surface, star.spokes[(i + 1) % n]) - centre);
        }
        defects.push_back({star.vertex, std::abs(kTwoPi - sum)});
    }
    return defects;
}

} // namespace devsurf::solver
