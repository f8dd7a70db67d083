#include "solver/formulation/vertex_developability.h"

#include "model/math_constants.h"
#include "solver/core/term.h"
#include "solver/quality/vertex_stars.h"

#include <algorithm>
#include <cmath>
#include <memory>

namespace devsurf::solver {

namespace {

model::Vec3 valueAt(const std::vector<double>& state, int offset) {
    const auto o = static_cast<std::size_t>(offset);
    return {state[o], state[o + 1], state[o + 2]};
}

using devsurf::model::kPi;

struct StarOffsets {
    int centre = 0;
    std::vector<int> spokes;
};

// Rows s · ((r − v) + λ (l − v)) = 0 (three per star): the crease's two tangent points l, r lie
// on one line through the vertex v, on opposite sides (λ > 0, an auxiliary variable).
class TangentContinuityTerm : public Term {
public:
    struct Star {
        int vertex = 0;
        int left = 0;
        int right = 0;
        int ratio = 0;
        double scale = 1.0;
    };
    void add(const Star& star) { m_stars.push_back(star); }
    const char* typeName() const override { return "TangentContinuityTerm"; }
    int rowCount() const override { return 3 * static_cast<int>(m_stars.size()); }
    void buildPattern(PatternBuilder& builder) const override {
        for (const Star& s : m_stars) {
            for (int k = 0; k < 3; ++k) {
                builder.beginRow();
                builder.addColumn(s.right + k);
                builder.addColumn(s.vertex + k);
                builder.addColumn(s.left + k);
                builder.addColumn(s.ratio);
            }
        }
    }
    void evaluate(const double* x, double* residuals, double* jacobian) const override {
        for (const Star& s : m_stars) {
            const double lambda = x[s.ratio];
            for (int k = 0; k < 3; ++k) {
                const double left = x[s.left + k] - x[s.vertex + k];
                *residuals++ = s.scale * (x[s.right + k] - x[s.vertex + k] + lambda * left);
                *jacobian++ = s.scale;
                *jacobian++ = -s.scale * (1.0 + lambda);
                *jacobian++ = s.scale * lambda;
                *jacobian++ = s.scale * left;
            }
        }
    }

private:
    std::vector<Star> m_stars;
};

// The index i (0 or 1) such that spokes i and i + 2 of a four-spoke star are both S-edges (a
// crease passing through the vertex), or -1.
int creaseThrough(const VertexStar& star) {
    if (star.spokes.size() != 4) {
        return -1;
    }
    for (std::size_t i = 0; i < 2; ++i) {
        if (star.spokes[i].spline && star.spokes[i + 2].spline) {
            return static_cast<int>(i);
        }
    }
    return -1;
}

model::CreaseCondition conditionOf(const model::CompositeSurface& surface, model::EdgeId edge) {
    return surface.hasEdge(edge) ? surface.edge(edge).condition : model::CreaseCondition::None;
}

} // namespace

int addVertexDevelopability(const model::CompositeSurface& surface,
                            const std::map<model::VertexId, int>& vertexOffsets,
                            const std::map<model::EdgeId, std::vector<int>>& edgeOffsets,
                            Problem& problem, std::vector<double>& state, SquaredDistanceTerm& term,
                            MinimumLengthTerm& guard, const FormulationOptions& options) {
    const double spokeGuard = options.vertexSpokeGuard;
    const double smoothCreaseAngle = options.vertexSmoothCreaseAngle;
    std::vector<StarOffsets> stars;
    std::vector<int> through; // per star: creaseThrough, or -1 without tangent continuity
    std::vector<std::pair<model::EdgeId, model::EdgeId>> starEdges; // the crease's two S-edges
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
            through.push_back(smoothCreaseAngle > 0.0 ? creaseThrough(star) : -1);
            const int i = through.back();
            starEdges.emplace_back(
                i >= 0 ? star.spokes[static_cast<std::size_t>(i)].edge : model::kInvalidId,
                i >= 0 ? star.spokes[static_cast<std::size_t>(i) + 2].edge : model::kInvalidId);
            stars.push_back(std::move(s));
        }
    }
    if (stars.empty()) {
        return 0;
    }
    // Every star whose crease passes through gets both kinds of rows, so that the problem's
    // structure depends on the combinatorics only (a rough start of the same design reuses the
    // symbolic analysis); the rows of the kind a star does not use are scaled to zero.
    int ratios = 0;
    const auto crossing = static_cast<int>(
        std::count_if(through.begin(), through.end(), [](int i) { return i >= 0; }));
    if (crossing > 0) {
        ratios = problem.addVariableBlock("creaseTangentRatios", crossing);
    }
    const int block = problem.addVariableBlock("vertexStars", 2 * flatPoints);
    state.resize(static_cast<std::size_t>(problem.variableCount()), 0.0);
    auto smooth = std::make_unique<TangentContinuityTerm>();
    int next = block;
    for (std::size_t k = 0; k < stars.size(); ++k) {
        const StarOffsets& s = stars[k];
        const model::Vec3 v = valueAt(state, s.centre);
        const std::size_t n = s.spokes.size();
        double sum = 0.0;
        for (std::size_t i = 0; i < n; ++i) {
            sum += angleBetween(valueAt(state, s.spokes[i]) - v,
                                valueAt(state, s.spokes[(i + 1) % n]) - v);
        }
        const bool kept = std::abs(2.0 * kPi - sum) <= options.vertexStartDefectLimit;
        double flatScale = kept ? 1.0 : 0.0;
        if (through[k] >= 0) {
            const auto i = static_cast<std::size_t>(through[k]);
            const int left = s.spokes[i];
            const int right = s.spokes[i + 2];
            const model::Vec3 l = valueAt(state, left) - v;
            const model::Vec3 r = valueAt(state, right) - v;
            // A crease with a condition (a curved fold) is meant smooth; a plain crease only
            // where it is straight already: its kink is the design's (docs/tuning.md).
            const bool conditioned =
                conditionOf(surface, starEdges[k].first) != model::CreaseCondition::None &&
                conditionOf(surface, starEdges[k].second) != model::CreaseCondition::None;
            const double limit =
                conditioned ? smoothCreaseAngle
                            : std::min(smoothCreaseAngle, options.vertexSmoothPlainCreaseAngle);
            const bool straight = kept && angleBetween(l, r) > kPi - limit;
            const int ratio = ratios++;
            state[static_cast<std::size_t>(ratio)] = r.norm() / l.norm();
            smooth->add({s.centre, left, right, ratio, straight ? 1.0 / r.norm() : 0.0});
            flatScale = straight ? 0.0 : flatScale;
        }
        const int centre = next;
        next += 2; // v̄ at the origin
        std::vector<int> flat;
        double angle = 0.0;
        for (std::size_t i = 0; i < n; ++i) {
            const model::Vec3 c = valueAt(state, s.spokes[i]) - v;
            if (i > 0) {
                angle += angleBetween(valueAt(state, s.spokes[i - 1]) - v, c);
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
            const double spoke = flatScale / (c - v).norm();
            term.addRow({{flat[i], spoke}, {centre, -spoke}},
                        {{s.spokes[i], spoke}, {s.centre, -spoke}}, 0.0);
            if (spokeGuard > 0.0) {
                guard.addRow({{s.spokes[i], 1.0}, {s.centre, -1.0}},
                             kept ? spokeGuard * (c - v).norm() : 0.0);
            }
            const double rim = flatScale / (d - c).norm();
            term.addRow({{flat[j], rim}, {flat[i], -rim}},
                        {{s.spokes[j], rim}, {s.spokes[i], -rim}}, 0.0);
        }
    }
    if (crossing > 0) {
        problem.add(problem.addFamily("smoothCreaseVertices", TermRole::Constraint,
                                      options.vertexDevelopabilityWeight),
                    std::move(smooth));
    }
    return static_cast<int>(stars.size());
}

} // namespace devsurf::solver
