#include "pattern_seams.h"

#include "pattern_geometry.h"
#include "pattern_labels.h"

// At -O1 (the sanitizer builds) GCC 12 warns of maybe-uninitialised points inside
// Boost.Geometry's buffer strategies, a false positive in its headers.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#include <boost/geometry.hpp>
#pragma GCC diagnostic pop

#include <algorithm>
#include <cmath>

namespace devsurf::model::pattern {

namespace {

// A mitred corner of the offset reaches at most this many widths from its polyline corner.
constexpr double kMitreLimit = 4.0;

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

std::vector<double> arcLengths(const std::vector<Vec2>& points) {
    std::vector<double> lengths{0.0};
    for (std::size_t i = 0; i + 1 < points.size(); ++i) {
        lengths.push_back(lengths.back() + (points[i + 1] - points[i]).norm());
    }
    return lengths;
}

// What replaces a run of the outline, its two end points included.
std::vector<Vec2> replacement(const std::vector<Vec2>& run, const PatternOptions& options) {
    const double width = options.seamAllowance;
    const std::vector<Vec2> offset = offsetPolyline(run, width);
    std::vector<Vec2> result{run.front()};
    if (offset.size() < 2) {
        // Nothing to offset (a run of one point): the outline stays.
    } else if (!options.glueTabs) {
        result.insert(result.end(), offset.begin(), offset.end());
    } else {
        const double total = arcLengths(run).back();
        const std::vector<double> lengths = arcLengths(offset);
        const double offsetTotal = lengths.back();
        // Sides at 45° where the seam is long enough, steeper on short seams.
        const double inset = std::min({width, 0.25 * total, 0.5 * offsetTotal});
        result.push_back(atLength(offset, lengths, inset));
        for (std::size_t i = 1; i + 1 < offset.size(); ++i) {
            if (lengths[i] > inset && lengths[i] < offsetTotal - inset) {
                result.push_back(offset[i]);
            }
        }
        result.push_back(atLength(offset, lengths, offsetTotal - inset));
    }
    result.push_back(run.back());
    return result;
}

} // namespace

std::vector<Vec2> offsetPolyline(const std::vector<Vec2>& points, double width) {
    namespace bg = boost::geometry;
    using Point = bg::model::d2::point_xy<double>;
    bg::model::linestring<Point> line;
    for (const Vec2& p : points) {
        if (line.empty() || !(p == Vec2(bg::get<0>(line.back()), bg::get<1>(line.back())))) {
            line.emplace_back(p.x, p.y);
        }
    }
    const double distance = std::abs(width);
    if (line.size() < 2 || !(distance > 0.0)) {
        return {};
    }
    // The one-sided buffer: the area between the polyline and its offset, bounded by the
    // polyline on one side (distance 0) and the offset on the other.
    bg::model::multi_polygon<bg::model::polygon<Point>> area;
    const bg::strategy::buffer::distance_asymmetric<double> sides(width < 0.0 ? distance : 0.0,
                                                                  width < 0.0 ? 0.0 : distance);
    bg::buffer(line, area, sides, bg::strategy::buffer::side_straight(),
               bg::strategy::buffer::join_miter(kMitreLimit), bg::strategy::buffer::end_flat(),
               bg::strategy::buffer::point_square());
    if (area.empty()) {
        return {};
    }
    const auto& largest =
        *std::max_element(area.begin(), area.end(),
                          [](const auto& a, const auto& b) { return bg::area(a) < bg::area(b); });
    // Its boundary runs along the polyline and back along the offset: the offset is the part
    // of the closed ring away from the polyline, from the ring's first point on the polyline.
    std::vector<Point> ring(largest.outer().begin(), largest.outer().end() - 1);
    std::vector<bool> far(ring.size());
    for (std::size_t i = 0; i < ring.size(); ++i) {
        far[i] = bg::distance(ring[i], line) > 0.5 * distance;
    }
    const auto near = std::find(far.begin(), far.end(), false);
    if (near == far.end()) {
        return {};
    }
    const std::size_t start = static_cast<std::size_t>(near - far.begin());
    std::vector<Vec2> offset;
    for (std::size_t k = 0; k < ring.size(); ++k) {
        const std::size_t i = (start + k) % ring.size();
        const Vec2 p(bg::get<0>(ring[i]), bg::get<1>(ring[i]));
        if (far[i] && (offset.empty() || !(offset.back() == p))) {
            offset.push_back(p);
        }
    }
    // The buffer adds points along straight sides (where its pieces were joined): drop those
    // between collinear neighbours.
    std::vector<Vec2> corners;
    for (std::size_t i = 0; i < offset.size(); ++i) {
        if (i > 0 && i + 1 < offset.size()) {
            const Vec2 u = offset[i] - corners.back();
            const Vec2 v = offset[i + 1] - offset[i];
            if (std::abs(cross2(u, v)) <= 1e-12 * u.norm() * v.norm() && dot2(u, v) > 0.0) {
                continue;
            }
        }
        corners.push_back(offset[i]);
    }
    offset = std::move(corners);
    if (offset.size() >= 2 &&
        (offset.front() - points.front()).norm() > (offset.back() - points.front()).norm()) {
        std::reverse(offset.begin(), offset.end());
    }
    return offset;
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
