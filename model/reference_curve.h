#pragma once

#include "vec3.h"

#include <string>
#include <vector>

namespace devsurf::model {

// A curve imported from another program (DXF, STEP, IGES) that the design refers to: shown in
// the 3D view, never solved for. Stored as the polyline it was sampled to, in the project's
// units (mm).
struct ReferenceCurve {
    std::string name;   // what the user sees ("SPLINE 3", an edge's name)
    std::string source; // the source's layer or entity name; may be empty
    std::vector<Vec3> points;

    bool operator==(const ReferenceCurve& other) const {
        return name == other.name && source == other.source && points == other.points;
    }
    bool operator!=(const ReferenceCurve& other) const { return !(*this == other); }
};

} // namespace devsurf::model
