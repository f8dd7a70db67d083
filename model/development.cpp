#include "development.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <deque>
#include <limits>

namespace devsurf::model {

namespace {

struct Triangle {
    std::array<int, 3> v;
    std::array<Vec2, 3> corner; // this triangle's own placement of its vertices
    bool placed = false;
};

// Places c on the left of the directed segment pa→pb with |c−pa| = da and |c−pb| = db.
Vec2 placeApex(const Vec2& pa, const Vec2& pb, double da, double db) {
    const Vec2 d = pb - pa;
    const double length = d.norm();
    if (length <= 0.0) {
        return pa;
    }
    const Vec2 along = d * (1.0 / length);
    const Vec2 left(-along.y, along.x);
    const double x = (da * da - db * db + length * length) / (2.0 * length);
    const double y = std::sqrt(std::max(0.0, da * da - x * x));
    return pa + along * x + left * y;
}

Vec2 reduce(const Vec2& d, const std::optional<Vec2>& period) {
    if (!period) {
        return d;
    }
    Vec2 best = d;
    for (int k = -2; k <= 2; ++k) {
        const Vec2 candidate = d + *period * static_cast<double>(k);
        if (candidate.norm() < best.norm()) {
            best = candidate;
        }
    }
    return best;
}

Vec2 rotate(const Vec2& p, double angle) {
    const double c = std::cos(angle);
    const double s = std::sin(angle);
    return Vec2(c * p.x - s * p.y, s * p.x + c * p.y);
}

// Rigidly moves the development of one component onto the xy projection of its 3D vertices
// (least squares rotation about the centroids).
void alignToProjection(const SampledMesh& mesh, const std::vector<int>& component,
                       std::vector<Vec2>& positions) {
    if (component.empty()) {
        return;
    }
    Vec2 c2d;
    Vec2 c3d;
    for (int i : component) {
        c2d = c2d + positions[i];
        c3d = c3d + Vec2(mesh.vertices[i].x, mesh.vertices[i].y);
    }
    const double inverse = 1.0 / static_cast<double>(component.size());
    c2d = c2d * inverse;
    c3d = c3d * inverse;
    double sumDot = 0.0;
    double sumCross = 0.0;
    for (int i : component) {
        const Vec2 p = positions[i] - c2d;
        const Vec2 q = Vec2(mesh.vertices[i].x, mesh.vertices[i].y) - c3d;
        sumDot += p.x * q.x + p.y * q.y;
        sumCross += cross2(p, q);
    }
    const double angle = std::atan2(sumCross, sumDot);
    for (int i : component) {
        positions[i] = rotate(positions[i] - c2d, angle) + c3d;
    }
}

} // namespace

std::optional<Problem> keepDevelopment(CompositeSurface& surface) {
    const Development unfolded =
        unfoldSampledMesh(sampleSurface(surface, kDevelopmentSamplesPerInterval));
    if (unfolded.components != 1 || unfolded.closureError > kOneSheetClosure) {
        Problem problem = problemOf(ProblemCode::NotOneSheet);
        problem.count = unfolded.components;
        problem.value = unfolded.closureError;
        return problem;
    }
    surface.setKeepsDevelopment(true);
    surface.setDevelopment(unfolded.vertices);
    if (unfolded.period) {
        // Closed around (Fig. 14): the sheet is the cylinder it unrolls from.
        SheetDomain cylinder;
        cylinder.shape = SheetShape::Cylinder;
        cylinder.radius = unfolded.period->norm() / (2.0 * 3.14159265358979323846);
        cylinder.angle = std::atan2(unfolded.period->y, unfolded.period->x);
        surface.setSheetDomain(cylinder);
    }
    return std::nullopt;
}

Development unfoldSampledMesh(const SampledMesh& mesh) {
    Development dev;
    dev.vertices.assign(mesh.vertices.size(), Vec2());

    std::vector<Triangle> triangles;
    for (const auto& face : mesh.faces) {
        for (std::size_t i = 1; i + 1 < face.size(); ++i) {
            triangles.push_back({{face[0], face[i], face[i + 1]}, {}, false});
        }
    }
    // Triangles across each undirected edge (side 3t + k is side k of triangle t).
    std::vector<std::pair<int, int>> sideEdges;
    sideEdges.reserve(3 * triangles.size());
    for (const Triangle& triangle : triangles) {
        for (int k = 0; k < 3; ++k) {
            const int a = triangle.v[k];
            const int b = triangle.v[(k + 1) % 3];
            sideEdges.emplace_back(std::min(a, b), std::max(a, b));
        }
    }
    const SidesByEdge byEdge = groupSidesByEdge(sideEdges);
    auto length = [&mesh](int a, int b) { return distance(mesh.vertices[a], mesh.vertices[b]); };

    std::vector<char> vertexPlaced(mesh.vertices.size(), 0);
    std::vector<std::pair<int, int>> nonTreeAdjacencies;
    std::vector<std::vector<int>> components;

    for (int seed = 0; seed < static_cast<int>(triangles.size()); ++seed) {
        if (triangles[seed].placed) {
            continue;
        }
        ++dev.components;
        std::vector<int> componentVertices;
        Triangle& first = triangles[seed];
        first.corner[0] = Vec2(0, 0);
        first.corner[1] = Vec2(length(first.v[0], first.v[1]), 0);
        first.corner[2] = placeApex(first.corner[0], first.corner[1],
                                    length(first.v[0], first.v[2]), length(first.v[1], first.v[2]));
        first.placed = true;
        std::deque<int> queue{seed};
        while (!queue.empty()) {
            const int t = queue.front();
            queue.pop_front();
            const Triangle& tri = triangles[t];
            for (int k = 0; k < 3; ++k) {
                if (!vertexPlaced[tri.v[k]]) {
                    vertexPlaced[tri.v[k]] = 1;
                    dev.vertices[tri.v[k]] = tri.corner[k];
                    componentVertices.push_back(tri.v[k]);
                }
            }
            for (int k = 0; k < 3; ++k) {
                const int a = tri.v[k];
                const int b = tri.v[(k + 1) % 3];
                const auto [first, last] = byEdge.run[static_cast<std::size_t>(3 * t + k)];
                for (std::size_t i = first; i < last; ++i) {
                    const auto n = static_cast<int>(byEdge.order[i] / 3);
                    if (n == t) {
                        continue;
                    }
                    Triangle& next = triangles[n];
                    if (next.placed) {
                        if (n > t) {
                            nonTreeAdjacencies.emplace_back(t, n);
                        }
                        continue;
                    }
                    // The neighbour lies on the other side of the shared edge, i.e. on the
                    // left of b → a.
                    int ia = 0;
                    int ib = 0;
                    for (int j = 0; j < 3; ++j) {
                        ia = next.v[j] == a ? j : ia;
                        ib = next.v[j] == b ? j : ib;
                    }
                    const int ic = 3 - ia - ib;
                    const Vec2 pa = tri.corner[k];
                    const Vec2 pb = tri.corner[(k + 1) % 3];
                    next.corner[ia] = pa;
                    next.corner[ib] = pb;
                    next.corner[ic] = placeApex(pb, pa, length(next.v[ib], next.v[ic]),
                                                length(next.v[ia], next.v[ic]));
                    next.placed = true;
                    queue.push_back(n);
                }
            }
        }
        components.push_back(std::move(componentVertices));
    }

    // A closing translation between neighbours that were unfolded along different paths.
    double largest = 0.0;
    for (const auto& [t1, t2] : nonTreeAdjacencies) {
        for (int k = 0; k < 3; ++k) {
            for (int j = 0; j < 3; ++j) {
                if (triangles[t1].v[k] == triangles[t2].v[j]) {
                    const Vec2 d = triangles[t2].corner[j] - triangles[t1].corner[k];
                    if (d.norm() > largest) {
                        largest = d.norm();
                        dev.period = d;
                    }
                }
            }
        }
    }
    double scale = 0.0;
    for (const Vec3& p : mesh.vertices) {
        scale = std::max(scale, std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z)}));
    }
    const double tolerance = 1e-9 * std::max(scale, 1.0);
    if (largest <= tolerance) {
        dev.period.reset();
    } else {
        // A period is a translation that every closing mismatch agrees with (a cylinder cut
        // open). A surface that is not exactly developable (a flat design with one vertex
        // lifted) closes up with mismatches that vary along the seam: that is no period, and
        // reading the development modulo it would fold the drawing onto a thin band.
        const double slack = std::max(tolerance, 0.01 * largest);
        for (const auto& [t1, t2] : nonTreeAdjacencies) {
            for (int k = 0; k < 3 && dev.period; ++k) {
                for (int j = 0; j < 3 && dev.period; ++j) {
                    if (triangles[t1].v[k] != triangles[t2].v[j]) {
                        continue;
                    }
                    const Vec2 d = triangles[t2].corner[j] - triangles[t1].corner[k];
                    const double off =
                        std::min({d.norm(), (d - *dev.period).norm(), (d + *dev.period).norm()});
                    if (off > slack) {
                        dev.period.reset();
                    }
                }
            }
        }
    }
    for (const Triangle& tri : triangles) {
        for (int k = 0; k < 3; ++k) {
            const Vec2 d = reduce(tri.corner[k] - dev.vertices[tri.v[k]], dev.period);
            dev.closureError = std::max(dev.closureError, d.norm());
        }
    }

    // Orientation: a cylinder's period along +x; otherwise each component gets the best
    // rotation onto its xy projection (exact for flat pieces lying in that plane).
    if (dev.period) {
        const double angle = -std::atan2(dev.period->y, dev.period->x);
        for (Vec2& p : dev.vertices) {
            p = rotate(p, angle);
        }
        dev.period = rotate(*dev.period, angle);
    } else {
        for (const auto& component : components) {
            alignToProjection(mesh, component, dev.vertices);
        }
    }
    dev.maxEdgeLengthError = edgeLengthError(mesh, dev);
    return dev;
}

namespace {

// The largest difference between a distance in space and in the kept development over every
// pair of every sampled face, absolute (mm) or relative to the distance in the sheet.
double keptSheetPairError(const CompositeSurface& surface, bool relative) {
    if (!surface.keepsDevelopment()) {
        return -1.0;
    }
    const std::vector<Vec2>& flat = surface.development();
    const SampledMesh mesh = sampleSurface(surface, kDevelopmentSamplesPerInterval);
    if (flat.size() != mesh.vertices.size()) {
        return -1.0;
    }
    const std::optional<Vec2> period = domainPeriod(surface.sheetDomain());
    double worst = 0.0;
    for (const auto& face : mesh.faces) {
        for (std::size_t i = 0; i < face.size(); ++i) {
            for (std::size_t j = i + 1; j < face.size(); ++j) {
                const auto a = static_cast<std::size_t>(face[i]);
                const auto b = static_cast<std::size_t>(face[j]);
                const double inSheet = reduce(flat[a] - flat[b], period).norm();
                const double gap = std::abs(distance(mesh.vertices[a], mesh.vertices[b]) - inSheet);
                if (!relative) {
                    worst = std::max(worst, gap);
                } else if (inSheet > 0.0) {
                    worst = std::max(worst, gap / inSheet);
                }
            }
        }
    }
    return worst;
}

} // namespace

double keptSheetStretch(const CompositeSurface& surface) {
    return keptSheetPairError(surface, false);
}

double keptSheetStretchRelative(const CompositeSurface& surface) {
    return keptSheetPairError(surface, true);
}

double edgeLengthError(const SampledMesh& mesh, const Development& development) {
    double worst = 0.0;
    for (const auto& face : mesh.faces) {
        for (std::size_t i = 0; i < face.size(); ++i) {
            const int a = face[i];
            const int b = face[(i + 1) % face.size()];
            const double l3 = distance(mesh.vertices[a], mesh.vertices[b]);
            const double l2 =
                reduce(development.vertices[a] - development.vertices[b], development.period)
                    .norm();
            if (l3 > 0.0) {
                worst = std::max(worst, std::abs(l3 - l2) / l3);
            }
        }
    }
    return worst;
}

} // namespace devsurf::model
