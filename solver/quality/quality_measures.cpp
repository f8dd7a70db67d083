#include "solver/quality/quality_measures.h"

#include "model/derived_geometry.h"
#include "model/math_constants.h"
#include "model/sampled_mesh.h"
#include "model/strip.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <limits>
#include <map>
#include <utility>
#include <vector>

namespace devsurf::solver {

using model::Vec3;

namespace {

using devsurf::model::kTwoPi;

// δ of a quad p0 p1 p2 p3: distance of the diagonal lines p0p2 and p1p3 over the mean of the
// two shortest edges. Returns -1 for a quad whose diagonals are parallel (degenerate).
double quadFlatness(const Vec3& p0, const Vec3& p1, const Vec3& p2, const Vec3& p3) {
    const Vec3 d1 = p2 - p0;
    const Vec3 d2 = p3 - p1;
    const Vec3 normal = cross(d1, d2);
    const double length = normal.norm();
    if (!(length > 1e-300)) {
        return -1.0;
    }
    const double gap = std::abs(dot(p1 - p0, normal)) / length;
    double edges[4] = {distance(p0, p1), distance(p1, p2), distance(p2, p3), distance(p3, p0)};
    std::sort(edges, edges + 4);
    const double reference = 0.5 * (edges[0] + edges[1]);
    return reference > 0.0 ? gap / reference : -1.0;
}

} // namespace

double normalizedDevelopabilityResidual(const Vec3& aMinusB, const Vec3& aPrime,
                                        const Vec3& bPrime) {
    const double scale = aMinusB.norm() * aPrime.norm() * bPrime.norm();
    if (!(scale > 0.0)) {
        return 0.0;
    }
    return std::abs(det(aMinusB, aPrime, bPrime)) / scale;
}

std::vector<double> faceFlatness(const model::SampledMesh& mesh) {
    std::vector<double> flatness(mesh.faces.size(), std::numeric_limits<double>::quiet_NaN());
    for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
        const std::vector<int>& face = mesh.faces[f];
        if (face.size() != 4) {
            continue;
        }
        const double delta = quadFlatness(mesh.vertices[static_cast<std::size_t>(face[0])],
                                          mesh.vertices[static_cast<std::size_t>(face[1])],
                                          mesh.vertices[static_cast<std::size_t>(face[2])],
                                          mesh.vertices[static_cast<std::size_t>(face[3])]);
        if (delta >= 0.0) {
            flatness[f] = delta;
        }
    }
    return flatness;
}

std::vector<double> vertexAngleDefects(const model::SampledMesh& mesh) {
    std::map<std::pair<int, int>, int> edgeFaces;
    std::vector<double> angleSum(mesh.vertices.size(), 0.0);
    for (const std::vector<int>& face : mesh.faces) {
        const std::size_t n = face.size();
        for (std::size_t i = 0; i < n; ++i) {
            const int v = face[i];
            const int next = face[(i + 1) % n];
            const int previous = face[(i + n - 1) % n];
            ++edgeFaces[{std::min(v, next), std::max(v, next)}];
            const Vec3& p = mesh.vertices[static_cast<std::size_t>(v)];
            angleSum[static_cast<std::size_t>(v)] +=
                angleBetween(mesh.vertices[static_cast<std::size_t>(next)] - p,
                             mesh.vertices[static_cast<std::size_t>(previous)] - p);
        }
    }
    std::vector<char> onBoundary(mesh.vertices.size(), 0);
    std::vector<char> used(mesh.vertices.size(), 0);
    for (const auto& [edge, faces] : edgeFaces) {
        used[static_cast<std::size_t>(edge.first)] = used[static_cast<std::size_t>(edge.second)] =
            1;
        if (faces == 1) {
            onBoundary[static_cast<std::size_t>(edge.first)] = 1;
            onBoundary[static_cast<std::size_t>(edge.second)] = 1;
        }
    }
    std::vector<double> defects(mesh.vertices.size(), std::numeric_limits<double>::quiet_NaN());
    for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
        if (used[v] && !onBoundary[v]) {
            defects[v] = std::abs(kTwoPi - angleSum[v]);
        }
    }
    return defects;
}

namespace {

// Count, mean and largest of the values that are not NaN (NaN: no value there).
void accumulate(const std::vector<double>& values, int& count, double& mean, double& largest) {
    double sum = 0.0;
    for (double value : values) {
        if (!std::isnan(value)) {
            ++count;
            sum += value;
            largest = std::max(largest, value);
        }
    }
    mean = count > 0 ? sum / count : 0.0;
}

} // namespace

QualityMeasures measureQuality(const model::CompositeSurface& surface,
                               const QualityOptions& options) {
    QualityMeasures q;
    const auto derived =
        model::DerivedGeometry::of(surface, std::max(1, options.meshSamplesPerInterval));
    const model::SampledMesh& mesh = derived->mesh();

    accumulate(faceFlatness(mesh), q.quads, q.flatnessMean, q.flatnessMax);
    accumulate(vertexAngleDefects(mesh), q.interiorVertices, q.curvatureMean, q.curvatureMax);

    const int samples = std::max(1, options.developabilitySamplesPerInterval);
    double developabilitySum = 0.0;
    for (const model::Strip& strip : derived->strips()) {
        if (strip.isCone()) {
            continue; // cones are developable by construction
        }
        const int intervals = surface.edge(strip.aSide.edge).space.intervals;
        for (int i = 0; i < intervals; ++i) {
            for (int j = 0; j < samples; ++j) {
                // Midpoints of a fine subdivision: never the solver's collocation values.
                const double u = (i + (j + 0.5) / samples) / intervals;
                const double r = normalizedDevelopabilityResidual(
                    strip.a.evaluate(u) - strip.b.evaluate(u), strip.a.derivative(u, 1),
                    strip.b.derivative(u, 1));
                ++q.developabilitySamples;
                developabilitySum += r;
                q.developabilityMax = std::max(q.developabilityMax, r);
            }
        }
    }
    q.developabilityMean =
        q.developabilitySamples > 0 ? developabilitySum / q.developabilitySamples : 0.0;
    return q;
}

std::vector<PatchDevelopability> developabilityOfPatches(const model::CompositeSurface& surface,
                                                         int segmentsPerInterval,
                                                         int samplesPerInterval) {
    std::vector<PatchDevelopability> result;
    std::vector<model::Strip> strips;
    try {
        strips = model::stripsOf(surface);
    } catch (const std::exception&) {
        return result; // an invalid surface has no strips to measure
    }
    const int samples = std::max(1, samplesPerInterval);
    const int perInterval = std::max(1, segmentsPerInterval);
    for (const model::Strip& strip : strips) {
        if (strip.isCone()) {
            continue;
        }
        const int intervals = std::max(1, surface.edge(strip.aSide.edge).space.intervals);
        const long long n = static_cast<long long>(intervals) * samples;
        const long long m = static_cast<long long>(intervals) * perInterval;
        std::vector<double> values(static_cast<std::size_t>(n));
        PatchDevelopability patch;
        patch.face = strip.face;
        patch.segments.assign(static_cast<std::size_t>(m), -1.0);
        for (long long i = 0; i < n; ++i) {
            const double u = (static_cast<double>(i) + 0.5) / static_cast<double>(n);
            const double r = normalizedDevelopabilityResidual(
                strip.a.evaluate(u) - strip.b.evaluate(u), strip.a.derivative(u, 1),
                strip.b.derivative(u, 1));
            values[static_cast<std::size_t>(i)] = r;
            patch.worst = std::max(patch.worst, r);
            // The segment of u = (2i+1) / 2n, in integers so that a sample on a segment's
            // boundary always falls on the same side.
            const long long segment = std::min(m - 1, (2 * i + 1) * m / (2 * n));
            double& value = patch.segments[static_cast<std::size_t>(segment)];
            value = std::max(value, r);
        }
        for (long long k = 0; k < m; ++k) {
            double& value = patch.segments[static_cast<std::size_t>(k)];
            if (value < 0.0) {
                const long long nearest =
                    std::clamp<long long>(((2 * k + 1) * n) / (2 * m), 0, n - 1);
                value = values[static_cast<std::size_t>(nearest)];
            }
        }
        result.push_back(std::move(patch));
    }
    return result;
}

std::vector<std::pair<model::FaceId, double>>
developabilityByFace(const model::CompositeSurface& surface, int samplesPerInterval) {
    std::vector<std::pair<model::FaceId, double>> result;
    for (const PatchDevelopability& patch :
         developabilityOfPatches(surface, 1, samplesPerInterval)) {
        result.emplace_back(patch.face, patch.worst);
    }
    std::sort(result.begin(), result.end(),
              [](const auto& a, const auto& b) { return a.second > b.second; });
    return result;
}

double worstDevelopability(const model::CompositeSurface& surface) {
    const auto faces = developabilityByFace(surface);
    return faces.empty() ? 0.0 : faces.front().second;
}

} // namespace devsurf::solver
