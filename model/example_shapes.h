#pragma once

// The shapes of the built-in examples (model/examples.h lists them and makes a project of one)
// and the spline helpers they are drawn with. Internal to the model library.

#include "composite_surface.h"

#include <functional>
#include <optional>
#include <vector>

namespace devsurf::model::example_shapes {

// Control points of a curve in the given space whose Greville abscissae lie on f; this
// reproduces lines exactly and approximates other curves closely. The end points are the
// given vertex positions bit for bit, so the curve starts and ends at its vertices.
std::vector<Vec3> controlPointsAlong(const SplineSpace& space, const Vec3& start, const Vec3& end,
                                     const std::function<Vec3(double)>& f);
// As controlPointsAlong, then corrected a few times by what the curve misses at the Greville
// abscissae, so that a curve such as a circular arc lies on f to a fraction of a micrometre
// rather than inside it by the control polygon's sag.
std::vector<Vec3> controlPointsThrough(const SplineSpace& space, const Vec3& start, const Vec3& end,
                                       const std::function<Vec3(double)>& f);
Vec3 lerp(const Vec3& a, const Vec3& b, double t);
// `points` with the second and the last-but-one control point moved onto the given unit
// tangents at the ends (each at its distance from its end), where given: consecutive curves
// through a vertex then meet tangent-continuously, one smooth curve as the solver keeps it.
std::vector<Vec3> alongEndTangents(std::vector<Vec3> points, const std::optional<Vec3>& start,
                                   const std::optional<Vec3>& end);

// Plain shapes (model/example_shapes.cpp): size is each example's resolution.
CompositeSurface makeSheet(int size);
CompositeSurface makeAnnulus(int rings, bool throughCircles);
CompositeSurface makeCylinder(int sectors);
CompositeSurface makeMixed(int intervals);
CompositeSurface makeTorus(int size);

// The paper's folds, with curved-fold conditions and pins (model/fold_examples.cpp).
CompositeSurface makeFig8(int size);
CompositeSurface makeFig6(int intervals);
CompositeSurface makeFig13(int size);
CompositeSurface makeFig12(int rings);
CompositeSurface makeColumn(int sectors);

} // namespace devsurf::model::example_shapes
