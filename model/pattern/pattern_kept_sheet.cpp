#include "pattern_kept_sheet.h"

#include "model/derived_geometry.h"
#include "model/plane_motion.h"
#include "model/sampled_mesh.h"

#include <map>
#include <optional>

namespace devsurf::model::pattern {

bool copiesCoincide(const CutMesh& cut, const Development& development, double tolerance) {
    std::map<int, int> firstCopy;
    for (std::size_t v = 0; v < cut.original.size(); ++v) {
        const auto [it, inserted] = firstCopy.emplace(cut.original[v], static_cast<int>(v));
        if (!inserted &&
            (development.vertices[v] - development.vertices[static_cast<std::size_t>(it->second)])
                    .norm() > tolerance) {
            return false;
        }
    }
    return true;
}

bool layOntoKeptSheet(const CompositeSurface& surface, const SampledMesh& mesh, const CutMesh& cut,
                      Development& development) {
    const std::vector<Vec2>& kept = surface.development();
    if (!surface.keepsDevelopment() || development.period || development.components != 1 ||
        surface.sheetDomain().shape == SheetShape::Cylinder ||
        development.vertices.size() != cut.original.size() ||
        kept.size() != sampledVertexCount(surface, kDevelopmentSamplesPerInterval)) {
        return false;
    }
    // The kept development's own sampling, cached with the surface's other derived geometry.
    const auto keptSampling = DerivedGeometry::of(surface, kDevelopmentSamplesPerInterval);
    const SampledMesh& coarse = keptSampling->mesh();
    // For every vertex of `mesh`, the kept sample at the same place on the surface, if any.
    std::vector<int> shared(mesh.vertices.size(), -1);
    for (std::size_t v = 0; v < mesh.coarseVertexIds.size(); ++v) {
        shared[v] = static_cast<int>(v); // the coarse vertices come first in both
    }
    std::map<EdgeId, const SampledMesh::Polyline*> keptLine;
    for (const SampledMesh::Polyline& line : coarse.splineEdges) {
        keptLine[line.edge] = &line;
    }
    for (const SampledMesh::Polyline& line : mesh.splineEdges) {
        const auto it = keptLine.find(line.edge);
        if (it == keptLine.end() || line.vertices.size() < 2) {
            return false;
        }
        const std::size_t fine = line.vertices.size() - 1;
        const std::size_t other = it->second->vertices.size() - 1;
        for (std::size_t k = 0; k <= fine; ++k) {
            if ((k * other) % fine == 0) {
                shared[static_cast<std::size_t>(line.vertices[k])] =
                    it->second->vertices[k * other / fine];
            }
        }
    }
    // Where the cut mesh's vertex v lies on the kept sheet, if it is a shared sample.
    auto keptAt = [&](std::size_t v) -> std::optional<Vec2> {
        const int s = shared[static_cast<std::size_t>(cut.original[v])];
        return s >= 0 ? std::optional<Vec2>(kept[static_cast<std::size_t>(s)]) : std::nullopt;
    };
    std::vector<Vec2> from;
    std::vector<Vec2> to;
    for (std::size_t v = 0; v < cut.original.size(); ++v) {
        if (const auto place = keptAt(v)) {
            from.push_back(development.vertices[v]);
            to.push_back(*place);
        }
    }
    const std::optional<PlaneMotion> motion = fitPlaneMotion(from, to);
    if (!motion) {
        return false;
    }
    std::vector<Vec2> laid(development.vertices.size());
    for (std::size_t v = 0; v < laid.size(); ++v) {
        laid[v] = motion->apply(development.vertices[v]);
    }
    // The samples between two shared ones along a curve follow them linearly, on each side of
    // a cut with that side's copies (which the unfolding placed together).
    std::vector<Vec2> placed = laid;
    const auto copies = edgeCopies(mesh, cut);
    for (const SampledMesh::Polyline& line : mesh.splineEdges) {
        for (const std::vector<int>& side : polylineCopies(line.vertices, copies)) {
            std::size_t last = 0; // index along the side of the last shared sample
            for (std::size_t k = 0; k < side.size(); ++k) {
                const auto v = static_cast<std::size_t>(side[k]);
                const auto place = keptAt(v);
                if (!place) {
                    continue;
                }
                const auto w = static_cast<std::size_t>(side[last]);
                const auto lastPlace = keptAt(w);
                if (k > last && lastPlace) {
                    const Vec2 a = *lastPlace - laid[w];
                    const Vec2 b = *place - laid[v];
                    for (std::size_t i = last; i <= k; ++i) {
                        const double t =
                            static_cast<double>(i - last) / static_cast<double>(k - last);
                        const auto u = static_cast<std::size_t>(side[i]);
                        placed[u] = laid[u] + a * (1.0 - t) + b * t;
                    }
                }
                last = k;
            }
        }
    }
    for (std::size_t v = 0; v < placed.size(); ++v) {
        if (const auto place = keptAt(v)) {
            placed[v] = *place;
        }
    }
    development.vertices = std::move(placed);
    return true;
}

} // namespace devsurf::model::pattern
