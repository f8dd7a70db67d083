#pragma once

#include <QFlags>

namespace devsurf::document {

// What an edit changed, so that views rebuild only what they must.
enum class Change : unsigned {
    Geometry = 0x1,         // positions of vertices or control points
    Labels = 0x2,           // R/S labels, spline spaces, crease conditions
    Topology = 0x4,         // vertices, edges or faces added or removed
    Pins = 0x8,             // vertices pinned or released
    ReferenceCurves = 0x10, // reference curves added or removed (no surface changed)
    ReferenceShapes = 0x20, // reference meshes or point clouds added or removed (idem)
    Everything = 0x3f,
};
Q_DECLARE_FLAGS(Changes, Change)
Q_DECLARE_OPERATORS_FOR_FLAGS(Changes)

} // namespace devsurf::document
