#pragma once

#include <string>
#include <vector>

namespace devsurf::model {

class CompositeSurface;

// Coordinates farther than this from the origin (in mm: one kilometre) are taken as a damaged
// or mis-scaled design, not as sheet material.
inline constexpr double kMaxCoordinate = 1.0e6;

// Degenerate geometry of a structurally sound surface, as sentences naming the faces: positions
// that are not finite or absurdly large, curves and rulings of zero length, coincident
// vertices of a face, faces of zero area. Part of CompositeSurface::validate(); entities whose
// data are structurally broken (e.g. a wrong control-point count) are skipped here because
// validate() reports them already.
//
// GeometryChecks::VerticesAndEdges leaves out the faces (coincident vertices, zero area),
// which cost most: the check a solver step's result gets (SolveSession::step), a ruling or
// curve collapsed to a point.
enum class GeometryChecks { All, VerticesAndEdges };
std::vector<std::string> degenerateGeometryProblems(const CompositeSurface& surface,
                                                    GeometryChecks checks = GeometryChecks::All);

} // namespace devsurf::model
