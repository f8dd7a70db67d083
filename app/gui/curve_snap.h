#pragma once

#include "model/reference_curve.h"

#include <QPoint>

#include <optional>
#include <vector>

namespace devsurf::views {
class SceneView;
} // namespace devsurf::views

namespace devsurf::app {

// The point of a reference curve drawn nearest a widget position, for the Drag tool's Snap to
// Reference Curves.
struct CurveSnap {
    model::Vec3 point;   // on the curve's polyline (scene coordinates = mm)
    int curve = -1;      // its index in the project
    double pixels = 0.0; // how far from the position it is drawn
};

// The nearest point within `tolerance` logical pixels, measured on screen: each segment is
// projected, the nearest point found on the projection, and the 3D point taken at the same
// fraction of the segment. nullopt when no curve is drawn that near.
std::optional<CurveSnap> snapToCurves(const views::SceneView& view,
                                      const std::vector<model::ReferenceCurve>& curves,
                                      const QPoint& widgetPos, double tolerance = 10.0);

} // namespace devsurf::app
