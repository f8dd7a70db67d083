#pragma once

// For every crease of a surface (an S-edge shared by two patches): which patch lies on its
// left and which on its right, and how far it is folded.

#include "model/composite_surface.h"
#include "model/sampled_mesh.h"

#include <vector>

namespace devsurf::model {

struct CreaseFold {
    EdgeId edge = kInvalidId;
    // The patch whose loop runs along the edge's stored orientation (from → to): seen from the
    // side the patches' normals point to, it lies on the left of the edge.
    FaceId left = kInvalidId;
    FaceId right = kInvalidId;
    // Mean signed dihedral fold angle along the crease, in degrees, seen from the normal side:
    // > 0 a mountain (the patches turn away from the viewer), < 0 a valley, 0 flat.
    double foldAngleDegrees = 0.0;
    // Largest |fold angle| along the crease, in degrees.
    double maxFoldAngleDegrees = 0.0;
};

// Folds below this angle (degrees) count as flat: such a crease is drawn as "CREASE".
inline constexpr double kFlatFoldDegrees = 0.1;

// Every crease of the surface, in edge id order; the mesh is the surface's sampled mesh (the
// normals come from its faces on either side of the crease's samples).
std::vector<CreaseFold> creaseFolds(const CompositeSurface& surface, const SampledMesh& mesh);

} // namespace devsurf::model
