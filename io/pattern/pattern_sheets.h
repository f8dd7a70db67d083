#pragma once

// Where the sheets of a cutting pattern go when several are written into one drawing (DXF,
// SVG, FOLD) or printed one after another (PDF): the pattern places every piece in the
// coordinates of its own sheet, so sheets are set side by side here.

#include "model/pattern/cutting_pattern.h"

#include <utility>
#include <vector>

namespace devsurf::io {

// Space between sheets set side by side, mm.
inline constexpr double kSheetSpacing = 20.0;

struct SheetGroup {
    int sheet = -1;          // the pattern's sheet index; -1: a piece the layout could not place
    std::vector<int> pieces; // indices into CuttingPattern::pieces
    model::Vec2 min;         // bounds of the pieces in their own (sheet) coordinates
    model::Vec2 max;
    model::Vec2 offset; // added to the coordinates when sheets are set side by side
};

// Every sheet with pieces, in order, then each piece the layout could not place on its own.
std::vector<SheetGroup> sheetGroups(const model::CuttingPattern& pattern);

// Bounds of the given pieces: outlines, paths and label anchors. {min, max}; {0,0},{0,0} when
// there is nothing.
std::pair<model::Vec2, model::Vec2> piecesBounds(const model::CuttingPattern& pattern,
                                                 const std::vector<int>& pieces);

// Bounds of all groups side by side (offsets applied).
std::pair<model::Vec2, model::Vec2> drawingBounds(const std::vector<SheetGroup>& groups);

} // namespace devsurf::io
