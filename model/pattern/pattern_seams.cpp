#include "pattern_seams.h"

#include "pattern_geometry.h"
#include "pattern_labels.h"

#include <algorithm>
#include <cmath>
#include <optional>

namespace devsurf::model::pattern {

namespace {

Vec2 rightNormal(const Vec2& from, const Vec2& to) {
    const Vec2 d = to - from;
    const double length = d.norm();
    return length > 0.0 ? Vec2(d.y / length, -d.x / length) : Vec2();
}

// The point at arc length s along a polyline whose vertex arc lengths are given.
Vec2 atLength(const std::vector<Vec2>& points, const std::vector<double>& lengths, double s) {
    for (std::size_t i = 0; i + 1 < points.size(); ++i) {
        if (s <= lengths[i + 1] || i + 2 == points.size()) {
            const double span = lengths[i + 1] - lengths[i];
            const double t = span > 0.0 ? std::clamp((s - lengths[i]) / span, 0.0, 1.0) : 0.0;
            return points[i] + (points[i + 1] - points[i]) * t;
        }
    }
    return points.back();
}

// What replaces a run of the outline, its two end points included.
std::vector<Vec2> replacement(const std::vector<Vec2>& run, const PatternOptions& options) {
    const double width = options.seamAllowance;
    const std::vector<Vec2> offset = offsetPolyline(run, width);
    std::vector<Vec2> result{run.front()};
    if (!options.glueTabs) {
        result.insert(result.end(), offset.begin(), offset.end());
    } else {
        std::vector<double> lengths{0.0};
        for (std::size_t i = 0; i + 1 < run.size(); ++i) {
            lengths.push_back(lengths.back() + (run[i + 1] - run[i]).norm());
        }
        const double total = lengths.back();
        // Sides at 45° where the seam is long enough, steeper on short seams.
        const double inset = std::min(width, 0.25 * total);
        result.push_back(atLength(offset, lengths, inset));
        for (std::size_t i = 1; i + 1 < run.size(); ++i) {
            if (lengths[i] > inset && lengths[i] < total - inset) {
                result.push_back(offset[i]);
            }
        }
        result.push_back(atLength(offset, lengths, total - inset));
    }
    result.push_back(run.back());
    return result;
}

} // namespace

std::vector<Vec2> offsetPolyline(const std::vector<Vec2>& points, double width) {
    std::vector<Vec2> result;
    const std::size_t n = points.size();
    for (std::size_t i = 0; i < n; ++i) {
        const std::optional<Vec2> before =
            i > 0 ? std::optional<Vec2>(rightNormal(points[i - 1], points[i])) : std::nullopt;
        const std::optional<Vec2> after =
            i + 1 < n ? std::optional<Vec2>(rightNormal(points[i], points[i + 1])) : std::nullopt;
        Vec2 normal = before ? *before : (after ? *after : Vec2());
        if (before && after) {
            const Vec2 sum = *before + *after;
            const double length = sum.norm();
            // A mitre keeps both neighbouring segments at the full width; it is capped so that a
            // sharp corner does not shoot out.
            if (length > 1e-12) {
                normal = sum * (1.0 / length);
                normal = normal * (1.0 / std::max(0.25, dot2(normal, *after)));
            }
        }
        result.push_back(points[i] + normal * width);
    }
    return result;
}

void addSeamAllowances(PieceBuild& build, const PatternOptions& options) {
    PatternPiece& piece = build.piece;
    const int n = static_cast<int>(piece.outline.size());
    if (options.seamAllowance <= 0.0 || n < 3) {
        return;
    }
    std::vector<SeamRun> runs;
    for (const SeamRun& run : build.seams) {
        if (run.primary) {
            runs.push_back(run);
        }
    }
    std::sort(runs.begin(), runs.end(),
              [](const SeamRun& a, const SeamRun& b) { return a.first < b.first; });
    if (!options.glueTabs) {
        // One continuous strip along consecutive seam edges.
        bool merged = true;
        while (merged && runs.size() > 1) {
            merged = false;
            for (std::size_t i = 0; i < runs.size() && !merged; ++i) {
                for (std::size_t j = 0; j < runs.size() && !merged; ++j) {
                    if (i != j && runs[i].last == runs[j].first && runs[j].last != runs[i].first) {
                        runs[i].last = runs[j].last;
                        runs.erase(runs.begin() + static_cast<std::ptrdiff_t>(j));
                        merged = true;
                    }
                }
            }
        }
    }
    if (runs.empty()) {
        return;
    }
    // Outline indices strictly inside a run are replaced; start the walk outside every run.
    std::vector<char> inside(static_cast<std::size_t>(n), 0);
    for (const SeamRun& run : runs) {
        for (int i = (run.first + 1) % n; i != run.last; i = (i + 1) % n) {
            inside[static_cast<std::size_t>(i)] = 1;
        }
    }
    int start = -1;
    for (int i = 0; i < n && start < 0; ++i) {
        const bool runStart =
            std::any_of(runs.begin(), runs.end(), [i](const SeamRun& r) { return r.first == i; });
        if (!inside[static_cast<std::size_t>(i)] && !runStart) {
            start = i;
        }
    }
    if (start < 0) {
        return; // the whole outline is one seam: nothing sensible to add
    }
    std::vector<Vec2> outline;
    for (int k = 0; k < n;) {
        const int i = (start + k) % n;
        const auto run =
            std::find_if(runs.begin(), runs.end(), [i](const SeamRun& r) { return r.first == i; });
        if (run == runs.end()) {
            outline.push_back(piece.outline[static_cast<std::size_t>(i)]);
            ++k;
            continue;
        }
        const std::vector<Vec2> original = runPoints(piece, *run);
        std::vector<Vec2> added = replacement(original, options);
        // A run that starts where the previous one ended shares that point.
        if (!outline.empty() && outline.back() == added.front()) {
            added.erase(added.begin());
        }
        added.pop_back(); // the run's last point is emitted by whatever follows it
        outline.insert(outline.end(), added.begin(), added.end());
        PatternPath seam;
        seam.layer = PatternLayer::Seam;
        seam.points = original;
        seam.edge = run->edge;
        piece.paths.push_back(std::move(seam));
        k += (run->last - run->first + n) % n;
    }
    for (PatternPath& path : piece.paths) {
        if (path.layer == PatternLayer::Cut && path.closed && path.points == piece.outline) {
            path.points = outline;
        }
    }
    piece.outline = std::move(outline);
}

} // namespace devsurf::model::pattern
