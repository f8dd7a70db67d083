#pragma once

// The first step of a cutting pattern: a surface developed into flat pieces (cut open where it
// does not close up), each with its outline, creases, rulings and mesh, oriented like the
// surface is seen in the 3D view. Layout, overlaps and seam allowances come later.

#include "model/composite_surface.h"
#include "model/pattern/cutting_pattern.h"

#include <string>
#include <vector>

namespace devsurf::model::pattern {

// One side of a cut-open seam as it lies on a piece's outline.
struct SeamRun {
    int first = 0; // index into PatternPiece::outline
    int last = 0;  // the run is first, first + 1, …, last (modulo the outline's size)
    EdgeId edge = kInvalidId;
    int seam = 0;         // seams are numbered from 1 per piece; both sides share the number
    bool primary = false; // the side that gets the seam allowance or the glue tab
};

struct PieceBuild {
    PatternPiece piece;
    std::vector<SeamRun> seams;
};

// "A", "B", …, "Z", "AA", "AB", …
std::string pieceName(int index);

// Samples per spline interval such that no sampled chord of the surface's curves is further
// than tolerance from its curve (at most 1000).
int samplesForTolerance(const CompositeSurface& surface, double tolerance);

// The pieces of one (valid) surface; names continue from nameIndex, which is advanced.
std::vector<PieceBuild> developSurface(const CompositeSurface& surface, int surfaceIndex,
                                       const PatternOptions& options, int& nameIndex);

} // namespace devsurf::model::pattern
