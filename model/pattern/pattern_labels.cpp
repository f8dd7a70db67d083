#include "pattern_labels.h"

#include "pattern_geometry.h"

#include <algorithm>
#include <cmath>
#include <map>

namespace devsurf::model::pattern {

namespace {

constexpr double kDegreesPerRadian = 57.295779513082320876798;
constexpr double kLabelHeight = 5.0; // mm, the largest text drawn

} // namespace

std::vector<Vec2> runPoints(const PatternPiece& piece, const SeamRun& run) {
    std::vector<Vec2> points;
    const int n = static_cast<int>(piece.outline.size());
    if (n == 0) {
        return points;
    }
    for (int i = run.first;; i = (i + 1) % n) {
        points.push_back(piece.outline[static_cast<std::size_t>(i)]);
        if (i == run.last || static_cast<int>(points.size()) > n) {
            break;
        }
    }
    return points;
}

void choosePrimarySides(PieceBuild& build) {
    auto& runs = build.seams;
    std::sort(runs.begin(), runs.end(),
              [](const SeamRun& a, const SeamRun& b) { return a.first < b.first; });
    // Chains of runs that follow each other along the outline.
    std::vector<int> chain(runs.size(), -1);
    int chains = 0;
    for (std::size_t i = 0; i < runs.size(); ++i) {
        if (chain[i] >= 0) {
            continue;
        }
        chain[i] = chains;
        for (std::size_t current = i;;) {
            std::size_t next = runs.size();
            for (std::size_t j = 0; j < runs.size(); ++j) {
                if (chain[j] < 0 && runs[j].first == runs[current].last) {
                    next = j;
                }
            }
            if (next == runs.size()) {
                break;
            }
            chain[next] = chains;
            current = next;
        }
        // Chains are also followed backwards (a chain may wrap past the outline's start).
        for (std::size_t current = i;;) {
            std::size_t previous = runs.size();
            for (std::size_t j = 0; j < runs.size(); ++j) {
                if (chain[j] < 0 && runs[j].last == runs[current].first) {
                    previous = j;
                }
            }
            if (previous == runs.size()) {
                break;
            }
            chain[previous] = chains;
            current = previous;
        }
        ++chains;
    }
    // For each seam, the side in the chain seen first gets the allowance; so does every seam of
    // that chain that is still undecided.
    std::map<int, bool> decided;
    for (std::size_t i = 0; i < runs.size(); ++i) {
        if (decided.count(runs[i].seam) != 0) {
            continue;
        }
        for (std::size_t j = 0; j < runs.size(); ++j) {
            if (chain[j] == chain[i] && decided.count(runs[j].seam) == 0) {
                decided[runs[j].seam] = true;
                for (std::size_t k = 0; k < runs.size(); ++k) {
                    if (runs[k].seam == runs[j].seam) {
                        runs[k].primary = k == j;
                    }
                }
            }
        }
    }
}

void addPieceLabel(PatternPiece& piece) {
    if (piece.outline.empty()) {
        return;
    }
    const auto [lo, hi] = pieceBounds(piece);
    const double height = std::min(kLabelHeight, 0.2 * std::min(hi.x - lo.x, hi.y - lo.y));
    // The outline's centroid if it lies inside the piece, else the middle of its largest face.
    Vec2 centroid;
    double area = 0.0;
    for (std::size_t i = 0; i < piece.outline.size(); ++i) {
        const Vec2& a = piece.outline[i];
        const Vec2& b = piece.outline[(i + 1) % piece.outline.size()];
        const double w = cross2(a, b);
        centroid = centroid + (a + b) * w;
        area += w;
    }
    bool inside = std::abs(area) > 0.0;
    if (inside) {
        centroid = centroid * (1.0 / (3.0 * area));
        inside = pointInPolygon(centroid, piece.outline);
        for (const auto& hole : piece.holes) {
            inside = inside && !pointInPolygon(centroid, hole);
        }
    }
    if (!inside) {
        double largest = -1.0;
        for (const auto& face : piece.mesh.faces) {
            std::vector<Vec2> polygon;
            Vec2 middle;
            for (int v : face) {
                polygon.push_back(piece.mesh.vertices[static_cast<std::size_t>(v)]);
                middle = middle + polygon.back() * (1.0 / static_cast<double>(face.size()));
            }
            const double faceArea = std::abs(signedArea(polygon));
            if (faceArea > largest) {
                largest = faceArea;
                centroid = middle;
            }
        }
    }
    PatternLabel label;
    label.text = piece.name;
    label.height = height;
    label.position = centroid - Vec2(0.0, 0.5 * height);
    piece.labels.push_back(label);
}

void addSeamLabels(PieceBuild& build) {
    PatternPiece& piece = build.piece;
    for (const SeamRun& run : build.seams) {
        const std::vector<Vec2> points = runPoints(piece, run);
        double length = 0.0;
        for (std::size_t i = 0; i + 1 < points.size(); ++i) {
            length += (points[i + 1] - points[i]).norm();
        }
        if (length <= 0.0) {
            continue;
        }
        // The middle of the run and its direction there.
        double walked = 0.0;
        Vec2 middle = points.front();
        Vec2 direction(1.0, 0.0);
        for (std::size_t i = 0; i + 1 < points.size(); ++i) {
            const Vec2 d = points[i + 1] - points[i];
            const double step = d.norm();
            if (step > 0.0 && walked + step >= 0.5 * length) {
                direction = d * (1.0 / step);
                middle = points[i] + direction * (0.5 * length - walked);
                break;
            }
            walked += step;
        }
        const double height = std::min(kLabelHeight, 0.3 * length);
        // The outline runs counter-clockwise: the piece lies on the left.
        const Vec2 inward(-direction.y, direction.x);
        double angle = std::atan2(direction.y, direction.x) * kDegreesPerRadian;
        double offset = 0.3 * height; // baseline near the edge, text towards the inside
        if (angle > 90.0 || angle <= -90.0) {
            angle = std::remainder(angle + 180.0, 360.0); // keep the text upright
            offset = 1.3 * height;                        // its top is now near the edge
        }
        PatternLabel label;
        label.text = piece.name + std::to_string(run.seam);
        label.height = height;
        label.angleDegrees = angle;
        label.position = middle + inward * offset;
        piece.labels.push_back(label);
    }
}

} // namespace devsurf::model::pattern
