#include "scene_geometry.h"

#include "model/development.h"
#include "model/sampled_mesh.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <set>

namespace devsurf::views {

using model::EdgeId;
using model::FaceId;
using model::Vec2;
using model::Vec3;
using model::VertexId;

namespace {

// Mesh index of every coarse vertex (the sampled mesh lists them first).
std::map<VertexId, int> coarseIndex(const model::SampledMesh& mesh) {
    std::map<VertexId, int> index;
    for (std::size_t i = 0; i < mesh.coarseVertexIds.size(); ++i) {
        index[mesh.coarseVertexIds[i]] = static_cast<int>(i);
    }
    return index;
}

// The coarse edges as index polylines into the sampled mesh, in their stored orientation.
std::vector<std::pair<EdgeId, std::vector<int>>>
edgePolylines(const model::CompositeSurface& surface, const model::SampledMesh& mesh) {
    const std::map<VertexId, int> index = coarseIndex(mesh);
    std::map<EdgeId, std::vector<int>> sampled;
    for (const auto& line : mesh.splineEdges) {
        sampled[line.edge] = line.vertices;
    }
    std::vector<std::pair<EdgeId, std::vector<int>>> result;
    for (const auto& [id, record] : surface.edges()) {
        auto it = sampled.find(id);
        if (it != sampled.end()) {
            result.emplace_back(id, it->second);
        } else {
            result.emplace_back(id, std::vector<int>{index.at(record.from), index.at(record.to)});
        }
    }
    return result;
}

EdgeCurve makeCurve(const model::CompositeSurface& surface, EdgeId id) {
    EdgeCurve curve;
    curve.id = id;
    curve.spline = surface.edge(id).isSpline();
    const std::size_t faces = surface.facesOfEdge(id).size();
    curve.crease = curve.spline && faces == 2;
    curve.boundary = faces == 1;
    return curve;
}

Vec3 toScene(const Vec2& p, double dx, double dy) {
    return {p.x + dx, p.y + dy, 0.0};
}

// The copy of q (modulo the period) nearest to reference.
Vec2 unwrap(const Vec2& q, const Vec2& reference, const std::optional<Vec2>& period) {
    if (!period) {
        return q;
    }
    const double len2 = period->x * period->x + period->y * period->y;
    if (len2 <= 0.0) {
        return q;
    }
    const Vec2 diff = reference - q;
    const double k = std::round((diff.x * period->x + diff.y * period->y) / len2);
    return q + *period * k;
}

} // namespace

SurfaceScene buildSpatialScene(const model::CompositeSurface& surface, int surfaceIndex) {
    const model::SampledMesh mesh = model::sampleSurface(surface, kSamplesPerInterval);
    SurfaceScene scene;
    scene.surface = surfaceIndex;

    // One copy of a sampled vertex per coarse face: normals are smooth inside a patch and
    // break at creases, where the surface has a kink.
    std::map<std::pair<FaceId, int>, int> local;
    for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
        const FaceId face = mesh.faceOrigin[f];
        std::vector<int> polygon;
        for (int v : mesh.faces[f]) {
            auto [it, inserted] = local.emplace(std::make_pair(face, v), 0);
            if (inserted) {
                it->second = static_cast<int>(scene.points.size());
                scene.points.push_back(mesh.vertices[static_cast<std::size_t>(v)]);
                scene.normals.emplace_back();
            }
            polygon.push_back(it->second);
        }
        // Newell's normal: robust for quads that are not exactly planar and for triangles.
        Vec3 normal;
        for (std::size_t i = 0; i < polygon.size(); ++i) {
            const Vec3& a = scene.points[static_cast<std::size_t>(polygon[i])];
            const Vec3& b =
                scene.points[static_cast<std::size_t>(polygon[(i + 1) % polygon.size()])];
            normal += cross(a, b);
        }
        for (int p : polygon) {
            scene.normals[static_cast<std::size_t>(p)] += normal;
        }
        scene.polygons.push_back(std::move(polygon));
        scene.polygonFace.push_back(face);
    }
    for (Vec3& n : scene.normals) {
        const double len = n.norm();
        n = len > 0.0 ? n / len : Vec3(0.0, 0.0, 1.0);
    }

    for (const auto& [id, indices] : edgePolylines(surface, mesh)) {
        EdgeCurve curve = makeCurve(surface, id);
        for (int v : indices) {
            curve.points.push_back(mesh.vertices[static_cast<std::size_t>(v)]);
        }
        if (curve.spline) {
            const auto& controls = surface.edge(id).controlPoints;
            scene.controlPolygons.push_back(controls);
            for (std::size_t i = 1; i + 1 < controls.size(); ++i) {
                scene.controlPoints.push_back(controls[i]);
            }
        }
        scene.edges.push_back(std::move(curve));
    }
    scene.vertices = surface.vertices();
    return scene;
}

SurfaceScene buildDevelopmentScene(const model::CompositeSurface& surface, int surfaceIndex,
                                   double x0) {
    const model::SampledMesh mesh = model::sampleSurface(surface, kSamplesPerInterval);
    const model::Development development = model::unfoldSampledMesh(mesh);
    const auto& flat = development.vertices;
    const auto& period = development.period;

    // A periodic development (a cylinder cut open) is drawn over one period, starting at the
    // first coarse vertex (so the cut runs along a ruling through vertices). Every face, ruling and
    // edge is first unwrapped around its first point and then moved by whole periods until its
    // centroid lies in that window, so that the pieces along the cut are drawn whole and on the
    // same side.
    double windowStart = 0.0;
    double period2 = 0.0;
    if (period) {
        period2 = period->x * period->x + period->y * period->y;
        windowStart = std::numeric_limits<double>::infinity();
        for (std::size_t i = 0; i < mesh.coarseVertexIds.size(); ++i) {
            const Vec2& v = flat[i];
            windowStart = std::min(windowStart, (v.x * period->x + v.y * period->y) / period2);
        }
        windowStart -= 1e-9;
    }
    auto place = [&](const std::vector<int>& indices, bool chain) {
        std::vector<Vec2> points;
        Vec2 reference = flat[static_cast<std::size_t>(indices.front())];
        for (int v : indices) {
            points.push_back(unwrap(flat[static_cast<std::size_t>(v)], reference, period));
            if (chain) {
                reference = points.back();
            }
        }
        if (period && period2 > 0.0) {
            Vec2 centroid;
            for (const Vec2& p : points) {
                centroid = centroid + p * (1.0 / static_cast<double>(points.size()));
            }
            const double u = (centroid.x * period->x + centroid.y * period->y) / period2;
            const double k = std::ceil(windowStart - u);
            for (Vec2& p : points) {
                p = p + *period * k;
            }
        }
        return points;
    };

    std::vector<std::vector<Vec2>> faces;
    for (const auto& face : mesh.faces) {
        faces.push_back(place(face, false));
    }
    // Place the lower left corner of the drawing at (x0, 0).
    double minX = std::numeric_limits<double>::infinity();
    double minY = std::numeric_limits<double>::infinity();
    for (const auto& face : faces) {
        for (const Vec2& p : face) {
            minX = std::min(minX, p.x);
            minY = std::min(minY, p.y);
        }
    }
    if (!std::isfinite(minX)) {
        minX = 0.0;
        minY = 0.0;
    }
    const double dx = x0 - minX;
    const double dy = -minY;

    SurfaceScene scene;
    scene.surface = surfaceIndex;
    std::map<std::pair<int, int>, int> edgeUse; // sampled mesh edge -> number of faces
    for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
        const auto& face = mesh.faces[f];
        std::vector<int> polygon;
        for (std::size_t i = 0; i < face.size(); ++i) {
            polygon.push_back(static_cast<int>(scene.points.size()));
            scene.points.push_back(toScene(faces[f][i], dx, dy));
            const int a = face[i];
            const int b = face[(i + 1) % face.size()];
            ++edgeUse[{std::min(a, b), std::max(a, b)}];
        }
        scene.polygons.push_back(std::move(polygon));
        scene.polygonFace.push_back(mesh.faceOrigin[f]);
    }
    // The outline: sampled edges used by a single face, drawn from that face's copy.
    for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
        const auto& face = mesh.faces[f];
        const auto& polygon = scene.polygons[f];
        for (std::size_t i = 0; i < face.size(); ++i) {
            const int a = face[i];
            const int b = face[(i + 1) % face.size()];
            if (a != b && edgeUse[{std::min(a, b), std::max(a, b)}] == 1) {
                scene.outline.emplace_back(
                    scene.points[static_cast<std::size_t>(polygon[i])],
                    scene.points[static_cast<std::size_t>(polygon[(i + 1) % face.size()])]);
            }
        }
    }
    for (const auto& [a, b] : mesh.rulings) {
        const std::vector<Vec2> ends = place({a, b}, false);
        scene.rulings.emplace_back(toScene(ends[0], dx, dy), toScene(ends[1], dx, dy));
    }
    for (const auto& [id, indices] : edgePolylines(surface, mesh)) {
        EdgeCurve curve = makeCurve(surface, id);
        for (const Vec2& p : place(indices, true)) {
            curve.points.push_back(toScene(p, dx, dy));
        }
        scene.edges.push_back(std::move(curve));
    }
    const std::map<VertexId, int> index = coarseIndex(mesh);
    for (const auto& [id, i] : index) {
        scene.vertices[id] = toScene(place({i}, false).front(), dx, dy);
    }
    return scene;
}

std::pair<Vec3, Vec3> sceneBounds(const SurfaceScene& scene) {
    const double inf = std::numeric_limits<double>::infinity();
    Vec3 lo(inf, inf, inf);
    Vec3 hi(-inf, -inf, -inf);
    for (const Vec3& p : scene.points) {
        for (int k = 0; k < 3; ++k) {
            lo[k] = std::min(lo[k], p[k]);
            hi[k] = std::max(hi[k], p[k]);
        }
    }
    return {lo, hi};
}

std::array<double, 3> patchRgb(FaceId face) {
    // Soft, distinguishable colours that keep black curves and the orange highlight readable.
    static const std::array<std::array<double, 3>, 10> palette = {{
        {0.55, 0.71, 0.89},
        {0.96, 0.73, 0.49},
        {0.60, 0.82, 0.58},
        {0.90, 0.58, 0.60},
        {0.74, 0.65, 0.86},
        {0.78, 0.66, 0.56},
        {0.94, 0.71, 0.84},
        {0.70, 0.80, 0.80},
        {0.88, 0.86, 0.55},
        {0.62, 0.84, 0.87},
    }};
    return palette[face % palette.size()];
}

} // namespace devsurf::views
