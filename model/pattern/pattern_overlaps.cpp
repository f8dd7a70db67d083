#include "pattern_overlaps.h"

#include "pattern_geometry.h"

#include <boost/geometry.hpp>
#include <boost/geometry/index/rtree.hpp>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <map>

namespace devsurf::model::pattern {

namespace {

namespace bg = boost::geometry;
namespace bgi = boost::geometry::index;
using BgPoint = bg::model::d2::point_xy<double>;
using BgSegment = bg::model::segment<BgPoint>;
using BgBox = bg::model::box<BgPoint>;
using BgPolygon = bg::model::polygon<BgPoint, false, false>; // counter-clockwise, open

// The faces collected for an overlap stop at about this many: enough to name its patches.
constexpr std::size_t kNamedFaces = 64;

struct Segment {
    Vec2 a;
    Vec2 b;
    int owner = 0; // which piece (between pieces) or loop (within one)
    int index = 0; // position in its loop
    int loopSize = 0;
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

BgPoint toBg(const Vec2& p) {
    return {p.x, p.y};
}

BgSegment toBg(const Segment& s) {
    return {toBg(s.a), toBg(s.b)};
}

// Every crossing pair of segments (in the order of the list), found through an R-tree of their
// bounding boxes; sameOwner: pairs within one owner (else only pairs of different owners).
// Stops when visit returns false.
template <typename Visit>
void crossings(const std::vector<Segment>& segments, bool sameOwner, Visit visit) {
    using Entry = std::pair<BgBox, std::size_t>;
    std::vector<Entry> boxes;
    boxes.reserve(segments.size());
    for (std::size_t i = 0; i < segments.size(); ++i) {
        boxes.emplace_back(bg::return_envelope<BgBox>(toBg(segments[i])), i);
    }
    const bgi::rtree<Entry, bgi::rstar<16>> tree(boxes.begin(), boxes.end());
    std::vector<Entry> near;
    for (std::size_t i = 0; i < segments.size(); ++i) {
        const Segment& s = segments[i];
        near.clear();
        tree.query(bgi::intersects(boxes[i].first), std::back_inserter(near));
        std::sort(near.begin(), near.end(),
                  [](const Entry& x, const Entry& y) { return x.second < y.second; });
        for (const Entry& entry : near) {
            if (entry.second <= i) {
                continue;
            }
            const Segment& t = segments[entry.second];
            if ((s.owner == t.owner) != sameOwner || (sameOwner && neighbours(s, t))) {
                continue;
            }
            if (bg::intersects(toBg(s), toBg(t)) && !visit(s, t)) {
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

// The piece's area: its outline with its holes.
BgPolygon polygonOf(const PatternPiece& piece) {
    BgPolygon polygon;
    for (const Vec2& p : piece.outline) {
        polygon.outer().push_back(toBg(p));
    }
    for (const std::vector<Vec2>& hole : piece.holes) {
        polygon.inners().emplace_back();
        for (const Vec2& p : hole) {
            polygon.inners().back().push_back(toBg(p));
        }
    }
    bg::correct(polygon); // orientation of the outline and the holes as Boost.Geometry wants
    return polygon;
}

// Mesh faces lying on top of other faces of the same piece: a face's centroid inside another
// face, farther than `margin` from its edges. The outline of a development that winds round
// more than once and lands exactly on itself (a band wound one and a half times, developed
// into a ring whose second half covers the first) runs along itself without crossing, which
// the crossing test above cannot tell from a seam that closes up. An R-tree of the faces' boxes
// gives each centroid only the faces near it. Appends the patches of both faces of every such
// pair to `faces`.
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
    for (std::size_t f = 0; f < count; ++f) {
        Face& face = sampled[f];
        for (int v : mesh.faces[f]) {
            const Vec2& p = mesh.vertices[static_cast<std::size_t>(v)];
            face.polygon.push_back(p);
            face.centroid = face.centroid + p * (1.0 / static_cast<double>(mesh.faces[f].size()));
            face.lo = {std::min(face.lo.x, p.x), std::min(face.lo.y, p.y)};
            face.hi = {std::max(face.hi.x, p.x), std::max(face.hi.y, p.y)};
        }
    }
    using Entry = std::pair<BgBox, std::size_t>;
    std::vector<Entry> boxes;
    boxes.reserve(count);
    for (std::size_t f = 0; f < count; ++f) {
        boxes.emplace_back(BgBox(toBg(sampled[f].lo), toBg(sampled[f].hi)), f);
    }
    const bgi::rtree<Entry, bgi::rstar<16>> tree(boxes.begin(), boxes.end());
    std::vector<Entry> near;
    bool found = false;
    for (std::size_t f = 0; f < count && faces.size() < kNamedFaces; ++f) {
        const Vec2& c = sampled[f].centroid;
        near.clear();
        tree.query(bgi::intersects(toBg(c)), std::back_inserter(near));
        std::sort(near.begin(), near.end(),
                  [](const Entry& x, const Entry& y) { return x.second < y.second; });
        for (const Entry& entry : near) {
            const std::size_t g = entry.second;
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
    // Touching counts, as a shared cut would cut both pieces.
    return bg::intersects(polygonOf(a), polygonOf(b));
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
