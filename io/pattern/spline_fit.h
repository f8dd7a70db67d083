#pragma once

// Cubic splines through a sampled curve, within a tolerance, for writers whose readers prefer
// smooth curves (DXF SPLINE): far fewer entities than the polyline for the same accuracy.

#include "model/vec3.h"

#include <vector>

namespace devsurf::io {

// A clamped cubic B-spline made of Bézier segments: control points 3m + 1 for m segments,
// knots 0,0,0,0, 1,1,1, …, m,m,m,m (each segment is one Bézier piece, so the curve passes
// through every 3rd control point).
struct CubicSpline {
    std::vector<model::Vec2> controlPoints;
    std::vector<double> knots;
    int segments() const { return controlPoints.empty() ? 0 : int(controlPoints.size() - 1) / 3; }
};

// Fits a spline to a polyline (closed: the last point joins the first) so that every point of
// the polyline is within `tolerance` of the spline and every point of the spline is within
// `tolerance` of the polyline. Corners (turns above 30°) stay corners. Fewer than two points
// give an empty spline.
CubicSpline fitCubicSpline(const std::vector<model::Vec2>& points, bool closed, double tolerance);

// The point of segment `segment` at local parameter t in [0, 1] (de Casteljau).
model::Vec2 splinePoint(const CubicSpline& spline, int segment, double t);

} // namespace devsurf::io
