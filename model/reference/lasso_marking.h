#pragma once

#include "model/reference_shape.h"
#include "model/vec3.h"

#include <array>
#include <cstddef>
#include <vector>

namespace devsurf::model::reference {

// A camera as the lasso needs it: scene point → screen position (the coordinates the lasso
// is drawn in), and where the camera looks from, to tell the points facing it.
struct LassoCamera {
    // Row-major 4 × 4 matrix from homogeneous scene coordinates (x, y, z, 1) to (sx·w, sy·w,
    // ·, w): the screen position is (sx, sy) after the division by w. w ≤ 0: behind the eye.
    std::array<double, 16> toScreen{};
    bool parallel = false; // a parallel projection looks along `direction` everywhere
    Vec3 eye;              // perspective: the camera's position
    Vec3 direction;        // parallel: the unit direction of projection
    // The screen position of a scene point; false if it lies behind the eye.
    bool project(const Vec3& point, Vec2& screen) const;
    // The direction from a point towards the camera (not normalised).
    Vec3 towardsCamera(const Vec3& point) const;
};

// Whether a screen position lies inside a closed polygon (even–odd rule; the last vertex
// joins the first). Fewer than 3 vertices hold nothing.
bool insidePolygon(const std::vector<Vec2>& polygon, const Vec2& point);

// One normal per point of the shape: its own normals if it has one per point, else for a
// mesh the area-weighted mean of its triangles' normals (zero at a point no triangle uses),
// else (a point cloud without normals) none: an empty vector.
std::vector<Vec3> pointNormals(const ReferenceShape& shape);

// The points of `shape` (indices, ascending) that a lasso drawn on the screen marks: those
// whose screen position lies inside `lasso` and that face the camera. A point faces it when
// its normal (pointNormals) points towards the camera; a mesh point no triangle uses is never
// marked. That keeps the far side of a closed shape out of the mark, but not a part hidden
// behind another front-facing part (an ear before the body): there is no depth test. A point
// cloud without normals cannot tell its sides apart: every point inside the lasso is marked.
std::vector<std::size_t> pointsInLasso(const ReferenceShape& shape, const std::vector<Vec2>& lasso,
                                       const LassoCamera& camera);

} // namespace devsurf::model::reference
