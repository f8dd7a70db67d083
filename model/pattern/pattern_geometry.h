#pragma once

// Small plane-geometry helpers shared by the pattern's steps (pieces, layout, overlaps, seams).

#include "model/pattern/cutting_pattern.h"

#include <vector>

namespace devsurf::model::pattern {

// Signed area of a closed polygon (positive when counter-clockwise).
double signedArea(const std::vector<Vec2>& polygon);

// Whether p lies inside the closed polygon (even-odd rule).
bool pointInPolygon(const Vec2& p, const std::vector<Vec2>& polygon);

// Distance from p to the segment [a,b].
double distanceToSegment(const Vec2& p, const Vec2& a, const Vec2& b);

// The closed boundary loops of a polygon mesh's faces (vertex indices), each running with the
// faces' orientation: the edges used by one face only.
std::vector<std::vector<int>> boundaryLoops(const std::vector<std::vector<int>>& faces);

// Convex hull, counter-clockwise, without collinear points.
std::vector<Vec2> convexHull(std::vector<Vec2> points);

// The rigid motion p ↦ R(angle)·p + shift.
struct Placement {
    double angle = 0.0; // radians, counter-clockwise
    Vec2 shift;
    Vec2 apply(const Vec2& p) const;
};

// Moves everything a piece holds (outline, holes, paths, labels, mesh, edges, vertices,
// rulings) by the motion; labels turn with it.
void transformPiece(PatternPiece& piece, const Placement& placement);

// Bounding box {min, max} of a piece's outline and holes.
std::pair<Vec2, Vec2> pieceBounds(const PatternPiece& piece);

} // namespace devsurf::model::pattern
