#include "pattern_sheet.h"

#include "model/derived_geometry.h"
#include "model/math_constants.h"
#include "model/pattern/pattern_geometry.h"
#include "model/sheet_creases.h"
#include "model/sheet_domain.h"

#include <algorithm>
#include <cmath>
#include <map>

namespace devsurf::model::pattern {

Vec2 PlaneMotion::apply(const Vec2& p) const {
    const Vec2 q = (mirrored ? Vec2{-p.x, p.y} : p) - from;
    const double c = std::cos(angle), s = std::sin(angle);
    return Vec2{c * q.x - s * q.y, s * q.x + c * q.y} + to;
}

Vec2 PlaneMotion::applyInverse(const Vec2& p) const {
    const Vec2 q = p - to;
    const double c = std::cos(angle), s = std::sin(angle);
    const Vec2 r = Vec2{c * q.x + s * q.y, -s * q.x + c * q.y} + from;
    return mirrored ? Vec2{-r.x, r.y} : r;
}

static std::pair<PlaneMotion, double>
fitPlaneMotionMirrored(std::vector<Vec2> source, const std::vector<Vec2>& target, bool mirrored) {
    if (mirrored) {
        for (Vec2& p : source) {
            p.x = -p.x;
        }
    }
    Vec2 cs, ct;
    for (std::size_t i = 0; i < source.size(); ++i) {
        cs = cs + source[i];
        ct = ct + target[i];
    }
    const double n = static_cast<double>(source.size());
    cs = cs * (1.0 / n);
    ct = ct * (1.0 / n);
    double a = 0.0, b = 0.0;
    for (std::size_t i = 0; i < source.size(); ++i) {
        const Vec2 s = source[i] - cs, t = target[i] - ct;
        a += dot2(s, t);
        b += cross2(s, t);
    }
    PlaneMotion motion;
    motion.angle = std::atan2(b, a);
    motion.to = ct;
    // `from` is in mirrored coordinates, as apply() mirrors before subtracting it; the
    // residual is measured on the already mirrored source, so without a second mirror.
    motion.from = cs;
    double squared = 0.0;
    for (std::size_t i = 0; i < source.size(); ++i) {
        const Vec2 d = motion.apply(source[i]) - target[i];
        squared += dot2(d, d);
    }
    motion.mirrored = mirrored;
    return {motion, squared};
}

std::optional<PlaneMotion> fitPlaneMotion(const std::vector<Vec2>& from,
                                          const std::vector<Vec2>& to) {
    if (from.size() != to.size() || from.size() < 2) {
        return std::nullopt;
    }
    const auto straight = fitPlaneMotionMirrored(from, to, false);
    const auto mirrored = fitPlaneMotionMirrored(from, to, true);
    return mirrored.second < straight.second ? mirrored.first : straight.first;
}

namespace {

std::vector<Vec2> circlePolygon(const Vec2& centre, double radius, double chordTolerance) {
    const double tolerance = std::clamp(chordTolerance, 1e-6, radius);
    const double step = 2.0 * std::acos(std::max(-1.0, 1.0 - tolerance / radius));
    const int n =
        std::clamp(static_cast<int>(std::ceil(2.0 * kPi / std::max(step, 1e-9))), 32, 1440);
    std::vector<Vec2> polygon;
    for (int i = 0; i < n; ++i) {
        const double t = 2.0 * kPi * i / n;
        polygon.push_back(centre + Vec2{radius * std::cos(t), radius * std::sin(t)});
    }
    return polygon;
}

// The rigid motion from the kept development's plane to `piece`'s (see sheetOnPiece).
std::optional<PlaneMotion> sheetMotion(const CompositeSurface& surface, const PatternPiece& piece) {
    const SheetDomain& domain = surface.sheetDomain();
    if (!surface.keepsDevelopment() || domain.isFree() || surface.development().empty() ||
        domainProblem(domain)) {
        return std::nullopt;
    }
    const auto derived = DerivedGeometry::of(surface, kDevelopmentSamplesPerInterval);
    const SampledMesh& mesh = derived->mesh();
    const std::vector<Vec2>& development = surface.development();
    if (development.size() != mesh.vertices.size()) {
        return std::nullopt; // stale: the next solve derives it again
    }
    // Vertices the piece shows once (a vertex on a cut-open seam shows twice: ambiguous).
    std::map<VertexId, int> shown;
    for (const auto& [id, position] : piece.vertices) {
        ++shown[id];
    }
    std::map<VertexId, Vec2> placed;
    for (const auto& [id, position] : piece.vertices) {
        if (shown[id] == 1) {
            placed[id] = position;
        }
    }
    std::vector<Vec2> source, target;
    for (std::size_t i = 0; i < mesh.coarseVertexIds.size(); ++i) {
        if (auto it = placed.find(mesh.coarseVertexIds[i]); it != placed.end()) {
            source.push_back(development[i]);
            target.push_back(it->second);
        }
    }
    return fitPlaneMotion(source, target);
}

} // namespace

std::vector<std::vector<Vec2>> sheetOnPiece(const CompositeSurface& surface,
                                            const PatternPiece& piece, double chordTolerance) {
    const std::optional<PlaneMotion> fitted = sheetMotion(surface, piece);
    if (!fitted) {
        return {};
    }
    const PlaneMotion& motion = *fitted;
    const SheetDomain& domain = surface.sheetDomain();

    std::vector<std::vector<Vec2>> loops;
    for (const DomainLoop& loop : domainLoops(domain)) {
        std::vector<Vec2> polygon =
            loop.circle ? circlePolygon(loop.centre, loop.radius, chordTolerance) : loop.polygon;
        for (Vec2& p : polygon) {
            p = motion.apply(p);
        }
        if (loop.outer) {
            loops.insert(loops.begin(), std::move(polygon));
        } else {
            loops.push_back(std::move(polygon));
        }
    }
    return loops;
}

std::vector<std::vector<Vec2>> creaseCurvesOnPiece(const CompositeSurface& surface,
                                                   const PatternPiece& piece) {
    const std::optional<PlaneMotion> fitted = sheetMotion(surface, piece);
    if (!fitted) {
        return {};
    }
    std::vector<std::vector<Vec2>> curves;
    for (const DomainLoop& curve : creaseCurveLoops(surface.sheetDomain())) {
        std::vector<Vec2> points;
        for (const Vec2& p : curve.polygon) {
            points.push_back(fitted->apply(p));
        }
        if (!curve.open && !points.empty()) {
            points.push_back(points.front());
        }
        curves.push_back(std::move(points));
    }
    return curves;
}

} // namespace devsurf::model::pattern
