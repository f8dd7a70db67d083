#pragma once

// Polylines of the exact curves the DXF reader meets (NURBS, arcs), within a chord tolerance.

#include "model/vec3.h"

#include <optional>
#include <vector>

namespace devsurf::io {

struct Nurbs {
    int degree = 0;
    std::vector<double> knots;
    std::vector<model::Vec3> controlPoints;
    std::vector<double> weights; // one per control point, or empty for all 1
};

// Whether the data describe a curve: degree 1 to 15, knots = points + degree + 1, knots
// non-decreasing and finite, weights positive and finite, a parameter range of positive length.
bool isValidNurbs(const Nurbs& curve);
// The point at parameter t (de Boor on homogeneous coordinates); curve must be valid.
model::Vec3 nurbsPoint(const Nurbs& curve, double t);
// The curve sampled so that no chord is further than tolerance from the curve at the middle of
// its parameter interval, at most maxPoints points; nullopt if the curve is not valid.
std::optional<std::vector<model::Vec3>> sampleNurbs(const Nurbs& curve, double tolerance,
                                                    std::size_t maxPoints);

// The circular arc about center in the plane spanned by the unit vectors u and v, from angle a0
// to a1 (radians, a1 > a0), with chords within tolerance of the arc.
std::vector<model::Vec3> sampleArc(const model::Vec3& center, double radius, const model::Vec3& u,
                                   const model::Vec3& v, double a0, double a1, double tolerance);

} // namespace devsurf::io
