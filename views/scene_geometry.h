#pragma once

// Internal to views/: what the 3D and the development view draw and pick, as plain data (no
// VTK), built from the model's sampled mesh and development.

#include "model/composite_surface.h"
#include "model/vec3.h"

#include <array>
#include <map>
#include <utility>
#include <vector>

namespace devsurf::views {

// One coarse edge as drawn: the sampled curve of an S-edge, the segment of an R-edge.
struct EdgeCurve {
    model::EdgeId id = model::kInvalidId;
    bool spline = false;
    bool crease = false; // an S-edge shared by two faces
    bool boundary = false;
    std::vector<model::Vec3> points;
};

// Everything one surface contributes to a view, in the view's scene coordinates (space for the
// 3D view; the development plane z = 0 for the 2D view).
struct SurfaceScene {
    int surface = 0;
    // Polygon corners. Points are not shared across coarse faces so that creases stay sharp
    // (3D) and a development with a period can be cut open (2D).
    std::vector<model::Vec3> points;
    std::vector<model::Vec3> normals; // per point, 3D only
    std::vector<std::vector<int>> polygons;
    std::vector<model::FaceId> polygonFace;
    std::vector<EdgeCurve> edges;
    std::vector<std::pair<model::Vec3, model::Vec3>> rulings; // development only
    std::vector<std::pair<model::Vec3, model::Vec3>> outline; // development only
    std::vector<std::vector<model::Vec3>> controlPolygons;    // 3D only
    std::vector<model::Vec3> controlPoints;                   // interior ones, 3D only
    std::map<model::VertexId, model::Vec3> vertices;
};

// Resolution of the curves drawn: samples per spline interval.
inline constexpr int kSamplesPerInterval = 8;

// The surface in space. Throws model::ModelError if the surface is not valid.
SurfaceScene buildSpatialScene(const model::CompositeSurface& surface, int surfaceIndex);

// The development (model::unfoldSampledMesh) in the plane z = 0, its lower left corner moved
// to (x0, 0). Throws model::ModelError if the surface is not valid.
SurfaceScene buildDevelopmentScene(const model::CompositeSurface& surface, int surfaceIndex,
                                   double x0);

// Axis-aligned bounds of a scene's polygons: {min, max}.
std::pair<model::Vec3, model::Vec3> sceneBounds(const SurfaceScene& scene);

// The fixed patch palette (RGB in 0..1) shared by the views and the panels.
std::array<double, 3> patchRgb(model::FaceId face);

} // namespace devsurf::views
