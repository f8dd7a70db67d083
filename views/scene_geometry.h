#pragma once

// Internal to views/: what the 3D and the development view draw and pick, as plain data (no
// VTK), built from the model's sampled mesh and development.

#include "model/composite_surface.h"
#include "model/creases.h"
#include "model/pattern/cutting_pattern.h"
#include "model/project.h"
#include "model/vec3.h"

#include <array>
#include <map>
#include <set>
#include <utility>
#include <vector>

namespace devsurf::views {

// One coarse edge as drawn: the sampled curve of an S-edge, the segment of an R-edge.
struct EdgeCurve {
    model::EdgeId id = model::kInvalidId;
    bool spline = false;
    bool crease = false; // an S-edge shared by two faces
    // How a crease is folded (model::creasesOf), drawn in the origami colours.
    model::FoldAssignment fold = model::FoldAssignment::Flat;
    // What the solver imposes on a crease (creases only; None otherwise).
    model::CreaseCondition condition = model::CreaseCondition::None;
    // A ruling between two patches that the surface stays smooth across (false: sharp, or not
    // such a ruling).
    bool smooth = false;
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
    std::vector<int> pointOrigin;     // per point, 3D only: its vertex of the sampled mesh
    std::vector<std::vector<int>> polygons;
    std::vector<model::FaceId> polygonFace;
    // 3D only, the quality measures of solver/quality (those the Solver panel reports): per
    // polygon its patch's developability residual within the polygon's span of u (0 for cones
    // and planar patches; the largest over a patch's polygons is the panel's value of the patch)
    // and its flatness δ; per point the angle defect |K| of its sampled-mesh vertex. NaN where a
    // measure does not apply (triangles for δ, boundary vertices for |K|).
    std::vector<double> polygonDevelopability;
    std::vector<double> polygonFlatness;
    std::vector<double> pointAngleDefect;
    std::vector<EdgeCurve> edges;
    std::vector<std::pair<model::Vec3, model::Vec3>> rulings; // development only
    std::vector<std::pair<model::Vec3, model::Vec3>> outline; // development only
    std::vector<std::vector<model::Vec3>> controlPolygons;    // 3D only
    std::vector<model::Vec3> controlPoints;                   // interior ones, 3D only
    std::map<model::VertexId, model::Vec3> vertices;
    // The pinned vertices among them (the solver never moves them; drawn red).
    std::set<model::VertexId> pinned;
    // Development only: the second copy of every vertex on a cut-open seam (drawn, not picked)
    // and the outline of every piece that overlaps itself or another one (drawn in red).
    std::vector<model::Vec3> seamVertices;
    std::vector<std::pair<model::Vec3, model::Vec3>> overlapOutline;
    // Development only: the boundary loops of the sheet a held development is confined to
    // (closed polylines, the first point repeated) and the crease curves drawn in it (open or
    // closed polylines), placed where the development is drawn.
    std::vector<std::vector<model::Vec3>> sheet;
};

// Resolution of the curves drawn: samples per spline interval.
inline constexpr int kSamplesPerInterval = 8;

// The surface in space. Throws model::ModelError if the surface is not valid.
SurfaceScene buildSpatialScene(const model::CompositeSurface& surface, int surfaceIndex);

// What a view draws: one scene per surface it could build, and the indices of the surfaces it
// could not (not valid).
struct SceneSet {
    std::vector<SurfaceScene> scenes;
    std::vector<int> invalidSurfaces;
};
using DevelopmentScenes = SceneSet;

// The development of every surface as the cutting pattern (model::buildCuttingPattern) lays it
// out without sheets: every surface's pieces side by side in the plane z = 0, cut open where a
// surface does not close up, oriented as the 3D view shows the surface. One scene per surface
// that could be developed; invalidSurfaces lists the indices of those that are not valid.
DevelopmentScenes buildDevelopmentScenes(const model::Project& project);

// The same in two steps, so that the first can be kept per surface revision (SceneCache): the
// pieces of one surface as the cutting pattern develops them (before the layout), ...
struct SurfaceDevelopment {
    bool invalid = false;                    // the surface is not valid
    std::vector<model::PatternPiece> pieces; // none if it could not be developed
};
SurfaceDevelopment developSurfaceForView(const model::CompositeSurface& surface, int surfaceIndex);
// ... then the pieces of every surface (one development per surface of the project, in order)
// laid out side by side. Equals buildDevelopmentScenes(project).
DevelopmentScenes layOutDevelopments(const model::Project& project,
                                     const std::vector<const SurfaceDevelopment*>& developments);

// Axis-aligned bounds of a scene's polygons: {min, max}.
std::pair<model::Vec3, model::Vec3> sceneBounds(const SurfaceScene& scene);

// The fixed patch palette (RGB in 0..1) shared by the views and the panels.
std::array<double, 3> patchRgb(model::FaceId face);

} // namespace devsurf::views
