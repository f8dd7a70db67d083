#pragma once

#include "bspline_curve.h"
#include "composite_surface.h"

#include <map>
#include <optional>
#include <set>
#include <vector>

namespace devsurf::model {

// Joining strips into one composite surface (§4.2, "Composite"): separately made strips are put
// into one surface and two of their boundary edges, once they lie close together, are welded
// into one shared edge, so that the result is watertight there.

// Two edges can be welded when no control point of one lies farther from its counterpart on
// the other than this fraction of their length (the mean length of their control polygons).
// Since both curves use the same basis, the curves then lie that close at every parameter.
inline constexpr double kWeldTolerance = 0.05;

// `first` and `second` as one surface of two separate parts. The entities of `first` keep
// their ids, those of `second` get new ones (the maps say which); pins, curves, crease
// conditions and smooth rulings are carried over. Named "first + second". The result keeps no
// development (its sampling changed); it keeps `first`'s sheet settings.
struct SurfacesSideBySide {
    CompositeSurface surface;
    std::map<VertexId, VertexId> vertexOfSecond;
    std::map<EdgeId, EdgeId> edgeOfSecond;
    std::map<FaceId, FaceId> faceOfSecond;
};
SurfacesSideBySide placeSideBySide(const CompositeSurface& first, const CompositeSurface& second);

// The parts of `surface`: its faces grouped by connection through shared edges, each part in
// id order, parts ordered by their smallest face id.
std::vector<std::set<FaceId>> surfaceParts(const CompositeSurface& surface);

// The curve along an edge: an S-edge's spline, an R-edge's straight segment (a degree-1 spline
// of one interval) between its vertices; both run from the edge's `from` to its `to` vertex.
BSplineCurve edgeCurve(const CompositeSurface& surface, EdgeId edge);

// Two boundary curves that lie nearest each other, one of each of two sets of faces.
struct NearestCurves {
    EdgeId first = kInvalidId;  // bordering a face of `one`
    EdgeId second = kInvalidId; // bordering a face of `other`
    // The largest distance between the curves' ends and between their midpoints, matched in
    // the closer orientation (mm), and the mean of their chord lengths.
    double separation = 0.0;
    double length = 0.0;
};
// The pair of boundary edges of one kind (two S-edges or two R-edges), one bordering a face of
// `one`, the other a face of `other`, of smallest separation; none if no such pair exists.
std::optional<NearestCurves> nearestBoundaryCurves(const CompositeSurface& surface,
                                                   const std::set<FaceId>& one,
                                                   const std::set<FaceId>& other);

// The result of welding two boundary edges.
struct Weld {
    CompositeSurface surface;
    EdgeId shared = kInvalidId;      // the welded edge, shared by the two faces
    double gap = 0.0;                // the largest distance of matched control points before (mm)
    bool reversed = false;           // the edges were matched against their stored orientations
    bool flipped = false;            // the part of `second` was turned over to match orientations
    std::map<EdgeId, EdgeId> edgeOf; // every old edge's new id (`second`'s: `shared`)
};

// Welds the boundary edges `first` and `second` of `surface` (two S-edges or two R-edges of
// different faces) into one edge shared by both faces: their end vertices are merged, each at
// the mean of the two, and the control points of two curves are averaged, matched in the
// orientation (along or against) in which they lie closer. Curves in different spline spaces
// of one degree and smoothness are first refined to the finer one when its intervals are a
// multiple of the other's. If both faces would run along the edge in the same direction, the
// part (faces connected through edges) of `second` is turned over, which needs it to be
// another part than `first`'s. Every vertex, edge and face gets a new id (in the order of the
// old ones); the other vertices, curves, conditions, pins and smooth rulings are carried over.
// Throws ModelError when the edges are not two boundary edges of one kind and of different
// faces (WeldNeedsBoundaryEdges), their spaces cannot be matched (CurveSpaceDiffers), they lie
// farther apart than `tolerance` times their length (EdgesTooFarApart) or the result would not
// be a valid surface.
Weld weldEdges(const CompositeSurface& surface, EdgeId first, EdgeId second,
               double tolerance = kWeldTolerance);

// `surfaces` with those at `indices` (ascending, at least one, in range) replaced by `joined`,
// which takes the first one's place and id: the design after a join (Tools ▸ Join Surfaces,
// `devsurf-cli join`).
std::vector<CompositeSurface> replaceByJoined(const std::vector<CompositeSurface>& surfaces,
                                              const std::vector<int>& indices,
                                              CompositeSurface joined);

// Merges the two strips on either side of the ruling `ruling` into one strip (§4.2, "merge two
// strips by joining their control sequences"): each curve of the result is the two curves that
// meet at an end of the ruling joined there, in S(n₁ + n₂, m, k) for curves in S(n₁, m, k) and
// S(n₂, m, k), its first n₁ intervals along the first curve. Its end control points are the far
// ends of the two curves, its inner ones fitted to both by least squares: exact when the two
// are pieces of one such spline (as splitAtRuling cuts them), otherwise the nearest spline of
// the joined space, which a Solve makes developable again. The ruling and its two vertices go;
// every vertex, edge and face gets a new id. Throws ModelError (MergeNeedsStrips) unless the
// ruling lies between two SRSR strips whose four curves are boundaries of one degree and
// smoothness and whose ruling's vertices belong to no other face.
CompositeSurface mergeStrips(const CompositeSurface& surface, EdgeId ruling);

} // namespace devsurf::model
