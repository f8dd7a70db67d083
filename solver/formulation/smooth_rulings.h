#pragma once

// Smooth transitions across rulings (docs/math.md §3): the unit normals of the two faces at a
// shared R-edge agree.

#include "model/composite_surface.h"
#include "solver/core/linear_term.h"
#include "solver/core/term.h"

#include <map>
#include <utility>
#include <vector>

namespace devsurf::solver {

// The normal of a face at one of its R-edges as a combination of state values, keyed by
// (face, edge).
using RulingNormals = std::map<std::pair<model::FaceId, model::EdgeId>, PointCombination>;

// `normal` (a combination of state values, evaluated at `state`) oriented like the face loop's
// normal: the loop runs along the ruling from p to q and the face lies on its left, so the loop's
// normal points along (q − p) × inward, with `inward` a direction from the ruling into the face.
// Returns the combination negated where it points the other way.
PointCombination orientedRulingNormal(const model::CompositeSurface& surface, model::FaceId face,
                                      model::EdgeId edge, const PointCombination& normal,
                                      const model::Vec3& inward, const std::vector<double>& state);

// n_f − n_g = 0 (3 rows) for every ruling shared by faces f, g that is marked smooth in the surface
// (EdgeRecord::smooth) or listed in `requested`, each once; `normals` must be oriented alike
// (orientedRulingNormal). Throws std::invalid_argument (naming the edge) for a requested edge
// that is not a ruling between two faces. Returns the number of rulings made smooth.
int addSmoothRulings(const model::CompositeSurface& surface,
                     const std::vector<model::EdgeId>& requested, const RulingNormals& normals,
                     LinearTerm& term);

} // namespace devsurf::solver
