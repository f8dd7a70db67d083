#pragma once

// Small composite surfaces for the formulation and quality tests, built independently of the
// code under test.

#include "model/composite_surface.h"
#include "model/sampled_mesh.h"

#include <algorithm>

#include <cmath>
#include <random>
#include <vector>

namespace devsurf::solver::testing {

// Control points of the straight segment pq at the Greville abscissae (exact for lines).
inline std::vector<model::Vec3> lineControls(const model::SplineSpace& space, const model::Vec3& p,
                                             const model::Vec3& q) {
    const std::vector<double> knots = space.knots(false);
    const int count = space.controlPointCount(false);
    std::vector<model::Vec3> points;
    for (int i = 0; i < count; ++i) {
        double greville = 0.0;
        for (int k = 1; k <= space.degree; ++k) {
            greville += knots[static_cast<std::size_t>(i + k)];
        }
        const double t = greville / space.degree;
        points.push_back(p * (1.0 - t) + q * t);
    }
    points.front() = p;
    points.back() = q;
    return points;
}

// A single strip between a(t) = s·(t, t², t³) (one cubic Bézier segment: any cubic is a cubic
// C² spline with one interval) and b = a + s·(0, 0.2, 1): a generalised cylinder.
inline model::CompositeSurface makeGeneralizedCylinder(double s) {
    const model::SplineSpace space{3, 2, 1};
    // Bézier control points of (t, t², t³): (0,0,0), (1/3,0,0), (2/3,1/3,0), (1,1,1).
    const std::vector<model::Vec3> a{{0, 0, 0}, {s / 3, 0, 0}, {2 * s / 3, s / 3, 0}, {s, s, s}};
    const model::Vec3 d(0, 0.2 * s, s);
    model::CompositeSurface surface;
    const auto a0 = surface.addVertex(a.front());
    const auto a1 = surface.addVertex(a.back());
    const auto b1 = surface.addVertex(a.back() + d);
    const auto b0 = surface.addVertex(a.front() + d);
    surface.addFace({a0, a1, b1, b0});
    surface.setSpline(a0, a1, space, a);
    std::vector<model::Vec3> b;
    for (const model::Vec3& p : a) {
        b.push_back(p + d);
    }
    surface.setSpline(b0, b1, space, b);
    return surface;
}

// A cone (SRR face) over a curved cubic C² base curve with its apex above.
inline model::CompositeSurface makeCone() {
    const model::SplineSpace space{3, 2, 3};
    model::CompositeSurface surface;
    const auto apex = surface.addVertex({50, 50, 80});
    const auto start = surface.addVertex({0, 0, 0});
    const auto end = surface.addVertex({100, 0, 0});
    surface.addFace({start, end, apex});
    std::vector<model::Vec3> base = lineControls(space, {0, 0, 0}, {100, 0, 0});
    for (std::size_t i = 1; i + 1 < base.size(); ++i) {
        base[i].y -= 20.0 * std::sin(3.14159 * base[i].x / 100.0);
        base[i].z += 5.0 * std::cos(3.0 * base[i].x / 100.0);
    }
    surface.setSpline(start, end, space, base);
    return surface;
}

// A strip between two curves with random control points near a unit square (not developable).
inline model::CompositeSurface makeRandomStrip(unsigned seed, double scale) {
    const model::SplineSpace space{3, 2, 3};
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> noise(-0.08, 0.08);
    model::CompositeSurface surface;
    const auto a0 = surface.addVertex(model::Vec3(0, 0, 0) * scale);
    const auto a1 = surface.addVertex(model::Vec3(1, 0, 0) * scale);
    const auto b1 = surface.addVertex(model::Vec3(1, 0.5, 0) * scale);
    const auto b0 = surface.addVertex(model::Vec3(0, 0.5, 0) * scale);
    surface.addFace({a0, a1, b1, b0});
    auto jittered = [&](const model::Vec3& p, const model::Vec3& q) {
        std::vector<model::Vec3> points = lineControls(space, p, q);
        for (std::size_t i = 1; i + 1 < points.size(); ++i) {
            points[i] += model::Vec3(noise(rng), noise(rng), noise(rng)) * scale;
        }
        return points;
    };
    surface.setSpline(a0, a1, space, jittered(surface.position(a0), surface.position(a1)));
    surface.setSpline(b0, b1, space, jittered(surface.position(b0), surface.position(b1)));
    return surface;
}

// Two strips between three parallel straight S-edges (cf. Fig. 13).
inline model::CompositeSurface makeTwoStrips(int intervals) {
    const model::SplineSpace space{3, 2, intervals};
    model::CompositeSurface surface;
    model::VertexId left[3];
    model::VertexId right[3];
    for (int j = 0; j < 3; ++j) {
        left[j] = surface.addVertex({0.0, 100.0 * j, 0.0});
        right[j] = surface.addVertex({300.0, 100.0 * j, 0.0});
    }
    for (int j = 0; j < 2; ++j) {
        surface.addFace({left[j], right[j], right[j + 1], left[j + 1]});
    }
    for (int j = 0; j < 3; ++j) {
        surface.setSpline(
            left[j], right[j], space,
            lineControls(space, surface.position(left[j]), surface.position(right[j])));
    }
    return surface;
}

// Largest relative difference between the length of an edge of a sampled face (all its vertex
// pairs) on `surface`, sampled anew at the kept development's density, and in `development`:
// the isometry measured from the geometry, not from a solver's residual.
inline double pairLengthError(const model::CompositeSurface& surface,
                              const std::vector<model::Vec2>& development) {
    const model::SampledMesh mesh =
        model::sampleSurface(surface, model::kDevelopmentSamplesPerInterval);
    if (mesh.vertices.size() != development.size()) {
        return 1.0;
    }
    double worst = 0.0;
    for (const std::vector<int>& face : mesh.faces) {
        for (std::size_t i = 0; i < face.size(); ++i) {
            for (std::size_t j = i + 1; j < face.size(); ++j) {
                const auto a = static_cast<std::size_t>(face[i]);
                const auto b = static_cast<std::size_t>(face[j]);
                const double space = model::distance(mesh.vertices[a], mesh.vertices[b]);
                const double flat = (development[a] - development[b]).norm();
                worst = std::max(worst, std::abs(space - flat) / space);
            }
        }
    }
    return worst;
}

} // namespace devsurf::solver::testing
