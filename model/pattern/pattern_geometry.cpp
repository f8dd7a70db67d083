#include "pattern_geometry.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

namespace devsurf::model::pattern {

double signedArea(const std::vector<Vec2>& polygon) {
    double area = 0.0;
    for (std::size_t i = 0; i < polygon.size(); ++i) {
        area += cross2(polygon[i], polygon[(i + 1) % polygon.size()]);
    }
    return 0.5 * area;
}

bool pointInPolygon(const Vec2& p, const std::vector<Vec2>& polygon) {
    bool inside = false;
    for (std::size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++) {
        const Vec2& a = polygon[i];
        const Vec2& b = polygon[j];
        if ((a.y > p.y) != (b.y > p.y) && p.x < (b.x - a.x) * (p.y - a.y) / (b.y - a.y) + a.x) {
            inside = !inside;
        }
    }
    return inside;
}

double distanceToSegment(const Vec2& p, const Vec2& a, const Vec2& b) {
    const Vec2 d = b - a;
    const double length2 = dot2(d, d);
    const double t = length2 > 0.0 ? std::clamp(dot2(p - a, d) / length2, 0.0, 1.0) : 0.0;
    return (p - (a + d * t)).norm();
}

std::vector<Vec2> convexHull(std::vector<Vec2> points) {
    // Andrew's monotone chain.
    std::sort(points.begin(), points.end(),
              [](const Vec2& a, const Vec2& b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
    points.erase(std::unique(points.begin(), points.end()), points.end());
    if (points.size() < 3) {
        return points;
    }
    std::vector<Vec2> hull(2 * points.size());
    std::size_t k = 0;
    for (std::size_t i = 0; i < points.size(); ++i) {
        while (k >= 2 && cross2(hull[k - 1] - hull[k - 2], points[i] - hull[k - 2]) <= 0) {
            --k;
        }
        hull[k++] = points[i];
    }
    for (std::size_t i = points.size() - 1, lower = k + 1; i > 0; --i) {
        while (k >= lower && cross2(hull[k - 1] - hull[k - 2], points[i - 1] - hull[k - 2]) <= 0) {
            --k;
        }
        hull[k++] = points[i - 1];
    }
    hull.resize(k - 1);
    return hull;
}

Vec2 Placement::apply(const Vec2& p) const {
    const double c = std::cos(angle);
    const double s = std::sin(angle);
    return Vec2(c * p.x - s * p.y + shift.x, s * p.x + c * p.y + shift.y);
}

void transformPiece(PatternPiece& piece, const Placement& placement) {
    auto move = [&placement](std::vector<Vec2>& points) {
        for (Vec2& p : points) {
            p = placement.apply(p);
        }
    };
    move(piece.outline);
    for (auto& hole : piece.holes) {
        move(hole);
    }
    for (auto& path : piece.paths) {
        move(path.points);
    }
    for (auto& path : piece.edgeCurves) {
        move(path.points);
    }
    move(piece.mesh.vertices);
    for (auto& [id, p] : piece.vertices) {
        p = placement.apply(p);
    }
    for (auto& segment : piece.rulingSegments) {
        segment[0] = placement.apply(segment[0]);
        segment[1] = placement.apply(segment[1]);
    }
    const double degrees = placement.angle * 180.0 / 3.14159265358979323846;
    for (auto& label : piece.labels) {
        label.position = placement.apply(label.position);
        label.angleDegrees = std::remainder(label.angleDegrees + degrees, 360.0);
    }
}

std::pair<Vec2, Vec2> pieceBounds(const PatternPiece& piece) {
    const double inf = std::numeric_limits<double>::infinity();
    Vec2 lo(inf, inf);
    Vec2 hi(-inf, -inf);
    auto extend = [&](const std::vector<Vec2>& points) {
        for (const Vec2& p : points) {
            lo = Vec2(std::min(lo.x, p.x), std::min(lo.y, p.y));
            hi = Vec2(std::max(hi.x, p.x), std::max(hi.y, p.y));
        }
    };
    extend(piece.outline);
    for (const auto& hole : piece.holes) {
        extend(hole);
    }
    if (!std::isfinite(lo.x)) {
        return {Vec2(), Vec2()};
    }
    return {lo, hi};
}

std::vector<std::vector<int>> boundaryLoops(const std::vector<std::vector<int>>& faces) {
    std::map<std::pair<int, int>, int> uses;
    for (const auto& face : faces) {
        for (std::size_t k = 0; k < face.size(); ++k) {
            const int a = face[k];
            const int b = face[(k + 1) % face.size()];
            ++uses[{std::min(a, b), std::max(a, b)}];
        }
    }
    std::multimap<int, int> next;
    for (const auto& face : faces) {
        for (std::size_t k = 0; k < face.size(); ++k) {
            const int a = face[k];
            const int b = face[(k + 1) % face.size()];
            if (uses[{std::min(a, b), std::max(a, b)}] == 1) {
                next.emplace(a, b);
            }
        }
    }
    std::vector<std::vector<int>> loops;
    while (!next.empty()) {
        const int start = next.begin()->first;
        std::vector<int> loop{start};
        int current = start;
        while (true) {
            const auto it = next.find(current);
            if (it == next.end()) {
                break;
            }
            current = it->second;
            next.erase(it);
            if (current == start) {
                break;
            }
            loop.push_back(current);
        }
        if (loop.size() >= 3) {
            loops.push_back(std::move(loop));
        }
    }
    return loops;
}

} // namespace devsurf::model::pattern
