#pragma once

// Labels of a pattern: the piece's name inside it, and one number per cut-open seam on both of
// its sides, so a builder knows what is glued to what.

#include "model/pattern/pattern_pieces.h"

namespace devsurf::model::pattern {

// Decides which side of every seam gets the allowance or tab: along each chain of consecutive
// seam edges on the outline, the whole chain on one side.
void choosePrimarySides(PieceBuild& build);

// The piece's name, upright, at a point inside the piece.
void addPieceLabel(PatternPiece& piece);

// "<piece><seam>" (e.g. "A1") along the middle of both sides of every seam, inside the piece.
void addSeamLabels(PieceBuild& build);

// The points of a seam run along the outline.
std::vector<Vec2> runPoints(const PatternPiece& piece, const SeamRun& run);

} // namespace devsurf::model::pattern
