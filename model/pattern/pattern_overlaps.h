#pragma once

// Overlap checks of a pattern: a piece whose development overlaps itself cannot be cut from one
// sheet; two pieces that overlap on a sheet cannot both be cut.

#include "model/pattern/cutting_pattern.h"

#include <vector>

namespace devsurf::model::pattern {

// Whether the piece's cut loops (outline and holes) cross themselves or each other, or a face
// of its mesh lies on top of another. faces receives the patches of the mesh faces at the
// crossing segments (or of the faces on top of each other).
bool selfOverlaps(const PatternPiece& piece, std::vector<FaceId>& faces);

// Whether two pieces' areas overlap: their loops cross, or one lies inside the other.
bool piecesOverlap(const PatternPiece& a, const PatternPiece& b);

// Every pair of pieces on the same sheet that overlap (pieces without a sheet are skipped).
std::vector<PatternOverlap> overlapsBetweenPieces(const std::vector<PatternPiece>& pieces);

} // namespace devsurf::model::pattern
