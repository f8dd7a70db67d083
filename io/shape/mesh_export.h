#pragma once

// Triangle meshes of a design's 3D shape for renderers, slicers and mesh tools: OBJ (one group
// per patch), binary STL and binary PLY, every patch's boundary curves sampled finely enough for
// a chord tolerance. Samples along an edge are shared by its two patches, so the mesh is
// watertight wherever the design is; a thickness offsets both sides and closes the rim.

#include "model/ids.h"
#include "model/project.h"
#include "model/vec3.h"

#include <QByteArray>
#include <QString>

#include <array>
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace devsurf::io {

enum class MeshFormat { Obj, Stl, Ply };

struct MeshExportOptions {
    MeshFormat format = MeshFormat::Stl;
    double tolerance = 0.01; // mm: the chord error of the sampled curves and rulings' quads
    double thickness = 0.0;  // mm: 0 for the surface itself, else a sheet of this thickness
    // Given the fraction done (0 … 1); returns false to cancel (ShapeExportError Cancelled).
    std::function<bool(double fraction)> progress;
};

struct ShapeMesh {
    std::vector<model::Vec3> vertices;
    std::vector<std::array<int, 3>> triangles; // oriented like the design's face loops
    std::vector<std::string> groups;           // one name per patch (and "rim" with thickness)
    std::vector<int> triangleGroup;            // index into groups, per triangle
    int samplesPerInterval = 0;                // what the tolerance required
    bool toleranceMet = true; // false where even 1000 samples per interval were too coarse
};

// The smallest sampling (samples per spline interval, at most kMaxMeshSamples) at which every
// S-edge's chords and every strip's triangles stay within `tolerance` of the exact surface;
// kMaxMeshSamples + 1 where even that is too coarse.
inline constexpr int kMaxMeshSamples = 1000;
int samplesForTolerance(const model::CompositeSurface& surface, double tolerance);

// The triangulated 3D shape of every surface of the project (surfaces must be valid; throws
// ModelError otherwise).
ShapeMesh shapeMesh(const model::Project& project, const MeshExportOptions& options);

// The file's bytes: OBJ as text, STL and PLY binary (OpenMesh's writers). Empty if OpenMesh's
// writer failed.
QByteArray meshBytes(const ShapeMesh& mesh, MeshFormat format);

// shapeMesh + meshBytes, written atomically. Throws FileError where the file cannot be written.
ShapeMesh saveMeshFile(const model::Project& project, const QString& path,
                       const MeshExportOptions& options);

// "obj", "stl", "ply" → the format.
bool meshFormatFromName(const std::string& name, MeshFormat& format);

} // namespace devsurf::io
