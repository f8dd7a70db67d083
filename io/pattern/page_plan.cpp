#include "page_plan.h"

#include <algorithm>
#include <cmath>

namespace devsurf::io {

using model::Vec2;

namespace {

int tilesAlong(double length, double content, double overlap) {
    if (length <= content) {
        return 1;
    }
    return static_cast<int>(std::ceil((length - overlap) / (content - overlap) - 1e-9));
}

PagePlan plan(const std::vector<SheetGroup>& groups, const Vec2& portrait, bool landscape) {
    PagePlan p;
    p.landscape = landscape;
    p.paper = landscape ? Vec2{portrait.y, portrait.x} : portrait;
    p.groups = groups;
    p.contentOrigin = {p.margin, p.margin};
    if (landscape) {
        p.content = {p.paper.x - 2.0 * p.margin - p.band, p.paper.y - 2.0 * p.margin};
        p.bandOrigin = {p.paper.x - p.margin - p.band, p.margin};
        p.bandSize = {p.band, p.content.y};
    } else {
        p.content = {p.paper.x - 2.0 * p.margin, p.paper.y - 2.0 * p.margin - p.band};
        p.bandOrigin = {p.margin, p.paper.y - p.margin - p.band};
        p.bandSize = {p.content.x, p.band};
    }
    for (std::size_t g = 0; g < groups.size(); ++g) {
        const SheetGroup& group = groups[g];
        const int columns = tilesAlong(group.max.x - group.min.x, p.content.x, p.overlap);
        const int rows = tilesAlong(group.max.y - group.min.y, p.content.y, p.overlap);
        p.rows.push_back(rows);
        p.columns.push_back(columns);
        for (int r = 0; r < rows; ++r) {
            for (int c = 0; c < columns; ++c) {
                PageTile tile;
                tile.group = static_cast<int>(g);
                tile.row = r;
                tile.column = c;
                tile.origin = {group.min.x + c * (p.content.x - p.overlap),
                               group.max.y - r * (p.content.y - p.overlap)};
                tile.label = rowName(r) + std::to_string(c + 1);
                p.tiles.push_back(tile);
            }
        }
    }
    return p;
}

} // namespace

std::string rowName(int row) {
    std::string name;
    for (int n = row + 1; n > 0; n = (n - 1) / 26) {
        name.insert(name.begin(), static_cast<char>('A' + (n - 1) % 26));
    }
    return name;
}

model::Vec2 printableSheet(const Vec2& portraitPaper) {
    const PagePlan p = plan({}, portraitPaper, false);
    return p.content;
}

PagePlan planPages(const model::CuttingPattern& pattern, const Vec2& portraitPaper) {
    const std::vector<SheetGroup> groups = sheetGroups(pattern);
    PagePlan portrait = plan(groups, portraitPaper, false);
    PagePlan landscape = plan(groups, portraitPaper, true);
    return landscape.tiles.size() < portrait.tiles.size() ? landscape : portrait;
}

} // namespace devsurf::io
