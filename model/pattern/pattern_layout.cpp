#include "pattern_layout.h"

#include "model/math_constants.h"
#include "pattern_geometry.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numeric>

namespace devsurf::model::pattern {

namespace {

constexpr double kEpsilon = 1e-9;

struct Rect {
    double x = 0.0;
    double y = 0.0;
    double w = 0.0;
    double h = 0.0;
    bool contains(const Rect& o) const {
        return o.x >= x - kEpsilon && o.y >= y - kEpsilon && o.x + o.w <= x + w + kEpsilon &&
               o.y + o.h <= y + h + kEpsilon;
    }
    bool overlaps(const Rect& o) const {
        return o.x < x + w - kEpsilon && x < o.x + o.w - kEpsilon && o.y < y + h - kEpsilon &&
               y < o.y + o.h - kEpsilon;
    }
};

// One sheet's free space as the maximal free rectangles of MaxRects.
struct Sheet {
    std::vector<Rect> free;

    void occupy(const Rect& used) {
        std::vector<Rect> next;
        for (const Rect& f : free) {
            if (!f.overlaps(used)) {
                next.push_back(f);
                continue;
            }
            if (used.x > f.x + kEpsilon) {
                next.push_back({f.x, f.y, used.x - f.x, f.h});
            }
            if (used.x + used.w < f.x + f.w - kEpsilon) {
                next.push_back({used.x + used.w, f.y, f.x + f.w - used.x - used.w, f.h});
            }
            if (used.y > f.y + kEpsilon) {
                next.push_back({f.x, f.y, f.w, used.y - f.y});
            }
            if (used.y + used.h < f.y + f.h - kEpsilon) {
                next.push_back({f.x, used.y + used.h, f.w, f.y + f.h - used.y - used.h});
            }
        }
        free.clear();
        for (std::size_t i = 0; i < next.size(); ++i) {
            bool redundant = false;
            for (std::size_t j = 0; j < next.size() && !redundant; ++j) {
                // Of two equal rectangles keep the first.
                redundant =
                    i != j && next[j].contains(next[i]) && (!next[i].contains(next[j]) || j < i);
            }
            if (!redundant) {
                free.push_back(next[i]);
            }
        }
    }
};

struct Choice {
    int sheet = -1;
    Rect rect;
    bool turned = false;
    double shortSide = std::numeric_limits<double>::infinity();
    double longSide = std::numeric_limits<double>::infinity();
};

// Turns a piece to its smallest-area bounding rectangle (an edge of the convex hull along x)
// if that saves more than 1 % over its current one.
double materialSavingAngle(const PatternPiece& piece) {
    const std::vector<Vec2> hull = convexHull(piece.outline);
    if (hull.size() < 3) {
        return 0.0;
    }
    const auto [lo, hi] = pieceBounds(piece);
    const double current = (hi.x - lo.x) * (hi.y - lo.y);
    double best = current;
    double bestAngle = 0.0;
    for (std::size_t i = 0; i < hull.size(); ++i) {
        const Vec2 d = hull[(i + 1) % hull.size()] - hull[i];
        // The MaxRects step tries quarter turns itself: keep the turn within ±45°.
        const double angle = std::remainder(-std::atan2(d.y, d.x), kPi / 2.0);
        const Placement turn{angle, Vec2()};
        double minX = std::numeric_limits<double>::infinity();
        double minY = minX;
        double maxX = -minX;
        double maxY = -minX;
        for (const Vec2& p : hull) {
            const Vec2 q = turn.apply(p);
            minX = std::min(minX, q.x);
            maxX = std::max(maxX, q.x);
            minY = std::min(minY, q.y);
            maxY = std::max(maxY, q.y);
        }
        const double area = (maxX - minX) * (maxY - minY);
        if (area < best) {
            best = area;
            bestAngle = angle;
        }
    }
    return best < 0.99 * current ? bestAngle : 0.0;
}

} // namespace

int layoutPieces(std::vector<PatternPiece>& pieces, const PatternOptions& options,
                 const std::vector<std::string>& surfaceNames,
                 std::vector<PatternProblem>& problems) {
    const double gap = std::max(0.0, options.gap);
    if (!options.layout) {
        // In rows from the top down, each at most kSideBySideRowAspect times as wide as the
        // pieces' square (or the widest piece), so that many long pieces (rings) still read.
        double area = 0.0;
        double widest = 0.0;
        for (const PatternPiece& piece : pieces) {
            const auto [lo, hi] = pieceBounds(piece);
            area += (hi.x - lo.x + gap) * (hi.y - lo.y + gap);
            widest = std::max(widest, hi.x - lo.x);
        }
        const double rowWidth = std::max(widest, kSideBySideRowAspect * std::sqrt(area));
        // First the rows and their heights, then each row on its baseline: the first at y = 0,
        // every next one below the last.
        std::vector<int> rowOf(pieces.size(), 0);
        std::vector<double> rowHeight(1, 0.0);
        double x = 0.0;
        for (std::size_t i = 0; i < pieces.size(); ++i) {
            const auto [lo, hi] = pieceBounds(pieces[i]);
            if (x > 0.0 && x + (hi.x - lo.x) > rowWidth) {
                x = 0.0;
                rowHeight.push_back(0.0);
            }
            rowOf[i] = static_cast<int>(rowHeight.size()) - 1;
            rowHeight.back() = std::max(rowHeight.back(), hi.y - lo.y);
            x += hi.x - lo.x + gap;
        }
        std::vector<double> baseline(rowHeight.size(), 0.0);
        for (std::size_t r = 1; r < rowHeight.size(); ++r) {
            baseline[r] = baseline[r - 1] - gap - rowHeight[r];
        }
        x = 0.0;
        for (std::size_t i = 0; i < pieces.size(); ++i) {
            if (i > 0 && rowOf[i] != rowOf[i - 1]) {
                x = 0.0;
            }
            PatternPiece& piece = pieces[i];
            const auto [lo, hi] = pieceBounds(piece);
            transformPiece(piece, Placement{0.0, Vec2(x - lo.x, baseline[rowOf[i]] - lo.y)});
            piece.sheet = 0;
            piece.size = hi - lo;
            x += hi.x - lo.x + gap;
        }
        return pieces.empty() ? 0 : 1;
    }
    const double width = options.sheetSize.x;
    const double height = options.sheetSize.y;
    for (PatternPiece& piece : pieces) {
        if (options.allowRotation) {
            const double angle = materialSavingAngle(piece);
            transformPiece(piece, Placement{angle, Vec2()});
            piece.rotationDegrees = angle * 180.0 / kPi;
        }
    }
    // Largest first: by the longer side, then the shorter one.
    std::vector<std::size_t> order(pieces.size());
    std::iota(order.begin(), order.end(), 0);
    auto extent = [&pieces](std::size_t i) {
        return pieceBounds(pieces[i]).second - pieceBounds(pieces[i]).first;
    };
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
        const Vec2 ea = extent(a);
        const Vec2 eb = extent(b);
        const double la = std::max(ea.x, ea.y);
        const double lb = std::max(eb.x, eb.y);
        return la != lb ? la > lb : std::min(ea.x, ea.y) > std::min(eb.x, eb.y);
    });
    std::vector<Sheet> sheets;
    const Rect usable{gap, gap, width - gap, height - gap};
    for (std::size_t index : order) {
        PatternPiece& piece = pieces[index];
        const Vec2 size = extent(index);
        const double w = size.x + gap;
        const double h = size.y + gap;
        auto fits = [&](double rw, double rh) {
            return rw <= usable.w + kEpsilon && rh <= usable.h + kEpsilon;
        };
        const bool upright = fits(w, h);
        const bool turned = options.allowRotation && fits(h, w);
        if (!upright && !turned) {
            piece.sheet = -1;
            const auto [lo, hi] = pieceBounds(piece);
            transformPiece(piece, Placement{0.0, Vec2() - lo});
            piece.size = hi - lo;
            PatternProblem problem;
            problem.code = PatternProblemCode::PieceTooLarge;
            problem.surface = piece.surface;
            problem.surfaceName = surfaceNames[static_cast<std::size_t>(piece.surface)];
            problem.piece = static_cast<int>(index);
            problem.size = size;
            problem.sheetSize = Vec2(width, height);
            problem.gap = gap;
            problems.push_back(std::move(problem));
            continue;
        }
        Choice best;
        for (int attempt = 0; attempt < 2 && best.sheet < 0; ++attempt) {
            if (attempt == 1) {
                sheets.push_back(Sheet{{usable}});
            }
            for (std::size_t s = 0; s < sheets.size(); ++s) {
                for (const Rect& f : sheets[s].free) {
                    for (const bool turn : {false, true}) {
                        if ((turn && !turned) || (!turn && !upright)) {
                            continue;
                        }
                        const double rw = turn ? h : w;
                        const double rh = turn ? w : h;
                        if (rw > f.w + kEpsilon || rh > f.h + kEpsilon) {
                            continue;
                        }
                        const double shortSide = std::min(f.w - rw, f.h - rh);
                        const double longSide = std::max(f.w - rw, f.h - rh);
                        if (shortSide < best.shortSide ||
                            (shortSide == best.shortSide && longSide < best.longSide)) {
                            best = {
                                static_cast<int>(s), {f.x, f.y, rw, rh}, turn, shortSide, longSide};
                        }
                    }
                }
            }
        }
        sheets[static_cast<std::size_t>(best.sheet)].occupy(best.rect);
        if (best.turned) {
            transformPiece(piece, Placement{kPi / 2.0, Vec2()});
            piece.rotationDegrees = std::remainder(piece.rotationDegrees + 90.0, 360.0);
        }
        const auto [lo, hi] = pieceBounds(piece);
        transformPiece(piece, Placement{0.0, Vec2(best.rect.x, best.rect.y) - lo});
        piece.sheet = best.sheet;
        piece.size = hi - lo;
    }
    return static_cast<int>(sheets.size());
}

} // namespace devsurf::model::pattern
