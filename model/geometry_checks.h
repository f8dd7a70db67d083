#pragma once

#include "problem.h"

#include <vector>

namespace devsurf::model {

class CompositeSurface;

// Coordinates farther than this from the origin (in mm: one kilometre) are taken as a damaged
// or mis-scaled design, not as sheet material.
inline constexpr double kMaxCoordinate = 1.0e6;

// Degenerate geometry of a structurally sound surface, as problems naming the faces: positions
// that are not finite or absurdly large, curves and rulings of zero length, curves pinched
// (a stretch shrunk to a point), coincident
// vertices of a face, faces of zero area. Part of CompositeSurface::validate(); entities whose
// data are structurally broken (e.g. a wrong control-point count) are skipped here because
// validate() reports them already. SolveSession checks every iterate with it.
std::vector<Problem> degenerateGeometryProblems(const CompositeSurface& surface);

// Every vertex and control point has finite coordinates.
bool allCoordinatesFinite(const CompositeSurface& surface);

} // namespace devsurf::model
