#include "pattern_sheets.h"

#include <algorithm>
#include <limits>
#include <map>

namespace devsurf::io {

using model::Vec2;

std::pair<Vec2, Vec2> piecesBounds(const model::CuttingPattern& pattern,
                                   const std::vector<int>& pieces) {
    constexpr double inf = std::numeric_limits<double>::infinity();
    Vec2 lo{inf, inf};
    Vec2 hi{-inf, -inf};
    auto add = [&](const Vec2& p) {
        lo = {std::min(lo.x, p.x), std::min(lo.y, p.y)};
        hi = {std::max(hi.x, p.x), std::max(hi.y, p.y)};
    };
    for (int index : pieces) {
        const model::PatternPiece& piece = pattern.pieces[static_cast<std::size_t>(index)];
        std::for_each(piece.outline.begin(), piece.outline.end(), add);
        for (const model::PatternPath& path : piece.paths) {
            std::for_each(path.points.begin(), path.points.end(), add);
        }
        for (const model::PatternLabel& label : piece.labels) {
            add(label.position);
        }
    }
    if (lo.x > hi.x) {
        return {{0.0, 0.0}, {0.0, 0.0}};
    }
    return {lo, hi};
}

std::vector<SheetGroup> sheetGroups(const model::CuttingPattern& pattern) {
    std::map<int, std::vector<int>> bySheet;
    std::vector<int> unplaced;
    for (std::size_t i = 0; i < pattern.pieces.size(); ++i) {
        if (pattern.pieces[i].sheet >= 0) {
            bySheet[pattern.pieces[i].sheet].push_back(static_cast<int>(i));
        } else {
            unplaced.push_back(static_cast<int>(i));
        }
    }
    std::vector<SheetGroup> groups;
    auto add = [&](int sheet, const std::vector<int>& pieces) {
        SheetGroup group;
        group.sheet = sheet;
        group.pieces = pieces;
        std::tie(group.min, group.max) = piecesBounds(pattern, pieces);
        groups.push_back(group);
    };
    for (const auto& [sheet, pieces] : bySheet) {
        add(sheet, pieces);
    }
    // Pieces the layout could not place may lie on top of each other: each is its own group.
    for (int index : unplaced) {
        add(-1, {index});
    }
    // Placed sheets keep their sheet frame (origin at the sheet's corner) so that a cutter sees
    // the pieces where the layout put them; sheets follow each other along x.
    double x = 0.0;
    for (SheetGroup& group : groups) {
        if (group.sheet >= 0) {
            group.offset = {x, 0.0};
            const double width = std::max(pattern.sheetSize.x, group.max.x);
            x += width + kSheetSpacing;
        } else {
            group.offset = {x - group.min.x, -group.min.y};
            x += group.max.x - group.min.x + kSheetSpacing;
        }
    }
    return groups;
}

std::pair<Vec2, Vec2> drawingBounds(const std::vector<SheetGroup>& groups) {
    if (groups.empty()) {
        return {{0.0, 0.0}, {0.0, 0.0}};
    }
    Vec2 lo = groups.front().min + groups.front().offset;
    Vec2 hi = groups.front().max + groups.front().offset;
    for (const SheetGroup& group : groups) {
        const Vec2 a = group.min + group.offset;
        const Vec2 b = group.max + group.offset;
        lo = {std::min(lo.x, a.x), std::min(lo.y, a.y)};
        hi = {std::max(hi.x, b.x), std::max(hi.y, b.y)};
    }
    return {lo, hi};
}

} // namespace devsurf::io
