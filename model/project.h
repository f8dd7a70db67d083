#pragma once

#include "composite_surface.h"
#include "reference_curve.h"
#include "reference_shape.h"

#include <algorithm>
#include <set>
#include <string>
#include <vector>

namespace devsurf::model {

// Everything a project file holds: the composite developables of one design and the curves
// and shapes it refers to.
struct Project {
    std::string units = "mm"; // the length unit of all coordinates
    std::vector<CompositeSurface> surfaces;
    std::vector<ReferenceCurve> referenceCurves; // imported, shown, never solved for
    std::vector<ReferenceShape> referenceShapes; // meshes and point clouds to approximate

    // Appends a surface with a new id (one more than the largest in use) and returns the id.
    SurfaceId addSurface(CompositeSurface surface) {
        SurfaceId next = 1;
        for (const CompositeSurface& s : surfaces) {
            next = std::max<SurfaceId>(next, s.id() + 1);
        }
        surface.setId(next);
        surfaces.push_back(std::move(surface));
        return next;
    }
    // Gives every surface without an id (0) or with the id of an earlier surface a new one, in
    // order; ids already unique are kept. Files of format 1 to 3 hold no ids.
    void assignSurfaceIds() {
        std::set<SurfaceId> used;
        SurfaceId next = 1;
        for (const CompositeSurface& s : surfaces) {
            next = std::max<SurfaceId>(next, s.id() + 1);
        }
        for (CompositeSurface& s : surfaces) {
            if (s.id() == 0 || !used.insert(s.id()).second) {
                s.setId(next);
                used.insert(next++);
            }
        }
    }
    // The index of the surface with this id, or -1.
    int indexOf(SurfaceId id) const {
        for (std::size_t i = 0; i < surfaces.size(); ++i) {
            if (surfaces[i].id() == id) {
                return static_cast<int>(i);
            }
        }
        return -1;
    }

    bool operator==(const Project& other) const {
        return units == other.units && surfaces == other.surfaces &&
               referenceCurves == other.referenceCurves && referenceShapes == other.referenceShapes;
    }
};

} // namespace devsurf::model
