#pragma once

#include "model/strip.h"
#include "model/vec3.h"

namespace devsurf::model::reference {

struct ClosestPoint {
    Vec3 position;
    double u = 0.0; // the strip's parameters of `position` (0 on a triangle)
    double v = 0.0;
    double distance = 0.0;
};

// The closest point to q of a strip or cone s(u,v) = (1−v) a(u) + v b(u), (u,v) ∈ [0,1]²,
// (the domain of every strip stripOfFace builds), found by projected Newton steps on (u,v)
// from (u0, v0) with a backtracking line search: a local minimum of |s(u,v) − q|, the global
// one when (u0, v0) is close enough to it (the nearest of dense samples). Falls back to
// Gauss–Newton where the Hessian is not positive definite, and keeps a parameter on the border
// of the square while the gradient pushes out.
ClosestPoint closestPointOnStrip(const Strip& strip, const Vec3& q, double u0, double v0);

// The closest point to q of the triangle (a, b, c), exactly (by the region of q).
ClosestPoint closestPointOnTriangle(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& q);

} // namespace devsurf::model::reference
