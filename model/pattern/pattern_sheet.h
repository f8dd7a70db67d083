#pragma once

// The sheet a held development is confined to (CompositeSurface::sheetDomain), drawn where a
// piece of the pattern lies: the development view shows it behind the piece, so a designer
// sees the development stay on its sheet while the 3D shape folds.

#include "model/composite_surface.h"
#include "model/pattern/cutting_pattern.h"

#include <optional>
#include <vector>

namespace devsurf::model::pattern {

// A rigid motion of the plane, a mirror allowed: p ↦ R(angle)·(mirror(p) − from) + to, with
// mirror(x, y) = (−x, y) when mirrored.
struct PlaneMotion {
    bool mirrored = false;
    double angle = 0.0;
    Vec2 from;
    Vec2 to;

    Vec2 apply(const Vec2& p) const;
    Vec2 applyInverse(const Vec2& p) const;
};

// The rigid motion (a mirror allowed) that best maps `from` onto `to` (2D Procrustes: least
// squared distances); none for fewer than two pairs or lists of different lengths.
std::optional<PlaneMotion> fitPlaneMotion(const std::vector<Vec2>& from,
                                          const std::vector<Vec2>& to);

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
