#pragma once

#include "composite_surface.h"

#include <cstddef>
#include <utility>
#include <vector>

namespace devsurf::model {

// The sampled mesh (V,E,F) of §5: every strip's boundary curves sampled at the same parameters
// u_i, giving quads a(u_i), a(u_{i+1}), b(u_{i+1}), b(u_i) (triangles where a side degenerates,
// fans for cones), plus the planar faces. Samples along an S-edge are shared by both faces of
// the edge, so the mesh is connected wherever the composite surface is.
struct SampledMesh {
    struct Polyline {
        EdgeId edge = kInvalidId;
        std::vector<int> vertices; // in the edge's stored orientation
    };

    std::vector<Vec3> vertices;               // coarse vertices first (in id order), then samples
    std::vector<std::vector<int>> faces;      // quads or triangles, oriented like the coarse faces
    std::vector<FaceId> faceOrigin;           // the coarse face each sampled face belongs to
    std::vector<Polyline> splineEdges;        // every S-edge, sampled
    std::vector<std::pair<int, int>> rulings; // the sampled rulings u = u_i of every strip
    std::vector<VertexId> coarseVertexIds;    // coarse vertex of the first coarseVertexIds.size()
};

// Samples every S-edge at samplesPerInterval points per spline interval. The surface must be
// valid (validate() empty); throws ModelError otherwise.
SampledMesh sampleSurface(const CompositeSurface& surface, int samplesPerInterval);

// The number of vertices sampleSurface gives at that sampling (structure only, no validation).
std::size_t sampledVertexCount(const CompositeSurface& surface, int samplesPerInterval);

// The sides of a list of polygons grouped by undirected edge, for walking across edges (the
// unfolding, cutting a mesh open). Side s is numbered polygon by polygon; edges[s] is its edge
// with the smaller vertex first. `order` lists the sides sorted by edge (in side order within an
// edge), and run[s] is the [begin, end) range of side s's edge in `order`: the sides along it.
struct SidesByEdge {
    std::vector<std::size_t> order;
    std::vector<std::pair<std::size_t, std::size_t>> run;
};
SidesByEdge groupSidesByEdge(const std::vector<std::pair<int, int>>& edges);

} // namespace devsurf::model
