#pragma once

// The sheet a held development is confined to (CompositeSurface::sheetDomain), drawn where a
// piece of the pattern lies: the development view shows it behind the piece, so a designer
// sees the development stay on its sheet while the 3D shape folds.

#include "model/composite_surface.h"
#include "model/pattern/cutting_pattern.h"
#include "model/plane_motion.h"

#include <optional>
#include <vector>

namespace devsurf::model::pattern {

// The boundary loops of `surface`'s sheet (outer first, then holes; closed, the first point
// not repeated; circles as polygons within `chordTolerance` mm) in the coordinates of `piece`,
// a piece of that surface's pattern: the rigid motion (a mirror allowed, as the pattern may
// show the sheet from its other side) that best maps the kept development's coarse vertices
// onto the piece's. Empty when the surface holds no sheet of a shape, has no development yet,
// or the piece has fewer than two of its vertices.
std::vector<std::vector<Vec2>> sheetOnPiece(const CompositeSurface& surface,
                                            const PatternPiece& piece, double chordTolerance);

// The curves drawn in that sheet for its creases to follow (SheetDomain::creaseCurves), by the
// same motion, as polylines (a closed one repeats its first point); empty where sheetOnPiece is.
std::vector<std::vector<Vec2>> creaseCurvesOnPiece(const CompositeSurface& surface,
                                                   const PatternPiece& piece);

} // namespace devsurf::model::pattern
