#pragma once

#include "sampled_mesh.h"

#include <optional>
#include <vector>

namespace devsurf::model {

// The development (V̄,Ē,F̄) of a sampled mesh: a planar position for every vertex (§5).
struct Development {
    std::vector<Vec2> vertices; // indexed like SampledMesh::vertices
    // Set when the unfolding closes up only modulo a translation, as for a surface that
    // develops onto a cylinder cut open (Fig. 14): coordinates are then read modulo period.
    std::optional<Vec2> period;
    // Largest distance between a vertex's position and where a neighbouring face puts it
    // (after reducing by the period): zero for an exactly developable, globally unfoldable mesh.
    double closureError = 0.0;
    // Largest relative difference between an edge length in space and in the development.
    double maxEdgeLengthError = 0.0;
    int components = 0;
};

// The initial development: the faces are split into triangles and unfolded one after the other
// across shared edges, breadth first, each triangle placed isometrically ("putting together
// developments of individual faces", §5). Disconnected parts are placed side by side. A flat
// component keeps the layout of its projection onto the xy-plane; a cylindrical one has its
// period along +x.
Development unfoldSampledMesh(const SampledMesh& mesh);

// The largest gap (mm) at which an unfolding still counts as one flat sheet (closure error).
inline constexpr double kOneSheetClosure = 1e-3;

// Makes `surface` hold its sheet (keepsDevelopment) as it unfolds now, on a cylinder sheet
// (SheetShape::Cylinder) of the unfolding's period where it closes around; or, changing
// nothing, the problem why it is not one sheet (several parts, a gap above kOneSheetClosure).
std::optional<Problem> keepDevelopment(CompositeSurface& surface);

// How far the surface is from its kept development (keepsDevelopment()), in mm: the largest
// difference between a distance in space and in the development over every pair of vertices of
// every face of sampleSurface(surface, kDevelopmentSamplesPerInterval), diagonals included, so
// a face that bends or shears counts. -1 when the surface keeps no development (or one that no
// longer matches its sampling).
double keptSheetStretch(const CompositeSurface& surface);
// The same pairs, each difference divided by the pair's length in the sheet: the largest
// relative edge-length error of the surface against its kept development (-1 likewise).
double keptSheetStretchRelative(const CompositeSurface& surface);

// Relative edge-length error between the mesh and a development of it (§8), using the
// development's period where it has one.
double edgeLengthError(const SampledMesh& mesh, const Development& development);

} // namespace devsurf::model
