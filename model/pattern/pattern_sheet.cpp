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
