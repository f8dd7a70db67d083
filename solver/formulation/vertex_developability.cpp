#include "solver/formulation/vertex_developability.h"

#include "solver/quality/vertex_stars.h"

#include <cmath>

namespace devsurf::solver {

namespace {

model::Vec3 valueAt(const std::vector<double>& state, int offset) {
    const auto o = static_cast<std::size_t>(offset);
    return {state[o], state[o + 1], state[o + 2]};
}

struct StarOffsets {
    int centre = 0;
    std::vector<int> spokes;
};

} // namespace

int addVertexDevelopability(const model::CompositeSurface& surface,
                            const std::map<model::VertexId, int>& vertexOffsets,
                            const std::map<model::EdgeId, std::vector<int>>& edgeOffsets,
                            Problem& problem, std::vector<double>& state, SquaredDistanceTerm& term,
                            MinimumLengthTerm& guard, double spokeGuard) {
    std::vector<StarOffsets> stars;
    int flatPoints = 0;
    for (const VertexStar& star : creaseVertexStars(surface)) {
        StarOffsets s;
        s.centre = vertexOffsets.at(star.vertex);
        for (const StarSpoke& spoke : star.spokes) {
            s.spokes.push_back(spoke.spline ? edgeOffsets.at(spoke.edge).at(spoke.controlIndex)
                                            : vertexOffsets.at(spoke.otherEnd));
        }
        // Lengths below 1e-9 of the diameter (the state's unit) give no usable triangle.
        const model::Vec3 v = valueAt(state, s.centre);
        const std::size_t n = s.spokes.size();
        bool degenerate = n < 3;
        for (std::size_t i = 0; i < n && !degenerate; ++i) {
            const model::Vec3 c = valueAt(state, s.spokes[i]);
            const model::Vec3 next = valueAt(state, s.spokes[(i + 1) % n]);
            degenerate = (c - v).norm() < 1e-9 || (next - c).norm() < 1e-9;
        }
        if (!degenerate) {
            flatPoints += 1 + static_cast<int>(n);
            stars.push_back(std::move(s));
        }
    }
    if (stars.empty()) {
        return 0;
    }
    const int block = problem.addVariableBlock("vertexStars", 2 * flatPoints);
    state.resize(static_cast<std::size_t>(problem.variableCount()), 0.0);
    int next = block;
    for (const StarOffsets& s : stars) {
        const model::Vec3 v = valueAt(state, s.centre);
        const std::size_t n = s.spokes.size();
        const int centre = next;
        next += 2; // v̄ at the origin
        std::vector<int> flat;
        double angle = 0.0;
        for (std::size_t i = 0; i < n; ++i) {
            const model::Vec3 c = valueAt(state, s.spokes[i]) - v;
            if (i > 0) {
                const model::Vec3 previous = valueAt(state, s.spokes[i - 1]) - v;
                angle += std::atan2(cross(previous, c).norm(), dot(previous, c));
            }
            flat.push_back(next);
            state[static_cast<std::size_t>(next)] = c.norm() * std::cos(angle);
            state[static_cast<std::size_t>(next + 1)] = c.norm() * std::sin(angle);
            next += 2;
        }
        // Rows: spoke i (v, cᵢ) and rim i (cᵢ, cᵢ₊₁), each scaled by 1 / reference length.
        for (std::size_t i = 0; i < n; ++i) {
            const std::size_t j = (i + 1) % n;
            const model::Vec3 c = valueAt(state, s.spokes[i]);
            const model::Vec3 d = valueAt(state, s.spokes[j]);
            const double spoke = 1.0 / (c - v).norm();
            term.addRow({{flat[i], spoke}, {centre, -spoke}},
                        {{s.spokes[i], spoke}, {s.centre, -spoke}}, 0.0);
            if (spokeGuard > 0.0) {
                guard.addRow({{s.spokes[i], 1.0}, {s.centre, -1.0}}, spokeGuard * (c - v).norm());
            }
            const double rim = 1.0 / (d - c).norm();
            term.addRow({{flat[j], rim}, {flat[i], -rim}},
                        {{s.spokes[j], rim}, {s.spokes[i], -rim}}, 0.0);
        }
    }
    return static_cast<int>(stars.size());
}

} // namespace devsurf::solver
