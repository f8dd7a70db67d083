#pragma once

#include "composite_surface.h"

#include <string>
#include <vector>

namespace devsurf::model {

// Everything a project file holds: the composite developables of one design.
struct Project {
    std::string units = "mm"; // the length unit of all coordinates
    std::vector<CompositeSurface> surfaces;

    bool operator==(const Project& other) const {
        return units == other.units && surfaces == other.surfaces;
    }
};

} // namespace devsurf::model
