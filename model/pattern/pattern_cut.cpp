#include "pattern_cut.h"

#include <algorithm>
#include <map>
#include <numeric>

namespace devsurf::model::pattern {

namespace {

class UnionFind {
public:
    explicit UnionFind(std::size_t size) : m_parent(size) {
        std::iota(m_parent.begin(), m_parent.end(), 0);
    }
    std::size_t find(std::size_t i) {
        while (m_parent[i] != i) {
            m_parent[i] = m_parent[m_parent[i]];
            i = m_parent[i];
        }
        return i;
    }
    bool unite(std::size_t a, std::size_t b) {
        a = find(a);
        b = find(b);
        if (a == b) {
            return false;
        }
        m_parent[std::max(a, b)] = std::min(a, b);
        return true;
    }

private:
    std::vector<std::size_t> m_parent;
};

} // namespace

std::set<EdgeId> chooseCutEdges(const CompositeSurface& surface, bool alongCreases) {
    std::map<FaceId, std::size_t> faceIndex;
    for (const auto& [id, loop] : surface.faces()) {
        faceIndex.emplace(id, faceIndex.size());
    }
    // Interior edges, those between two patches; crossing an S-edge first keeps the patches
    // of a strip row together and leaves the rulings to be cut.
    std::vector<EdgeId> interior;
    std::set<VertexId> boundaryVertices;
    for (const auto& [id, record] : surface.edges()) {
        if (surface.facesOfEdge(id).size() == 2) {
            interior.push_back(id);
        } else {
            boundaryVertices.insert(record.from);
            boundaryVertices.insert(record.to);
        }
    }
    std::stable_sort(interior.begin(), interior.end(), [&surface](EdgeId a, EdgeId b) {
        return surface.edge(a).isSpline() > surface.edge(b).isSpline();
    });
    UnionFind components(faceIndex.size());
    std::set<EdgeId> cut;
    for (EdgeId edge : interior) {
        const std::vector<FaceId> faces = surface.facesOfEdge(edge);
        if ((alongCreases && surface.edge(edge).isSpline()) ||
            !components.unite(faceIndex.at(faces[0]), faceIndex.at(faces[1]))) {
            cut.insert(edge);
        }
    }
    // An uncrossed edge that ends at an interior vertex where no other uncrossed edge ends
    // only slits the piece: the patches around that vertex close up (they are developable),
    // so it is not cut. Repeat until every remaining edge runs between boundary vertices or
    // joins others.
    bool pruned = true;
    while (pruned) {
        pruned = false;
        std::map<VertexId, int> degree;
        for (EdgeId edge : cut) {
            ++degree[surface.edge(edge).from];
            ++degree[surface.edge(edge).to];
        }
        for (auto it = cut.begin(); it != cut.end();) {
            const EdgeRecord& record = surface.edge(*it);
            const bool dangling =
                (degree[record.from] == 1 && boundaryVertices.count(record.from) == 0) ||
                (degree[record.to] == 1 && boundaryVertices.count(record.to) == 0);
            if (dangling) {
                --degree[record.from];
                --degree[record.to];
                it = cut.erase(it);
                pruned = true;
            } else {
                ++it;
            }
        }
    }
    return cut;
}

std::set<std::pair<int, int>> cutSegments(const CompositeSurface& surface, const SampledMesh& mesh,
                                          const std::set<EdgeId>& edges) {
    std::set<std::pair<int, int>> segments;
    if (edges.empty()) {
        return segments;
    }
    std::map<VertexId, int> coarse;
    for (std::size_t i = 0; i < mesh.coarseVertexIds.size(); ++i) {
        coarse[mesh.coarseVertexIds[i]] = static_cast<int>(i);
    }
    auto add = [&segments](int a, int b) { segments.emplace(std::min(a, b), std::max(a, b)); };
    for (const auto& line : mesh.splineEdges) {
        if (edges.count(line.edge) != 0) {
            for (std::size_t i = 0; i + 1 < line.vertices.size(); ++i) {
                add(line.vertices[i], line.vertices[i + 1]);
            }
        }
    }
    for (EdgeId edge : edges) {
        const EdgeRecord& record = surface.edge(edge);
        if (!record.isSpline()) {
            add(coarse.at(record.from), coarse.at(record.to));
        }
    }
    return segments;
}

CutMesh splitAlong(const SampledMesh& mesh, const std::set<std::pair<int, int>>& segments) {
    // Corners (face, position in face) are joined across every uncut edge shared by two faces.
    std::vector<std::size_t> cornerBase(mesh.faces.size() + 1, 0);
    for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
        cornerBase[f + 1] = cornerBase[f] + mesh.faces[f].size();
    }
    UnionFind corners(cornerBase.back());
    // Side k of face f (corner cornerBase[f] + k to the next corner) along its edge; the
    // corners of its smaller and larger vertex.
    std::vector<std::pair<int, int>> sideEdges;
    std::vector<std::pair<std::size_t, std::size_t>> sideCorners;
    sideEdges.reserve(cornerBase.back());
    sideCorners.reserve(cornerBase.back());
    for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
        const auto& face = mesh.faces[f];
        for (std::size_t k = 0; k < face.size(); ++k) {
            const std::size_t next = (k + 1) % face.size();
            const int a = face[k];
            const int b = face[next];
            sideEdges.emplace_back(std::min(a, b), std::max(a, b));
            sideCorners.emplace_back(cornerBase[f] + (a < b ? k : next),
                                     cornerBase[f] + (a < b ? next : k));
        }
    }
    const SidesByEdge byEdge = groupSidesByEdge(sideEdges);
    for (std::size_t i = 0; i < byEdge.order.size();) {
        const std::size_t first = byEdge.order[i];
        const std::size_t end = byEdge.run[first].second;
        if (segments.count(sideEdges[first]) == 0) {
            for (std::size_t j = i + 1; j < end; ++j) {
                const std::size_t other = byEdge.order[j];
                corners.unite(sideCorners[first].first, sideCorners[other].first);
                corners.unite(sideCorners[first].second, sideCorners[other].second);
            }
        }
        i = end;
    }
    CutMesh cut;
    std::vector<int> copyOfClass(cornerBase.back(), -1); // by the class's root corner
    cut.mesh.faceOrigin = mesh.faceOrigin;
    for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
        std::vector<int> face;
        for (std::size_t k = 0; k < mesh.faces[f].size(); ++k) {
            int& copy = copyOfClass[corners.find(cornerBase[f] + k)];
            if (copy < 0) {
                copy = static_cast<int>(cut.mesh.vertices.size());
                const int original = mesh.faces[f][k];
                cut.mesh.vertices.push_back(mesh.vertices[static_cast<std::size_t>(original)]);
                cut.original.push_back(original);
            }
            face.push_back(copy);
        }
        cut.mesh.faces.push_back(std::move(face));
    }
    return cut;
}

std::map<EdgeKey, std::vector<std::pair<int, int>>> edgeCopies(const SampledMesh& mesh,
                                                               const CutMesh& cut) {
    std::map<EdgeKey, std::vector<std::pair<int, int>>> copies;
    for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
        const auto& face = mesh.faces[f];
        const auto& copy = cut.mesh.faces[f];
        for (std::size_t k = 0; k < face.size(); ++k) {
            const std::size_t next = (k + 1) % face.size();
            const bool forward = face[k] < face[next];
            const std::pair<int, int> value =
                forward ? std::make_pair(copy[k], copy[next]) : std::make_pair(copy[next], copy[k]);
            auto& list = copies[{std::min(face[k], face[next]), std::max(face[k], face[next])}];
            if (std::find(list.begin(), list.end(), value) == list.end()) {
                list.push_back(value);
            }
        }
    }
    return copies;
}

std::vector<std::vector<int>>
polylineCopies(const std::vector<int>& line,
               const std::map<EdgeKey, std::vector<std::pair<int, int>>>& copies) {
    struct Open {
        std::vector<int> vertices;
        std::size_t lastSegment = 0;
    };
    std::vector<Open> open;
    for (std::size_t i = 0; i + 1 < line.size(); ++i) {
        const int a = line[i];
        const int b = line[i + 1];
        const auto it = copies.find({std::min(a, b), std::max(a, b)});
        if (a == b || it == copies.end()) {
            continue;
        }
        for (const auto& [p, q] : it->second) {
            const int from = a < b ? p : q;
            const int to = a < b ? q : p;
            auto match = std::find_if(open.begin(), open.end(), [&](const Open& o) {
                return o.lastSegment + 1 == i && o.vertices.back() == from;
            });
            if (match != open.end()) {
                match->vertices.push_back(to);
                match->lastSegment = i;
            } else {
                open.push_back({{from, to}, i});
            }
        }
    }
    std::vector<std::vector<int>> result;
    for (auto& o : open) {
        result.push_back(std::move(o.vertices));
    }
    return result;
}

} // namespace devsurf::model::pattern
