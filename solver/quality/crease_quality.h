#pragma once

// How well the crease conditions of a design hold, measured from the geometry alone (the
// strips' own normals a′ × (b − a), never the solver's normal variables).

#include "model/composite_surface.h"

#include <vector>

namespace devsurf::solver {

struct CreaseQuality {
    // Creases with a condition (curved fold, geodesic, straight when unfolded) between two
    // strips, and the parameter values sampled.
    int creases = 0;
    int samples = 0;
    // Over those creases: |⟨c²ᵢ − c²ᵢ₊₁, n_L ± n_R⟩| / (|c²ᵢ − c²ᵢ₊₁| |n_L ± n_R|), i = 0, 1,
    // with + for a curved fold (7) and − for a geodesic (8); n_L, n_R the unit normals of the
    // two strips at the crease, oriented to the same side. Samples where a factor vanishes
    // (a straight piece of crease, or n_L ± n_R = 0, where the condition holds trivially) count
    // as 0. For "straight when unfolded": |⟨o, n_L⟩| with o the unit normal of the osculating
    // plane (spanned by c²₀ − c²₁ and c²₁ − c²₂), i.e. the sine of the angle between n_L and that
    // plane; 0 where the crease is locally straight.
    double residualMax = 0.0;
    double residualMean = 0.0;
    // Mean |fold angle| (degrees) over every crease of the surface, with or without condition.
    double meanFoldDegrees = 0.0;
};

// Throws model::ModelError if the surface is not valid.
CreaseQuality measureCreaseQuality(const model::CompositeSurface& surface,
                                   int samplesPerInterval = 50);

// The curved-fold residual (7) of every crease between two strips (whatever its condition), in
// edge id order: the largest and the mean of |⟨c²ᵢ − c²ᵢ₊₁, n_L + n_R⟩| /
// (|c²ᵢ − c²ᵢ₊₁| |n_L + n_R|) over `samplesPerInterval` values per interval, measured as
// measureCreaseQuality does. Throws model::ModelError if the surface is not valid.
struct CreaseResidual {
    model::EdgeId edge = model::kInvalidId;
    double max = 0.0;
    double mean = 0.0;
};
std::vector<CreaseResidual> curvedFoldResiduals(const model::CompositeSurface& surface,
                                                int samplesPerInterval = 50);

} // namespace devsurf::solver
