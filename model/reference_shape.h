#pragma once

#include "vec3.h"

#include <array>
#include <string>
#include <vector>

namespace devsurf::model {

// A mesh or point cloud imported from another program (OBJ, PLY, STL, OFF, XYZ, PTS) that the
// design is to approximate: shown in the 3D view, never solved for. In the project's units
// (mm). A point cloud has no triangles; a mesh's triangles index into `points`.
struct ReferenceShape {
    std::string name;   // what the user sees (the file's base name unless given)
    std::string source; // the file it was read from; may be empty
    std::vector<Vec3> points;
    std::vector<Vec3> normals; // empty, or one per point
    std::vector<std::array<int, 3>> triangles;

    bool isPointCloud() const { return triangles.empty(); }

    bool operator==(const ReferenceShape& other) const {
        return name == other.name && source == other.source && points == other.points &&
               normals == other.normals && triangles == other.triangles;
    }
    bool operator!=(const ReferenceShape& other) const { return !(*this == other); }
};

} // namespace devsurf::model
