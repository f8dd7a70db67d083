#pragma once

// Arranging the pieces of a pattern on sheets.

#include "model/pattern/cutting_pattern.h"

#include <string>
#include <vector>

namespace devsurf::model::pattern {

// With options.layout: every piece is first turned to its smallest bounding rectangle where
// that saves more than 1 % of material (options.allowRotation), then packed with the MaxRects
// heuristic "best short side fit" (Jylänki, "A Thousand Ways to Pack the Bin", 2010) on as
// many sheets as needed, each rectangle trying both orientations, grown by options.gap so that
// pieces keep that gap to each other and to the sheet's edge. A piece that does not fit on an
// empty sheet gets sheet = -1 and a PieceTooLarge problem; it is left at the origin.
// Without options.layout the pieces lie side by side on one sheet (0), options.gap apart, in
// rows from the top down (the first on y = 0, the next below it), each row at most
// kSideBySideRowAspect times the side of the square of the pieces' area (or as wide as the widest
// piece). Returns the number of sheets used.
inline constexpr double kSideBySideRowAspect = 1.5;
int layoutPieces(std::vector<PatternPiece>& pieces, const PatternOptions& options,
                 const std::vector<std::string>& surfaceNames,
                 std::vector<PatternProblem>& problems);

} // namespace devsurf::model::pattern
