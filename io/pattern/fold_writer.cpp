// FOLD 1.1 (the crease-pattern JSON of origami software): the pattern's lines become one planar
// graph (shared points merged, lines ending on an edge split it) whose faces are traced, so a
// simulator can fold the design.

#include "pattern_sheets.h"
#include "pattern_writers.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <set>

namespace devsurf::io {

using model::PatternLayer;
using model::Vec2;

namespace {

// Points closer than this are one vertex (far below the pattern's tolerance, far above
// rounding noise of the layout).
constexpr double kMergeDistance = 1e-5;

struct Graph {
    std::vector<Vec2> vertices;
    std::vector<std::pair<int, int>> edges;
    std::vector<char> assignment;
    std::vector<double> angle;
    std::map<std::pair<long long, long long>, std::vector<int>> grid;
    std::set<std::pair<int, int>> edgeSet;

    std::pair<long long, long long> cell(const Vec2& p) const {
        return {static_cast<long long>(std::floor(p.x / kMergeDistance)),
                static_cast<long long>(std::floor(p.y / kMergeDistance))};
    }

    int vertex(const Vec2& p) {
        const auto [cx, cy] = cell(p);
        for (long long dx = -1; dx <= 1; ++dx) {
            for (long long dy = -1; dy <= 1; ++dy) {
                auto it = grid.find({cx + dx, cy + dy});
                if (it == grid.end()) {
                    continue;
                }
                for (int v : it->second) {
                    if ((vertices[std::size_t(v)] - p).norm() <= kMergeDistance) {
                        return v;
                    }
                }
            }
        }
        vertices.push_back(p);
        grid[{cx, cy}].push_back(int(vertices.size()) - 1);
        return int(vertices.size()) - 1;
    }

    void edge(int a, int b, char type, double foldAngle) {
        if (a == b || !edgeSet.insert({std::min(a, b), std::max(a, b)}).second) {
            return;
        }
        edges.emplace_back(a, b);
        assignment.push_back(type);
        angle.push_back(foldAngle);
    }

    // A line that ends inside another edge (a crease meeting the outline between two of its
    // samples, a ruling ending on a sampled crease, within `snap`) splits that edge there, so
    // that the faces close.
    void splitAtDanglingEnds(double snap) {
        std::vector<int> degree(vertices.size(), 0);
        for (const auto& [a, b] : edges) {
            ++degree[std::size_t(a)];
            ++degree[std::size_t(b)];
        }
        for (std::size_t v = 0; v < vertices.size(); ++v) {
            if (degree[v] != 1) {
                continue;
            }
            const Vec2 p = vertices[v];
            for (std::size_t e = 0; e < edges.size(); ++e) {
                const auto [a, b] = edges[e];
                if (a == int(v) || b == int(v)) {
                    continue;
                }
                const Vec2 pa = vertices[std::size_t(a)];
                const Vec2 ab = vertices[std::size_t(b)] - pa;
                const double length2 = ab.x * ab.x + ab.y * ab.y;
                const double t = ((p.x - pa.x) * ab.x + (p.y - pa.y) * ab.y) / length2;
                if (t <= 0.0 || t >= 1.0 || (pa + ab * t - p).norm() > snap) {
                    continue;
                }
                edges[e].second = int(v);
                edgeSet.insert({std::min(int(v), b), std::max(int(v), b)});
                edges.emplace_back(int(v), b);
                assignment.push_back(assignment[e]);
                angle.push_back(angle[e]);
                break;
            }
        }
    }

    // Faces left of every half-edge, traced by turning as far right as possible at each vertex;
    // bounded faces are the counter-clockwise ones.
    std::vector<std::vector<int>> faces(double& area) const {
        const std::size_t n = vertices.size();
        std::vector<std::vector<int>> out(n); // outgoing neighbours sorted by angle
        for (const auto& [a, b] : edges) {
            out[std::size_t(a)].push_back(b);
            out[std::size_t(b)].push_back(a);
        }
        auto direction = [this](int from, int to) {
            const Vec2 d = vertices[std::size_t(to)] - vertices[std::size_t(from)];
            return std::atan2(d.y, d.x);
        };
        for (std::size_t v = 0; v < n; ++v) {
            std::sort(out[v].begin(), out[v].end(),
                      [&](int p, int q) { return direction(int(v), p) < direction(int(v), q); });
        }
        std::set<std::pair<int, int>> used;
        std::vector<std::vector<int>> result;
        area = 0.0;
        for (std::size_t start = 0; start < n; ++start) {
            for (int first : out[start]) {
                if (used.count({int(start), first}) != 0) {
                    continue;
                }
                std::vector<int> face;
                int u = int(start);
                int v = first;
                double twiceArea = 0.0;
                while (used.insert({u, v}).second) {
                    face.push_back(u);
                    const Vec2 pu = vertices[std::size_t(u)];
                    const Vec2 pv = vertices[std::size_t(v)];
                    twiceArea += pu.x * pv.y - pv.x * pu.y;
                    const std::vector<int>& around = out[std::size_t(v)];
                    const auto back = std::find(around.begin(), around.end(), u) - around.begin();
                    const int next =
                        around[std::size_t((back + long(around.size()) - 1) % long(around.size()))];
                    u = v;
                    v = next;
                }
                if (twiceArea > 0.0 && face.size() >= 3) {
                    area += 0.5 * twiceArea;
                    result.push_back(std::move(face));
                }
            }
        }
        return result;
    }
};

char assignmentOf(const model::PatternPath& path) {
    switch (path.layer) {
    case PatternLayer::Cut:
        return 'B';
    case PatternLayer::Mountain:
        return 'M';
    case PatternLayer::Valley:
        return 'V';
    case PatternLayer::Crease:
        return path.foldAngleDegrees && *path.foldAngleDegrees == 0.0 ? 'F' : 'U';
    default: // rulings bend, seam lines fold a tab or allowance back: both flat in the crease
             // pattern
        return 'F';
    }
}

double polygonArea(const std::vector<Vec2>& polygon) {
    double twice = 0.0;
    for (std::size_t i = 0; i < polygon.size(); ++i) {
        const Vec2& a = polygon[i];
        const Vec2& b = polygon[(i + 1) % polygon.size()];
        twice += a.x * b.y - b.x * a.y;
    }
    return 0.5 * std::abs(twice);
}

} // namespace

QByteArray patternFold(const model::CuttingPattern& pattern, const PatternWriteOptions& options) {
    Graph graph;
    double outlineArea = 0.0;
    std::vector<double> holeAreas; // closed cut lines inside a piece
    std::vector<std::vector<int>> outlineFaces;
    for (const SheetGroup& group : sheetGroups(pattern)) {
        for (int index : group.pieces) {
            const model::PatternPiece& piece = pattern.pieces[std::size_t(index)];
            std::vector<Vec2> outline;
            std::vector<int> face;
            for (const Vec2& p : piece.outline) {
                outline.push_back(p + group.offset);
                const int v = graph.vertex(p + group.offset);
                if (face.empty() || (face.back() != v && face.front() != v)) {
                    face.push_back(v);
                }
            }
            // The cut region: the largest closed cut line less the others (holes).
            std::vector<double> cutAreas;
            for (const model::PatternPath& path : piece.paths) {
                if (path.layer == PatternLayer::Cut && path.closed) {
                    cutAreas.push_back(polygonArea(path.points));
                }
            }
            std::sort(cutAreas.begin(), cutAreas.end(), std::greater<>());
            double pieceArea = cutAreas.empty() ? polygonArea(outline) : cutAreas.front();
            for (std::size_t i = 1; i < cutAreas.size(); ++i) {
                pieceArea -= cutAreas[i];
                holeAreas.push_back(cutAreas[i]);
            }
            outlineArea += pieceArea;
            if (face.size() >= 3) {
                outlineFaces.push_back(face);
            }
            for (const model::PatternPath& path : piece.paths) {
                if (path.layer == PatternLayer::Labels || path.points.size() < 2 ||
                    (options.layers & layerBit(path.layer)) == 0) {
                    continue;
                }
                const char type = assignmentOf(path);
                // FOLD angles are positive for valleys; the pattern's are positive for mountains.
                const double foldAngle = path.foldAngleDegrees ? -*path.foldAngleDegrees : 0.0;
                int previous = graph.vertex(path.points.front() + group.offset);
                const int first = previous;
                for (std::size_t i = 1; i < path.points.size(); ++i) {
                    const int v = graph.vertex(path.points[i] + group.offset);
                    graph.edge(previous, v, type, foldAngle);
                    previous = v;
                }
                if (path.closed) {
                    graph.edge(previous, first, type, foldAngle);
                }
            }
        }
    }
    // Lines meet within the pattern's tolerance (each is sampled on its own).
    const double snap = std::max(kMergeDistance, options.tolerance);
    graph.splitAtDanglingEnds(snap);
    double tracedArea = 0.0;
    std::vector<std::vector<int>> faces = graph.faces(tracedArea);
    // A hole of a piece is traced like a face: bounded by cut edges only, as large as a hole.
    std::map<std::pair<int, int>, char> assignmentOfEdge;
    for (std::size_t e = 0; e < graph.edges.size(); ++e) {
        const auto [a, b] = graph.edges[e];
        assignmentOfEdge[{std::min(a, b), std::max(a, b)}] = graph.assignment[e];
    }
    faces.erase(
        std::remove_if(faces.begin(), faces.end(),
                       [&](const std::vector<int>& face) {
                           std::vector<Vec2> polygon;
                           for (std::size_t i = 0; i < face.size(); ++i) {
                               const int a = face[i];
                               const int b = face[(i + 1) % face.size()];
                               if (assignmentOfEdge[{std::min(a, b), std::max(a, b)}] != 'B') {
                                   return false;
                               }
                               polygon.push_back(graph.vertices[std::size_t(a)]);
                           }
                           const double area = polygonArea(polygon);
                           for (double hole : holeAreas) {
                               if (std::abs(area - hole) <= 1e-6 * std::max(1.0, hole)) {
                                   tracedArea -= area;
                                   return true;
                               }
                           }
                           return false;
                       }),
        faces.end());
    double lineLength = 0.0;
    for (const auto& [a, b] : graph.edges) {
        lineLength += (graph.vertices[std::size_t(a)] - graph.vertices[std::size_t(b)]).norm();
    }
    // Lines that cross without a shared point, or regions with holes (rings between closed
    // creases without rulings), leave faces that do not tile the pieces: then each piece's
    // outline is its one face (still a valid FOLD file).
    if (faces.empty() || std::abs(tracedArea - outlineArea) >
                             snap * lineLength + 1e-6 * std::max(1.0, outlineArea)) {
        faces = outlineFaces;
    }

    QJsonArray coords;
    for (const Vec2& p : graph.vertices) {
        coords.append(QJsonArray{p.x, p.y});
    }
    QJsonArray edgesVertices;
    QJsonArray edgesAssignment;
    QJsonArray edgesAngle;
    for (std::size_t e = 0; e < graph.edges.size(); ++e) {
        edgesVertices.append(QJsonArray{graph.edges[e].first, graph.edges[e].second});
        edgesAssignment.append(QString(QLatin1Char(graph.assignment[e])));
        edgesAngle.append(graph.angle[e]);
    }
    QJsonArray facesVertices;
    for (const std::vector<int>& face : faces) {
        QJsonArray list;
        for (int v : face) {
            list.append(v);
        }
        facesVertices.append(list);
    }
    QJsonObject root;
    root[QStringLiteral("file_spec")] = 1.1;
    root[QStringLiteral("file_creator")] = QStringLiteral("DevSurf");
    root[QStringLiteral("file_classes")] = QJsonArray{QStringLiteral("singleModel")};
    root[QStringLiteral("frame_title")] = QStringLiteral("DevSurf cutting pattern");
    root[QStringLiteral("frame_classes")] = QJsonArray{QStringLiteral("creasePattern")};
    root[QStringLiteral("frame_attributes")] = QJsonArray{QStringLiteral("2D")};
    root[QStringLiteral("frame_unit")] = QStringLiteral("mm");
    root[QStringLiteral("vertices_coords")] = coords;
    root[QStringLiteral("edges_vertices")] = edgesVertices;
    root[QStringLiteral("edges_assignment")] = edgesAssignment;
    root[QStringLiteral("edges_foldAngle")] = edgesAngle;
    root[QStringLiteral("faces_vertices")] = facesVertices;
    return QJsonDocument(root).toJson(QJsonDocument::Indented);
}

} // namespace devsurf::io
