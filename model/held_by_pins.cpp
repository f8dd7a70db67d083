#include "held_by_pins.h"
#include "derived_geometry.h"

#include "development.h"
#include "model_error.h"
#include "sampled_mesh.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <memory>
#include <set>
#include <sstream>
#include <unordered_map>
#include <utility>

namespace devsurf::model {

namespace {

// Samples per spline interval of the development (the pins' distances are those of its coarse
// vertices, which are exact; the samples only outline the sheet).
constexpr int kOutlineSamples = 2;
// Points tested along a line between two pins, that it lies in the sheet.
constexpr int kLineSamples = 32;
// Above this many pins only the lines between two of them are looked at, not the triangles of
// three (their number grows with the cube: 300 pins make 4.5 million).
constexpr std::size_t kMostPinsForTriangles = 300;

// The development as triangles in a uniform grid of cells, to test quickly whether a point lies
// in the sheet.
class Outline {
public:
    // Keeps a reference to the development's points, which must outlive it.
    Outline(const SampledMesh& mesh, const Development& development, double scale)
        : m_points(development.vertices), m_tolerance(1e-9 * scale) {
        std::unordered_map<std::uint64_t, int> sides;
        for (const std::vector<int>& face : mesh.faces) {
            for (std::size_t k = 1; k + 1 < face.size(); ++k) {
                m_triangles.push_back({face[0], face[k], face[k + 1]});
            }
            for (std::size_t k = 0; k < face.size(); ++k) {
                const int a = face[k];
                const int b = face[(k + 1) % face.size()];
                ++sides[(static_cast<std::uint64_t>(std::min(a, b)) << 32) |
                        static_cast<std::uint32_t>(std::max(a, b))];
            }
        }
        std::set<int> boundary;
        for (const auto& [side, count] : sides) {
            if (count == 1) {
                boundary.insert(static_cast<int>(side >> 32));
                boundary.insert(static_cast<int>(side & 0xffffffffU));
            }
        }
        for (int vertex : boundary) {
            m_boundary.push_back(m_points[static_cast<std::size_t>(vertex)]);
        }
        buildGrid();
    }

    bool contains(const Vec2& p) const {
        const long cell = cellOf(p);
        if (cell < 0) {
            return false;
        }
        for (int index : m_cells[static_cast<std::size_t>(cell)]) {
            const std::array<int, 3>& t = m_triangles[static_cast<std::size_t>(index)];
            const Vec2& a = m_points[static_cast<std::size_t>(t[0])];
            const Vec2& b = m_points[static_cast<std::size_t>(t[1])];
            const Vec2& c = m_points[static_cast<std::size_t>(t[2])];
            const double area = cross2(b - a, c - a);
            if (area == 0.0) {
                continue;
            }
            const double sign = area > 0.0 ? 1.0 : -1.0;
            const double tolerance = m_tolerance * (b - a).norm();
            if (sign * cross2(b - a, p - a) >= -tolerance &&
                sign * cross2(c - b, p - b) >= -tolerance &&
                sign * cross2(a - c, p - c) >= -tolerance) {
                return true;
            }
        }
        return false;
    }

    // Whether the segment from p to q lies in the sheet (tested at evenly spaced points, the
    // middle ones first: a line across a hole or a notch leaves the sheet there; a slit
    // narrower than half a triangle of the outline can pass unseen).
    bool containsSegment(const Vec2& p, const Vec2& q) const {
        // At least two points per grid cell along it (a cell holds about one triangle).
        const int half = std::max(
            kLineSamples / 2, static_cast<int>(std::min(1e6, std::ceil((q - p).norm() / m_cell))));
        for (int k = 0; k <= 2 * half; ++k) {
            const int step = (k % 2 == 0) ? k / 2 : -(k + 1) / 2;
            const double t = 0.5 + static_cast<double>(step) / (2 * half);
            if (!contains(p + (q - p) * t)) {
                return false;
            }
        }
        return true;
    }

    // Whether some point of the sheet's boundary lies strictly inside the triangle abc (a hole
    // or a notch inside it).
    bool boundaryInside(const Vec2& a, const Vec2& b, const Vec2& c) const {
        const double area = cross2(b - a, c - a);
        for (const Vec2& p : m_boundary) {
            const double u = cross2(b - p, c - p) / area;
            const double v = cross2(c - p, a - p) / area;
            const double w = cross2(a - p, b - p) / area;
            if (u > 1e-6 && v > 1e-6 && w > 1e-6) {
                return true;
            }
        }
        return false;
    }

private:
    // About one triangle per cell; each triangle is listed in every cell its bounding box
    // (widened by the tolerance) meets.
    void buildGrid() {
        m_low = Vec2(std::numeric_limits<double>::max(), std::numeric_limits<double>::max());
        Vec2 high(-m_low.x, -m_low.y);
        for (const Vec2& p : m_points) {
            m_low = Vec2(std::min(m_low.x, p.x), std::min(m_low.y, p.y));
            high = Vec2(std::max(high.x, p.x), std::max(high.y, p.y));
        }
        const double margin = 1e-6 * std::max({high.x - m_low.x, high.y - m_low.y, 1e-300});
        m_low = m_low - Vec2(margin, margin);
        high = high + Vec2(margin, margin);
        const double side =
            std::sqrt((high.x - m_low.x) * (high.y - m_low.y) /
                      static_cast<double>(std::max<std::size_t>(1, m_triangles.size())));
        m_cell = side > 0.0 ? side : std::max(high.x - m_low.x, high.y - m_low.y);
        m_columns = std::max(1L, static_cast<long>(std::ceil((high.x - m_low.x) / m_cell)));
        m_rows = std::max(1L, static_cast<long>(std::ceil((high.y - m_low.y) / m_cell)));
        m_cells.assign(static_cast<std::size_t>(m_columns * m_rows), {});
        for (std::size_t index = 0; index < m_triangles.size(); ++index) {
            Vec2 lo(std::numeric_limits<double>::max(), std::numeric_limits<double>::max());
            Vec2 hi(-lo.x, -lo.y);
            for (int vertex : m_triangles[index]) {
                const Vec2& p = m_points[static_cast<std::size_t>(vertex)];
                lo = Vec2(std::min(lo.x, p.x), std::min(lo.y, p.y));
                hi = Vec2(std::max(hi.x, p.x), std::max(hi.y, p.y));
            }
            const long c0 = column(lo.x - margin);
            const long c1 = column(hi.x + margin);
            const long r0 = row(lo.y - margin);
            const long r1 = row(hi.y + margin);
            for (long r = r0; r <= r1; ++r) {
                for (long c = c0; c <= c1; ++c) {
                    m_cells[static_cast<std::size_t>(r * m_columns + c)].push_back(
                        static_cast<int>(index));
                }
            }
        }
    }
    long column(double x) const {
        return std::clamp(static_cast<long>(std::floor((x - m_low.x) / m_cell)), 0L, m_columns - 1);
    }
    long row(double y) const {
        return std::clamp(static_cast<long>(std::floor((y - m_low.y) / m_cell)), 0L, m_rows - 1);
    }
    long cellOf(const Vec2& p) const {
        const double x = (p.x - m_low.x) / m_cell;
        const double y = (p.y - m_low.y) / m_cell;
        if (!(x >= 0.0 && y >= 0.0 && x < static_cast<double>(m_columns) &&
              y < static_cast<double>(m_rows))) {
            return -1; // outside the development's bounding box (or not a number)
        }
        return static_cast<long>(y) * m_columns + static_cast<long>(x);
    }

    const std::vector<Vec2>& m_points;
    std::vector<std::array<int, 3>> m_triangles;
    std::vector<Vec2> m_boundary;
    double m_tolerance;
    Vec2 m_low;
    double m_cell = 1.0;
    long m_columns = 1;
    long m_rows = 1;
    std::vector<std::vector<int>> m_cells;
};

// The surface's pins, its development and the pairs of pins that hold a line straight.
struct TautLines {
    std::shared_ptr<const DerivedGeometry> derived; // owns the mesh and the development
    std::map<VertexId, Vec2> flat;                  // coarse vertices in the development
    std::unique_ptr<Outline> outline;
    std::vector<VertexId> pins;
    std::vector<std::pair<std::size_t, std::size_t>> taut; // indices into pins, i < j
    std::vector<char> tautMatrix;                          // pins.size()²
    bool isTaut(std::size_t i, std::size_t j) const {      // i < j
        return tautMatrix[i * pins.size() + j] != 0;
    }
};

std::optional<TautLines> tautLinesOf(const CompositeSurface& surface, double relativeTolerance) {
    const std::set<VertexId>& pinned = surface.pinnedVertices();
    if (pinned.size() < 2) {
        return std::nullopt;
    }
    TautLines lines;
    try {
        lines.derived = DerivedGeometry::of(surface, kOutlineSamples);
    } catch (const ModelError&) {
        return std::nullopt; // not a valid surface: nothing to say about it
    }
    const SampledMesh& mesh = lines.derived->mesh();
    const Development& development = lines.derived->development();
    if (development.components != 1 || development.period) {
        return std::nullopt;
    }
    double scale = 0.0;
    for (const Vec2& p : development.vertices) {
        scale = std::max({scale, std::abs(p.x), std::abs(p.y)});
    }
    if (!(scale > 0.0) || development.closureError > 1e-6 * scale) {
        return std::nullopt; // not developable enough for its distances to mean anything
    }
    for (std::size_t i = 0; i < mesh.coarseVertexIds.size(); ++i) {
        lines.flat[mesh.coarseVertexIds[i]] = development.vertices[i];
    }
    lines.outline = std::make_unique<Outline>(mesh, development, scale);

    // Pairs of pins as far apart as in the development, along a line in the sheet.
    lines.pins.assign(pinned.begin(), pinned.end());
    const std::vector<VertexId>& pins = lines.pins;
    lines.tautMatrix.assign(pins.size() * pins.size(), 0);
    for (std::size_t i = 0; i < pins.size(); ++i) {
        for (std::size_t j = i + 1; j < pins.size(); ++j) {
            const Vec2 a = lines.flat.at(pins[i]);
            const Vec2 b = lines.flat.at(pins[j]);
            const double inPlane = (b - a).norm();
            const double inSpace = distance(surface.position(pins[i]), surface.position(pins[j]));
            if (inPlane > 0.0 && inSpace >= inPlane * (1.0 - relativeTolerance) &&
                lines.outline->containsSegment(a, b)) {
                lines.taut.push_back({i, j});
                lines.tautMatrix[i * pins.size() + j] = 1;
            }
        }
    }
    return lines;
}

} // namespace

std::vector<std::pair<VertexId, VertexId>> findTautPinLines(const CompositeSurface& surface,
                                                            double relativeTolerance) {
    std::vector<std::pair<VertexId, VertexId>> found;
    const std::optional<TautLines> lines = tautLinesOf(surface, relativeTolerance);
    if (!lines) {
        return found;
    }
    for (const auto& [i, j] : lines->taut) {
        const VertexId a = lines->pins[i];
        const VertexId b = lines->pins[j];
        const EdgeId edge = surface.edgeBetween(a, b);
        if (edge != kInvalidId && !surface.edge(edge).isSpline()) {
            continue; // a ruling: straight anyway
        }
        found.push_back({a, b});
    }
    return found;
}

std::optional<HeldVertex> findVertexHeldByPins(const CompositeSurface& surface,
                                               const std::vector<VertexId>& vertices,
                                               double relativeTolerance) {
    const std::set<VertexId>& pinned = surface.pinnedVertices();
    std::vector<VertexId> moving;
    for (VertexId vertex : vertices) {
        if (surface.hasVertex(vertex) && pinned.count(vertex) == 0) {
            moving.push_back(vertex);
        }
    }
    if (pinned.size() < 2 || moving.empty()) {
        return std::nullopt;
    }
    const std::optional<TautLines> lines = tautLinesOf(surface, relativeTolerance);
    if (!lines) {
        return std::nullopt;
    }
    const std::vector<VertexId>& pins = lines->pins;
    const std::map<VertexId, Vec2>& flat = lines->flat;
    const Outline& outline = *lines->outline;
    const auto& taut = lines->taut;
    auto isTaut = [&](std::size_t i, std::size_t j) { return lines->isTaut(i, j); };

    for (VertexId vertex : moving) {
        const Vec2 p = flat.at(vertex);
        for (const auto& [i, j] : taut) {
            const VertexId a = pins[i];
            const VertexId b = pins[j];
            const Vec2 pa = flat.at(a);
            const Vec2 pb = flat.at(b);
            const Vec2 d = pb - pa;
            const double length = d.norm();
            const double along = (d.x * (p - pa).x + d.y * (p - pa).y) / (length * length);
            if (along > 0.0 && along < 1.0 &&
                std::abs(cross2(d, p - pa)) / length <= relativeTolerance * length) {
                return HeldVertex{vertex, {a, b}};
            }
        }
        if (pins.size() > kMostPinsForTriangles) {
            continue;
        }
        for (std::size_t i = 0; i < pins.size(); ++i) {
            for (std::size_t j = i + 1; j < pins.size(); ++j) {
                if (!isTaut(i, j)) {
                    continue;
                }
                for (std::size_t k = j + 1; k < pins.size(); ++k) {
                    if (!isTaut(i, k) || !isTaut(j, k)) {
                        continue;
                    }
                    const Vec2 a = flat.at(pins[i]);
                    const Vec2 b = flat.at(pins[j]);
                    const Vec2 c = flat.at(pins[k]);
                    const double area = cross2(b - a, c - a);
                    const double size = std::max({(b - a).norm(), (c - b).norm(), (a - c).norm()});
                    if (std::abs(area) <= 1e-6 * size * size) {
                        continue; // three pins on a line hold only that line
                    }
                    const double u = cross2(b - p, c - p) / area;
                    const double v = cross2(c - p, a - p) / area;
                    const double w = cross2(a - p, b - p) / area;
                    const double inside = -relativeTolerance;
                    if (u >= inside && v >= inside && w >= inside &&
                        !outline.boundaryInside(a, b, c)) {
                        return HeldVertex{vertex, {pins[i], pins[j], pins[k]}};
                    }
                }
            }
        }
    }
    return std::nullopt;
}

} // namespace devsurf::model
