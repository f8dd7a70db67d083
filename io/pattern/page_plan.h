#pragma once

// How a pattern is printed at 1:1 on paper: each sheet's pieces are cut into page tiles that
// overlap by a strip (to tape pages together), pages carry a band with the scale squares and
// their label, and the orientation is the one that needs fewer pages.

#include "pattern_sheets.h"

#include <string>
#include <vector>

namespace devsurf::io {

struct PageTile {
    int group = 0;      // index into PagePlan::groups
    int row = 0;        // 0 = top row
    int column = 0;     // 0 = left column
    model::Vec2 origin; // pattern point (sheet coordinates) at the top-left of the content area
    std::string label;  // "B3": row letter, column number
};

struct PagePlan {
    model::Vec2 paper; // mm, as oriented
    bool landscape = false;
    double margin = 10.0; // unprinted border on every side, mm
    double band = 58.0;   // scale squares and labels: at the bottom (portrait) or right (landscape)
    double overlap = 10.0;     // strip shared by neighbouring tiles, mm
    model::Vec2 contentOrigin; // top-left of the content area on the page, mm from the top-left
    model::Vec2 content;       // size of the content area, mm
    std::vector<SheetGroup> groups;
    std::vector<int> rows;    // per group
    std::vector<int> columns; // per group
    std::vector<PageTile> tiles;
    model::Vec2 bandOrigin; // top-left of the band on the page
    model::Vec2 bandSize;
};

// Plans the tiles of every sheet on paper of the given portrait size (mm).
PagePlan planPages(const model::CuttingPattern& pattern, const model::Vec2& portraitPaper);

// The largest sheet (portrait, mm) whose pieces print on one page of the given paper: the
// paper less its margins and the band of scale squares.
model::Vec2 printableSheet(const model::Vec2& portraitPaper);

// "A", "B", …, "Z", "AA", … for row 0, 1, …
std::string rowName(int row);

} // namespace devsurf::io
