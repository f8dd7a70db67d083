#include "sheet_position.h"

#include "derived_geometry.h"

#include <algorithm>
#include <exception>
#include <limits>

namespace devsurf::model {

namespace {

struct Barycentric {
    double u = 0.0; // weights of the triangle's corners a, b, c
    double v = 0.0;
    double w = 0.0;
    double distance = 0.0; // from the point to the triangle (its clamped foot)
};

// The point's foot on triangle abc, clamped into it, as barycentric weights.
Barycentric locate(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
    const Vec3 ab = b - a;
    const Vec3 ac = c - a;
    const Vec3 ap = p - a;
    const double d00 = dot(ab, ab);
    const double d01 = dot(ab, ac);
    const double d11 = dot(ac, ac);
    const double d20 = dot(ap, ab);
    const double d21 = dot(ap, ac);
    const double det = d00 * d11 - d01 * d01;
    Barycentric result;
    if (det <= 0.0) {
        result.distance = std::numeric_limits<double>::infinity();
        return result;
    }
    double v = (d11 * d20 - d01 * d21) / det;
    double w = (d00 * d21 - d01 * d20) / det;
    v = std::clamp(v, 0.0, 1.0);
    w = std::clamp(w, 0.0, 1.0 - v);
    result.v = v;
    result.w = w;
    result.u = 1.0 - v - w;
    result.distance = distance(p, a * result.u + b * v + c * w);
    return result;
}

} // namespace

std::optional<Vec2> sheetPosition(const CompositeSurface& surface, FaceId face, const Vec3& point) {
    std::shared_ptr<const DerivedGeometry> derived;
    try {
        derived = DerivedGeometry::of(surface, kSheetSamples);
    } catch (const std::exception&) {
        return std::nullopt;
    }
    const SampledMesh& mesh = derived->mesh();
    const Development& development = derived->development();
    std::optional<Vec2> best;
    double bestDistance = std::numeric_limits<double>::infinity();
    for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
        if (mesh.faceOrigin[f] != face) {
            continue;
        }
        const std::vector<int>& loop = mesh.faces[f];
        for (std::size_t k = 1; k + 1 < loop.size(); ++k) {
            const auto a = static_cast<std::size_t>(loop[0]);
            const auto b = static_cast<std::size_t>(loop[k]);
            const auto c = static_cast<std::size_t>(loop[k + 1]);
            const Barycentric at =
                locate(point, mesh.vertices[a], mesh.vertices[b], mesh.vertices[c]);
            if (at.distance < bestDistance) {
                bestDistance = at.distance;
                best = development.vertices[a] * at.u + development.vertices[b] * at.v +
                       development.vertices[c] * at.w;
            }
        }
    }
    return best;
}

} // namespace devsurf::model
