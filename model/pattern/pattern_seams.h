#pragma once

// Seam allowances and glue tabs along the glued sides of a piece's outline.

#include "model/pattern/pattern_pieces.h"

#include <vector>

namespace devsurf::model::pattern {

// The polyline offset by width to the right of its direction (outwards for a counter-clockwise
// outline; to the left for a negative width), from the offset of its first point to that of its
// last, with mitred corners (at most 4 widths out) and the loops of concave corners cut off: the
// far side of Boost.Geometry's one-sided buffer of the polyline. Empty for fewer than two
// distinct points or no width.
std::vector<Vec2> offsetPolyline(const std::vector<Vec2>& points, double width);

// On one side of every seam (SeamRun::primary) the outline is replaced by a strip of
// options.seamAllowance outside it (or, with options.glueTabs, one trapezoidal tab per seam
// edge, its ends set back by the same width); the original edge is kept on the SEAM layer.
// The outline path on the CUT layer follows. Does nothing without an allowance.
void addSeamAllowances(PieceBuild& build, const PatternOptions& options);

} // namespace devsurf::model::pattern
