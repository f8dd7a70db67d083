#pragma once

#include "composite_surface.h"

#include <set>
#include <utility>
#include <vector>

namespace devsurf::model {

// The pure geometry of the document's edits. Each function returns the edited copy of a valid
// surface and leaves the input untouched; an edit that cannot be done throws ModelError with
// a sentence for the user. Ids of untouched entities are kept; new entities get fresh ids.

// A rotation followed by a translation: p ↦ R p + t.
struct RigidMotion {
    double rotation[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    Vec3 translation;

    static RigidMotion translationBy(const Vec3& offset);
    // Right-handed rotation by angle (radians) about the axis through point along direction
    // (Rodrigues' formula). Throws ModelError for a zero or non-finite axis.
    static RigidMotion rotationAbout(const Vec3& point, const Vec3& direction, double angle);
    Vec3 apply(const Vec3& p) const;
};

// Relabels edges R↔S together, validating once at the end (so a planar RRRR face can become an
// SRSR strip in one step). An edge that becomes S gets a straight control sequence (Greville
// points on the segment, so the parametrisation is linear) in the spline space of the S-edges
// it will share a face with (the first found in the faces it borders, including edges relabelled
// earlier in the list), or cubic C2 with 2 intervals if there are none. An edge that becomes R
// loses its control points and crease condition. Edges already carrying the label are left as
// they are. Throws with the first problem validate() reports for the result.
CompositeSurface relabelEdges(const CompositeSurface& surface,
                              const std::vector<std::pair<EdgeId, EdgeLabel>>& labels);

// The spline space an R-edge would get when relabelled S (see relabelEdges).
SplineSpace spaceForNewSplineEdge(const CompositeSurface& surface, EdgeId edge);

// Cuts the SRSR strip `face` along the new crease c = (1−t) a + t b, where a is the strip's
// curve a(u) of stripOfFace() and b its curve b(u) (so t runs from a to b), 0 < t < 1. c has
// the control points (1−t) a_i + t b_i: it is the ruled surface's curve v = t, so the geometry
// is unchanged. The cut runs across the whole row of SRSR strips connected through R-edges
// (each neighbour is cut at the same t, measured from the side the row came from). Planar
// neighbours across the row's rulings get the new vertex in their loop; an SRS strip or a cone
// across one of the rulings stops the cut and the edit is refused, as is a row that closes on
// itself with its sides swapped. Each cut face keeps its id for the part along its curve a.
CompositeSurface subdivideStrip(const CompositeSurface& surface, FaceId face, double t);

// The faces subdivideStrip(surface, face, t) would cut; throws as it does.
std::vector<FaceId> stripRow(const CompositeSurface& surface, FaceId face);

// Inserts a new ruling into the strip or cone `face` at the breakpoint u = breakpoint / n of its
// curve a(u) (stripOfFace(), n intervals), 1 <= breakpoint <= n−1. Every S-edge of the curve's
// spline class is split at the same point (a strip that runs along a shared curve the other way
// round sees breakpoint n−i), so every strip and cone of the class gets the new ruling: the
// pieces are exactly uniform with i and n−i intervals and the geometry is unchanged. Each split
// S-edge keeps its id (and orientation) for the piece at its start; each cut face keeps its id
// for the part holding its first loop vertex.
CompositeSurface splitAtRuling(const CompositeSurface& surface, FaceId face, int breakpoint);

// Refines every S-edge of the spline class of `edge` from n to factor·n intervals by knot
// insertion (the geometry is unchanged up to rounding). factor >= 2.
CompositeSurface refineSplineClass(const CompositeSurface& surface, EdgeId edge, int factor = 2);

// The S-edges of the spline class that contains `edge` (an S-edge), in id order.
std::vector<EdgeId> splineClassOf(const CompositeSurface& surface, EdgeId edge);

// Moves the given vertices by `motion`. An S-edge with both ends moved moves rigidly as a whole;
// on one with a single moved end, the control point next to it (index 1 or N−2) moves rigidly
// with it and the end control point follows the vertex. Throws for an empty set or an unknown
// vertex.
CompositeSurface moveVertices(const CompositeSurface& surface, const std::set<VertexId>& vertices,
                              const RigidMotion& motion);

} // namespace devsurf::model
