#include "pattern_overlaps.h"

#include "pattern_geometry.h"

#include <algorithm>
#include <map>

namespace devsurf::model::pattern {

namespace {

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

bool insidePiece(const Vec2& p, const PatternPiece& piece) {
    if (!pointInPolygon(p, piece.outline)) {
        return false;
    }
    return std::none_of(piece.holes.begin(), piece.holes.end(),
                        [&p](const std::vector<Vec2>& hole) { return pointInPolygon(p, hole); });
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
            found = true;
            record(s);
            record(t);
            return faces.size() < 64; // enough to name the patches
        });
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
