#pragma once

#include "bspline_curve.h"
#include "composite_surface.h"

#include <vector>

namespace devsurf::model {

// One side of a strip: an S-edge traversed as the strip's curve a(u) or b(u).
struct StripSide {
    EdgeId edge = kInvalidId;
    bool reversed = false; // the strip's curve runs against the edge's stored orientation
};

// The ruled surface s(u,v) = (1−v) a(u) + v b(u) of one SRSR/SRS face, or the cone
// s(u,v) = (1−v) a(u) + v apex of an SRR face (§2, §3.1). a and b share the parameter u:
// s(u,0) runs along a, s(u,1) along b, the rulings are u = const.
struct Strip {
    FaceId face = kInvalidId;
    FaceType type = FaceType::Invalid;
    StripSide aSide;
    StripSide bSide; // edge == kInvalidId for cones
    BSplineCurve a;
    BSplineCurve b; // empty for cones
    VertexId apexVertex = kInvalidId;
    Vec3 apex;

    bool isCone() const { return type == FaceType::ConeSRR; }
    Vec3 aPoint(double u) const { return a.evaluate(u); }
    Vec3 bPoint(double u) const { return isCone() ? apex : b.evaluate(u); }
    Vec3 point(double u, double v) const { return aPoint(u) * (1.0 - v) + bPoint(u) * v; }
};

// The strip of a strip or cone face. Throws ModelError for planar or invalid faces. The side
// a is chosen deterministically: in an SRSR face the S-edge with the smaller id, traversed along
// the face loop; in an SRS face the S-edge that follows the ruling along the loop.
Strip stripOfFace(const CompositeSurface& surface, FaceId face);

// All strips and cones of a surface, in face id order.
std::vector<Strip> stripsOf(const CompositeSurface& surface);

} // namespace devsurf::model
