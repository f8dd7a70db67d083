#include "pattern_overlaps.h"

#include "pattern_geometry.h"

#include <algorithm>
#include <cmath>
#include <map>

namespace devsurf::model::pattern {

namespace {

// The faces collected for an overlap stop at about this many: enough to name its patches.
constexpr std::size_t kNamedFaces = 64;

struct Segment {
    Vec2 a;
    Vec2 b;
    int owner = 0; // which piece (between pieces) or loop (within one)
    int index = 0; // position in its loop
    int loopSize = 0;
    double minX() const { return std::min(a.x, b.x); }
    double maxX() const { return std::max(a.x, b.x); }
};

void addLoop(std::vector<Segment>& segments, const std::vector<Vec2>& loop, int owner) {
    for (std::size_t i = 0; i < loop.size(); ++i) {
        segments.push_back({loop[i], loop[(i + 1) % loop.size()], owner, static_cast<int>(i),
                            static_cast<int>(loop.size())});
    }
}

bool neighbours(const Segment& s, const Segment& t) {
    if (s.owner != t.owner) {
        return false;
    }
    const int d = std::abs(s.index - t.index);
    return d <= 1 || d == s.loopSize - 1;
}

// Every crossing pair of segments, found by a sweep along x; sameOwner: pairs within one owner
// (else only pairs of different owners).
template <typename Visit>
void crossings(std::vector<Segment> segments, bool sameOwner, Visit visit) {
    std::sort(segments.begin(), segments.end(),
              [](const Segment& s, const Segment& t) { return s.minX() < t.minX(); });
    for (std::size_t i = 0; i < segments.size(); ++i) {
        const Segment& s = segments[i];
        for (std::size_t j = i + 1; j < segments.size() && segments[j].minX() <= s.maxX(); ++j) {
            const Segment& t = segments[j];
            if ((s.owner == t.owner) != sameOwner || (sameOwner && neighbours(s, t))) {
                continue;
            }
            if (std::max(s.a.y, s.b.y) < std::min(t.a.y, t.b.y) ||
                std::max(t.a.y, t.b.y) < std::min(s.a.y, s.b.y)) {
                continue;
            }
            if (segmentsIntersect(s.a, s.b, t.a, t.b) && !visit(s, t)) {
                return;
            }
        }
    }
}

// A surface developable up to rounding seldom closes up exactly around a hole or a closed
// strip, so its development, cut open there, may overlap itself at the cut by a hair: solved
// from noise, the annulus's cut opens or overlaps by some hundredths of a millimetre (the copies
// of its seam vertices 0.003 … 0.18 mm apart on a piece 720 mm across). Its outline then crosses
// itself where the two sides of the cut meet at angles whose sines are 1e-4 … 2e-3, and at the
// cut's ends, where a boundary curve and the other side of the cut touch within 0.075 mm of
// their ends. Such a crossing is not counted: one whose two segments can open an overlap of at
// most kNegligibleOverlap times the piece's size (the sine of their angle times the shorter
// length), or that lies within that distance of an end of both. A piece folded over onto itself
// crosses by 1 mm or more on the 424 mm fig8 example, where this allows 0.2 mm.
constexpr double kNegligibleOverlap = 5e-4;

bool negligibleCrossing(const Segment& s, const Segment& t, double size) {
    const Vec2 u = s.b - s.a;
    const Vec2 v = t.b - t.a;
    const double cross = u.x * v.y - u.y * v.x;
    const double lu = u.norm();
    const double lv = v.norm();
    const double allowed = kNegligibleOverlap * size;
    if (cross == 0.0 || !(lu > 0.0 && lv > 0.0) ||
        std::abs(cross) / (lu * lv) * std::min(lu, lv) < allowed) {
        return true; // parallel (touching end to end or along a line), or a hair's opening
    }
    const Vec2 w = t.a - s.a;
    const Vec2 x = s.a + u * ((w.x * v.y - w.y * v.x) / cross); // where the lines cross
    const auto nearEnd = [&x, allowed](const Segment& segment) {
        return std::min((x - segment.a).norm(), (x - segment.b).norm()) < allowed;
    };
    return nearEnd(s) && nearEnd(t);
}

bool insidePiece(const Vec2& p, const PatternPiece& piece) {
    if (!pointInPolygon(p, piece.outline)) {
        return false;
    }
    return std::none_of(piece.holes.begin(), piece.holes.end(),
                        [&p](const std::vector<Vec2>& hole) { return pointInPolygon(p, hole); });
}

// Mesh faces lying on top of other faces of the same piece: a face's centroid inside another
// face, farther than `margin` from its edges. The outline of a development that winds round
// more than once and lands exactly on itself (a band wound one and a half times, developed
// into a ring whose second half covers the first) runs along itself without crossing, which
// the sweep above cannot tell from a seam that closes up. Faces are binned in a grid of about
// their mean size, so each centroid meets only the faces near it. Appends the patches of both
// faces of every such pair to `faces`.
bool stackedFaces(const PatternPiece::Mesh& mesh, double margin, std::vector<FaceId>& faces) {
    const std::size_t count = mesh.faces.size();
    if (count < 2) {
        return false;
    }
    struct Face {
        std::vector<Vec2> polygon;
        Vec2 centroid;
        Vec2 lo{1e300, 1e300};
        Vec2 hi{-1e300, -1e300};
    };
    std::vector<Face> sampled(count);
    Vec2 lo{1e300, 1e300};
    double extent = 0.0;
    for (std::size_t f = 0; f < count; ++f) {
        Face& face = sampled[f];
        for (int v : mesh.faces[f]) {
            const Vec2& p = mesh.vertices[static_cast<std::size_t>(v)];
            face.polygon.push_back(p);
            face.centroid = face.centroid + p * (1.0 / static_cast<double>(mesh.faces[f].size()));
            face.lo = {std::min(face.lo.x, p.x), std::min(face.lo.y, p.y)};
            face.hi = {std::max(face.hi.x, p.x), std::max(face.hi.y, p.y)};
        }
        lo = {std::min(lo.x, face.lo.x), std::min(lo.y, face.lo.y)};
        extent += std::max(face.hi.x - face.lo.x, face.hi.y - face.lo.y);
    }
    const double cell = std::max(extent / static_cast<double>(count), 1e-9);
    const auto cellOf = [&](const Vec2& p) {
        return std::make_pair(static_cast<long long>((p.x - lo.x) / cell),
                              static_cast<long long>((p.y - lo.y) / cell));
    };
    std::map<std::pair<long long, long long>, std::vector<std::size_t>> grid;
    for (std::size_t f = 0; f < count; ++f) {
        const auto [i0, j0] = cellOf(sampled[f].lo);
        const auto [i1, j1] = cellOf(sampled[f].hi);
        for (long long i = i0; i <= i1; ++i) {
            for (long long j = j0; j <= j1; ++j) {
                grid[{i, j}].push_back(f);
            }
        }
    }
    bool found = false;
    for (std::size_t f = 0; f < count && faces.size() < kNamedFaces; ++f) {
        const Vec2& c = sampled[f].centroid;
        const auto near = grid.find(cellOf(c));
        if (near == grid.end()) {
            continue;
        }
        for (std::size_t g : near->second) {
            const std::vector<Vec2>& polygon = sampled[g].polygon;
            if (g == f || !pointInPolygon(c, polygon)) {
                continue;
            }
            double clearance = 1e300;
            for (std::size_t k = 0; k < polygon.size(); ++k) {
                clearance = std::min(
                    clearance, distanceToSegment(c, polygon[k], polygon[(k + 1) % polygon.size()]));
            }
            if (clearance > margin) {
                found = true;
                faces.push_back(mesh.faceOrigin[f]);
                faces.push_back(mesh.faceOrigin[g]);
                break;
            }
        }
    }
    return found;
}

} // namespace

bool selfOverlaps(const PatternPiece& piece, std::vector<FaceId>& faces) {
    std::vector<Segment> segments;
    addLoop(segments, piece.outline, 0);
    for (std::size_t h = 0; h < piece.holes.size(); ++h) {
        addLoop(segments, piece.holes[h], static_cast<int>(h) + 1);
    }
    // The patches at a point: those of the mesh faces with a vertex there (built at the first
    // crossing: most pieces have none).
    std::multimap<std::pair<double, double>, FaceId> facesAt;
    const auto [lo, hi] = pieceBounds(piece);
    const double size = (hi - lo).norm();
    bool found = false;
    auto record = [&](const Segment& s) {
        if (facesAt.empty()) {
            for (std::size_t f = 0; f < piece.mesh.faces.size(); ++f) {
                for (int v : piece.mesh.faces[f]) {
                    const Vec2& p = piece.mesh.vertices[static_cast<std::size_t>(v)];
                    facesAt.emplace(std::make_pair(p.x, p.y), piece.mesh.faceOrigin[f]);
                }
            }
        }
        for (const Vec2& p : {s.a, s.b}) {
            const auto range = facesAt.equal_range({p.x, p.y});
            for (auto it = range.first; it != range.second; ++it) {
                faces.push_back(it->second);
            }
        }
    };
    // Loops of one piece against each other too: owners differ there, so run both sweeps.
    for (const bool same : {true, false}) {
        crossings(segments, same, [&](const Segment& s, const Segment& t) {
            if (negligibleCrossing(s, t, size)) {
                return true;
            }
            found = true;
            record(s);
            record(t);
            return faces.size() < kNamedFaces;
        });
    }
    if (!found) {
        found = stackedFaces(piece.mesh, kNegligibleOverlap * size, faces);
    }
    std::sort(faces.begin(), faces.end());
    faces.erase(std::unique(faces.begin(), faces.end()), faces.end());
    return found;
}

bool piecesOverlap(const PatternPiece& a, const PatternPiece& b) {
    if (a.outline.empty() || b.outline.empty()) {
        return false;
    }
    const auto [loA, hiA] = pieceBounds(a);
    const auto [loB, hiB] = pieceBounds(b);
    if (hiA.x < loB.x || hiB.x < loA.x || hiA.y < loB.y || hiB.y < loA.y) {
        return false;
    }
    std::vector<Segment> segments;
    addLoop(segments, a.outline, 0);
    addLoop(segments, b.outline, 1);
    bool crossing = false;
    crossings(segments, false, [&crossing](const Segment&, const Segment&) {
        crossing = true;
        return false;
    });
    return crossing || insidePiece(a.outline.front(), b) || insidePiece(b.outline.front(), a);
}

std::vector<PatternOverlap> overlapsBetweenPieces(const std::vector<PatternPiece>& pieces) {
    std::vector<PatternOverlap> overlaps;
    for (std::size_t i = 0; i < pieces.size(); ++i) {
        for (std::size_t j = i + 1; j < pieces.size(); ++j) {
            if (pieces[i].sheet < 0 || pieces[i].sheet != pieces[j].sheet ||
                !piecesOverlap(pieces[i], pieces[j])) {
                continue;
            }
            PatternOverlap overlap;
            overlap.first = static_cast<int>(i);
            overlap.second = static_cast<int>(j);
            overlap.faces = pieces[i].faces;
            overlap.faces.insert(overlap.faces.end(), pieces[j].faces.begin(),
                                 pieces[j].faces.end());
            overlaps.push_back(std::move(overlap));
        }
    }
    return overlaps;
}

} // namespace devsurf::model::pattern
