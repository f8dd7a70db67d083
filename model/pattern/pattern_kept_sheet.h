#pragma once

// A surface that keeps its development is cut from that sheet (§5): the pattern's own unfolding,
// at its finer sampling, is laid onto the kept development.

#include "model/composite_surface.h"
#include "model/development.h"
#include "model/pattern/pattern_cut.h"

namespace devsurf::model::pattern {

// Whether the copies of every vertex on the cut land within tolerance of each other: the
// surface then closes up in the plane (a flat annulus) and need not be cut.
bool copiesCoincide(const CutMesh& cut, const Development& development, double tolerance);

// Lays `development` of `cut` (the surface's `mesh` at the pattern's sampling, cut open or not)
// onto the kept development: by the rigid motion that best maps the samples both share, then
// each shared sample put exactly where the kept sheet has it and the samples between two of
// them along a curve moved with them linearly (each side of a cut with its own copies).
// Unchanged, and false, for a surface that keeps no development (or one from another sampling),
// or a sheet around a cylinder.
bool layOntoKeptSheet(const CompositeSurface& surface, const SampledMesh& mesh, const CutMesh& cut,
                      Development& development);

} // namespace devsurf::model::pattern
