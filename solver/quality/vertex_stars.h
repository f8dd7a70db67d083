#pragma once

// The stars of the interior coarse vertices where creases meet (docs/math.md §7, vertex
// developability): the edges leaving such a vertex in cyclic order, each with the point that
// spans its tangent there. Shared by the solver's vertex-developability rows and the angle-defect
// measure, so both look at the same vertices and the same triangles.

#include "model/composite_surface.h"

#include <vector>

namespace devsurf::solver {

// One edge leaving the star's vertex: the point that gives its direction there. For an S-edge
// that is its second control point counted from the vertex (index `controlIndex` of the stored
// control sequence); for an R-edge, which is straight, the other end vertex `otherEnd`.
struct StarSpoke {
    model::EdgeId edge = model::kInvalidId;
    bool spline = false;
    std::size_t controlIndex = 0;                 // S-edge only
    model::VertexId otherEnd = model::kInvalidId; // R-edge only
};

struct VertexStar {
    model::VertexId vertex = model::kInvalidId;
    // In cyclic order around the vertex (consecutive spokes bound one face); the last and the
    // first bound a face too.
    std::vector<StarSpoke> spokes;
};

// Every interior coarse vertex (its faces close up around it) at which at least one crease (an
// S-edge shared by two faces) ends, in vertex id order. Vertices whose faces do not form a
// single closed fan are left out.
std::vector<VertexStar> creaseVertexStars(const model::CompositeSurface& surface);

// The point of a spoke in the surface's geometry.
model::Vec3 spokePoint(const model::CompositeSurface& surface, const StarSpoke& spoke);

struct VertexAngleDefect {
    model::VertexId vertex = model::kInvalidId;
    double defect = 0.0; // |2π − Σ angles| in radians
};

// For every vertex of creaseVertexStars: |2π − Σ angles between consecutive spokes|, the spokes
// taken from the control points (geometry only). Throws model::ModelError for an invalid
// surface.
std::vector<VertexAngleDefect> vertexAngleDefects(const model::CompositeSurface& surface);

} // namespace devsurf::solver
