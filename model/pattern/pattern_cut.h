#pragma once

// Where a surface is cut open so that every connected part develops into one flat piece.

#include "model/composite_surface.h"
#include "model/sampled_mesh.h"

#include <map>
#include <set>
#include <utility>
#include <vector>

namespace devsurf::model::pattern {

// The coarse edges to cut along so that every connected part of the surface becomes a
// topological disk: the edges not crossed by a spanning tree of the patches (built across
// S-edges first, so the cut runs along rulings where it can), pruned of every edge that ends at
// an interior vertex. Empty for a surface that is a disk already; one chain of rulings from
// boundary to boundary for a closed cylinder or an annulus. With alongCreases, every crease (an
// S-edge between two patches) is cut too and the tree runs across rulings only, so that every
// row of strips becomes its own piece (a closed surface such as a torus, whose rows develop onto
// cones of different angles that overlap when joined).
std::set<EdgeId> chooseCutEdges(const CompositeSurface& surface, bool alongCreases = false);

// The sampled segments {min, max} of mesh vertices that lie on the given coarse edges.
std::set<std::pair<int, int>> cutSegments(const CompositeSurface& surface, const SampledMesh& mesh,
                                          const std::set<EdgeId>& edges);

// The mesh with every vertex on a cut segment duplicated once per side: faces are kept in the
// same order, each corner renumbered; the fans of faces around a vertex that are joined across
// uncut edges share one copy.
struct CutMesh {
    SampledMesh mesh;          // vertices, faces and faceOrigin only
    std::vector<int> original; // for every vertex of the cut mesh, the vertex it copies
};
CutMesh splitAlong(const SampledMesh& mesh, const std::set<std::pair<int, int>>& segments);

using EdgeKey = std::pair<int, int>; // {min, max} vertex of the uncut mesh

// For every edge of the uncut mesh, its copies in the cut mesh (oriented like the key): one
// inside a piece, two along a cut.
std::map<EdgeKey, std::vector<std::pair<int, int>>> edgeCopies(const SampledMesh& mesh,
                                                               const CutMesh& cut);

// The copies of a polyline of the uncut mesh in the cut mesh, one per side it lies on.
std::vector<std::vector<int>>
polylineCopies(const std::vector<int>& line,
               const std::map<EdgeKey, std::vector<std::pair<int, int>>>& copies);

} // namespace devsurf::model::pattern
