#pragma once

// The creases of a surface, worked out once for everything that needs them: the interchange
// JSON, the cutting pattern (mountain and valley layers), the views and the solver's crease
// conditions. A crease is an S-edge shared by two faces.

#include "model/composite_surface.h"
#include "model/sampled_mesh.h"
#include "model/strip.h"

#include <cstddef>
#include <vector>

namespace devsurf::model {

// How a crease is folded, seen from the side the surface's normals point to (the side its face
// loops run counter-clockwise around): a mountain turns both faces away from the viewer, a
// valley towards them; flat is folded by less than kFlatFoldDegrees.
enum class FoldAssignment { Mountain, Valley, Flat };

// Folds below this angle (degrees) count as flat.
inline constexpr double kFlatFoldDegrees = 0.1;

// "M", "V" or "F", as origami files (FOLD) and the interchange JSON write it.
const char* foldAssignmentLetter(FoldAssignment assignment);

// One of the two faces at a crease.
struct CreaseSide {
    FaceId face = kInvalidId;
    // Index into stripsOf(surface) of the face's strip or cone; kNoStrip for a planar face.
    std::size_t strip = kNoStrip;
    // Which of the strip's curves the crease is (a: true, b: false), and whether that curve
    // runs against the edge's stored orientation (from → to).
    bool sideA = true;
    bool reversed = false;
    // The strip's own normal a′ × (b − a) points to the other side of the surface than the
    // face loop's normal: multiply it by −1 to orient both faces' normals alike.
    bool flipNormal = false;

    static constexpr std::size_t kNoStrip = static_cast<std::size_t>(-1);
};

struct Crease {
    EdgeId edge = kInvalidId;
    // Seen from the normal side, walking the edge from → to: `left` lies on the left.
    CreaseSide left;
    CreaseSide right;
    // Mean signed dihedral fold angle along the crease in degrees (> 0 mountain, < 0 valley),
    // weighted by the sampled length, and the largest |fold angle| along it.
    double foldAngleDegrees = 0.0;
    double maxFoldAngleDegrees = 0.0;
    FoldAssignment assignment = FoldAssignment::Flat;
};

// Every crease of the surface in edge id order. `strips` is stripsOf(surface) and `mesh` the
// surface's sampled mesh (the fold angles come from its faces on either side of the crease).
std::vector<Crease> creasesOf(const CompositeSurface& surface, const std::vector<Strip>& strips,
                              const SampledMesh& mesh);

} // namespace devsurf::model
