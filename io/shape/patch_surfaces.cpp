#include "patch_surfaces.h"

#include "model/model_error.h"
#include "model/strip.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace devsurf::io {

namespace {

using model::Vec3;

// Nodes and weights of the n-point Gauss–Legendre rule on [0, 1] (Newton on P_n).
struct GaussRule {
    std::vector<double> nodes;
    std::vector<double> weights;
};

GaussRule gaussRule(int n) {
    GaussRule rule;
    const double pi = std::acos(-1.0);
    for (int i = 0; i < n; ++i) {
        double x = std::cos(pi * (i + 0.75) / (n + 0.5));
        double derivative = 1.0;
        for (int iteration = 0; iteration < 100; ++iteration) {
            double p0 = 1.0;
            double p1 = x;
            for (int k = 2; k <= n; ++k) {
                const double p2 = ((2.0 * k - 1.0) * x * p1 - (k - 1.0) * p0) / k;
                p0 = p1;
                p1 = p2;
            }
            derivative = n * (x * p1 - p0) / (x * x - 1.0);
            const double step = p1 / derivative;
            x -= step;
            if (std::abs(step) < 1e-16) {
                break;
            }
        }
        rule.nodes.push_back(0.5 * (1.0 - x));
        rule.weights.push_back(1.0 / ((1.0 - x * x) * derivative * derivative));
    }
    return rule;
}

// The curve of a cone's apex: every pole at the apex, on the knots of the cone's S-edge.
model::BSplineCurve apexCurve(const model::BSplineCurve& a, const Vec3& apex) {
    return model::BSplineCurve(a.degree(), a.knots(),
                               std::vector<Vec3>(a.controlPoints().size(), apex), false);
}

// Whether the ruled patch's normal points against its loop's: the loop's normal by Newell's
// formula over its sampled boundary (a forwards, b backwards), the patch's where it is largest.
bool againstLoop(const PatchSurface& patch) {
    constexpr int kSamples = 32;
    std::vector<Vec3> boundary;
    for (int i = 0; i <= kSamples; ++i) {
        boundary.push_back(patch.a.evaluate(static_cast<double>(i) / kSamples));
    }
    for (int i = kSamples; i >= 0; --i) {
        boundary.push_back(patch.b.evaluate(static_cast<double>(i) / kSamples));
    }
    Vec3 loopNormal;
    for (std::size_t i = 0; i < boundary.size(); ++i) {
        loopNormal += model::cross(boundary[i], boundary[(i + 1) % boundary.size()]);
    }
    Vec3 best;
    for (double u : {0.5, 0.25, 0.75}) {
        Vec3 du;
        Vec3 dv;
        patch.derivatives(u, 0.5, du, dv);
        const Vec3 n = model::cross(du, dv);
        if (n.norm() > best.norm()) {
            best = n;
        }
    }
    return model::dot(best, loopNormal) < 0.0;
}

} // namespace

Vec3 PatchSurface::point(double u, double v) const {
    return a.evaluate(u) * (1.0 - v) + b.evaluate(u) * v;
}

void PatchSurface::derivatives(double u, double v, Vec3& du, Vec3& dv) const {
    Vec3 pa;
    Vec3 ta;
    Vec3 pb;
    Vec3 tb;
    a.pointAndTangent(u, pa, ta);
    b.pointAndTangent(u, pb, tb);
    du = ta * (1.0 - v) + tb * v;
    dv = pb - pa;
}

std::vector<PatchSurface> patchSurfaces(const model::CompositeSurface& surface) {
    const std::vector<model::Problem> problems = surface.validate();
    if (!problems.empty()) {
        throw model::ModelError(problems.front());
    }
    std::vector<PatchSurface> patches;
    for (const auto& [face, loop] : surface.faces()) {
        PatchSurface patch;
        patch.surface = surface.id();
        patch.face = face;
        patch.type = surface.faceType(face);
        if (patch.isPlanar()) {
            for (model::VertexId vertex : loop) {
                patch.corners.push_back(surface.position(vertex));
            }
        } else {
            const model::Strip strip = model::stripOfFace(surface, face);
            // The strip's curves are uniform clamped curves of one spline space; a reversed side
            // has the mirrored knots, equal up to rounding: both rows take a's knots.
            patch.a = strip.a.clamped();
            patch.b = strip.isCone()
                          ? apexCurve(patch.a, strip.apex)
                          : model::BSplineCurve(patch.a.degree(), patch.a.knots(),
                                                strip.b.clamped().controlPoints(), false);
            patch.flipped = againstLoop(patch);
        }
        patches.push_back(std::move(patch));
    }
    return patches;
}

double patchArea(const PatchSurface& patch) {
    if (patch.isPlanar()) {
        Vec3 sum;
        const std::size_t n = patch.corners.size();
        for (std::size_t i = 0; i < n; ++i) {
            sum += model::cross(patch.corners[i], patch.corners[(i + 1) % n]);
        }
        return 0.5 * sum.norm();
    }
    static const GaussRule uRule = gaussRule(16);
    static const GaussRule vRule = gaussRule(8);
    std::vector<double> breaks = patch.a.knots();
    breaks.erase(std::unique(breaks.begin(), breaks.end()), breaks.end());
    double area = 0.0;
    for (std::size_t span = 0; span + 1 < breaks.size(); ++span) {
        const double u0 = breaks[span];
        const double length = breaks[span + 1] - u0;
        for (std::size_t i = 0; i < uRule.nodes.size(); ++i) {
            for (std::size_t j = 0; j < vRule.nodes.size(); ++j) {
                Vec3 du;
                Vec3 dv;
                patch.derivatives(u0 + length * uRule.nodes[i], vRule.nodes[j], du, dv);
                area += length * uRule.weights[i] * vRule.weights[j] * model::cross(du, dv).norm();
            }
        }
    }
    return area;
}

double projectDiameter(const model::Project& project) {
    const double inf = std::numeric_limits<double>::infinity();
    Vec3 low{inf, inf, inf};
    Vec3 high{-inf, -inf, -inf};
    auto extend = [&](const Vec3& p) {
        for (int k = 0; k < 3; ++k) {
            low[k] = std::min(low[k], p[k]);
            high[k] = std::max(high[k], p[k]);
        }
    };
    for (const model::CompositeSurface& surface : project.surfaces) {
        for (const auto& [id, position] : surface.vertices()) {
            extend(position);
        }
        for (const auto& [id, edge] : surface.edges()) {
            for (const Vec3& p : edge.controlPoints) {
                extend(p);
            }
        }
    }
    return low.x > high.x ? 0.0 : (high - low).norm();
}

std::string patchName(const PatchSurface& patch, bool severalSurfaces) {
    std::string name = "patch " + std::to_string(patch.face);
    return severalSurfaces ? "surface " + std::to_string(patch.surface) + " " + name : name;
}

} // namespace devsurf::io
