#pragma once

// Every patch of a design as the exact surface a CAD program stores: a ruled patch (strip or
// cone) as a tensor-product B-spline of degree m in u (along its S-edges) and 1 in v (along the
// rulings), a planar patch as its polygon. The STEP/IGES writer hands these to OpenCASCADE; the
// tests measure the written files against them. No OpenCASCADE here.

#include "model/bspline_curve.h"
#include "model/composite_surface.h"
#include "model/project.h"
#include "model/vec3.h"

#include <string>
#include <vector>

namespace devsurf::io {

struct PatchSurface {
    model::SurfaceId surface = 0;
    model::FaceId face = model::kInvalidId;
    model::FaceType type = model::FaceType::Invalid;

    // Ruled patches: s(u, v) = (1 − v) a(u) + v b(u) on [0, 1]², a (the row of poles v = 0)
    // and b (v = 1) open clamped curves with one knot vector. A cone's b has every pole at
    // its apex.
    model::BSplineCurve a;
    model::BSplineCurve b;
    // The patch's normal ∂s/∂u × ∂s/∂v points against its face loop's normal (the side the
    // design's normals point to): a writer reverses the face.
    bool flipped = false;
    // Planar patches: the corners in loop order.
    std::vector<model::Vec3> corners;

    bool isPlanar() const { return type == model::FaceType::Planar; }
    // Ruled patches only.
    model::Vec3 point(double u, double v) const;
    // ∂s/∂u and ∂s/∂v at (u, v); ruled patches only.
    void derivatives(double u, double v, model::Vec3& du, model::Vec3& dv) const;
};

// The patches of one surface in face id order. The surface must be valid (validate() empty);
// throws ModelError otherwise.
std::vector<PatchSurface> patchSurfaces(const model::CompositeSurface& surface);

// The area of a patch: Gauss–Legendre quadrature per knot span of the exact surface (relative
// error far below 1e-9 for the patches DevSurf makes); a polygon's area exactly.
double patchArea(const PatchSurface& patch);

// The diagonal of the bounding box of every control point and vertex of the project.
double projectDiameter(const model::Project& project);

// The name a patch carries in exchange files: "patch 7", or "surface 2 patch 7" when the project
// has several surfaces. A file's names are identifiers, the same in every language.
std::string patchName(const PatchSurface& patch, bool severalSurfaces);

} // namespace devsurf::io
