#include "crease_quality.h"
#include "model/derived_geometry.h"

#include "model/bspline_curve.h"
#include "model/creases.h"
#include "model/sampled_mesh.h"
#include "model/strip.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace devsurf::solver {

namespace {

// The unit normal a′ × (b − a) of one side's strip at crease parameter u, oriented to the
// surface's normal side.
model::Vec3 unitNormal(const model::Strip& strip, const model::CreaseSide& side, double u) {
    const double s = side.reversed ? 1.0 - u : u;
    model::Vec3 n = cross(strip.a.derivative(s, 1), strip.bPoint(s) - strip.aPoint(s));
    const double length = n.norm();
    if (length <= 0.0) {
        return n;
    }
    return n * ((side.flipNormal ? -1.0 : 1.0) / length);
}

// |⟨d, n⟩| / (|d| |n|); 0 if d is below `tiny` (a straight piece of curve, where the
// direction of d is rounding noise) or n vanishes.
double normalisedProduct(const model::Vec3& d, const model::Vec3& n, double tiny) {
    const double scale = d.norm() * n.norm();
    return d.norm() > tiny && n.norm() > 1e-12 ? std::abs(dot(d, n)) / scale : 0.0;
}

// The largest and the summed residual of one crease's condition over `count` samples: (7)
// (`fold`), (8) or, for "straight when unfolded", |⟨d₀ × d₁ / |d₀ × d₁|, n_L⟩| with
// dₖ = c²ₖ − c²ₖ₊₁ (n_L in the osculating plane: the crease is a geodesic of its left strip).
struct Residuals {
    double max = 0.0;
    double sum = 0.0;
    int samples = 0;
};

Residuals creaseResiduals(const model::CompositeSurface& surface,
                          const std::vector<model::Strip>& strips, const model::Crease& crease,
                          model::CreaseCondition condition, int samplesPerInterval) {
    Residuals result;
    const model::EdgeRecord& record = surface.edge(crease.edge);
    const model::Strip& left = strips[crease.left.strip];
    const model::Strip& right = strips[crease.right.strip];
    const model::BSplineCurve curve =
        model::BSplineCurve::uniform(record.space, record.controlPoints);
    double polygon = 0.0;
    for (std::size_t i = 0; i + 1 < record.controlPoints.size(); ++i) {
        polygon += (record.controlPoints[i + 1] - record.controlPoints[i]).norm();
    }
    const double tiny = 1e-9 * polygon;
    const int count = samplesPerInterval * record.space.intervals;
    for (int i = 0; i < count; ++i) {
        const double u = (i + 0.5) / count;
        const model::DeBoorPoints points = curve.deBoorPoints(u);
        const model::Vec3 nl = unitNormal(left, crease.left, u);
        const model::Vec3 d0 = points.secondDerivativePoints[0] - points.secondDerivativePoints[1];
        const model::Vec3 d1 = points.secondDerivativePoints[1] - points.secondDerivativePoints[2];
        if (condition == model::CreaseCondition::Straight) {
            // A straight piece of curve (d₀ ∥ d₁) is straight when unfolded: 0.
            const model::Vec3 o = cross(d0, d1);
            const double r =
                o.norm() > tiny * (d0.norm() + d1.norm()) ? normalisedProduct(o, nl, 0.0) : 0.0;
            result.max = std::max(result.max, r);
            result.sum += 2.0 * r;
        } else {
            const model::Vec3 nr = unitNormal(right, crease.right, u);
            const model::Vec3 n =
                condition == model::CreaseCondition::CurvedFold ? nl + nr : nl - nr;
            for (const model::Vec3& d : {d0, d1}) {
                const double r = normalisedProduct(d, n, tiny);
                result.max = std::max(result.max, r);
                result.sum += r;
            }
        }
        ++result.samples;
    }
    return result;
}

bool between2Strips(const model::Crease& crease, const model::EdgeRecord& record) {
    return crease.left.strip != model::CreaseSide::kNoStrip &&
           crease.right.strip != model::CreaseSide::kNoStrip && record.space.degree >= 2;
}

} // namespace

CreaseQuality measureCreaseQuality(const model::CompositeSurface& surface, int samplesPerInterval) {
    CreaseQuality quality;
    const auto derived = model::DerivedGeometry::of(surface, 8);
    const std::vector<model::Strip>& strips = derived->strips();
    const std::vector<model::Crease>& creases = derived->creases();
    double foldSum = 0.0;
    double residualSum = 0.0;
    for (const model::Crease& crease : creases) {
        foldSum += std::abs(crease.foldAngleDegrees);
        const model::EdgeRecord& record = surface.edge(crease.edge);
        if (record.condition == model::CreaseCondition::None || !between2Strips(crease, record)) {
            continue;
        }
        ++quality.creases;
        const Residuals r =
            creaseResiduals(surface, strips, crease, record.condition, samplesPerInterval);
        quality.residualMax = std::max(quality.residualMax, r.max);
        residualSum += r.sum;
        quality.samples += r.samples;
    }
    quality.residualMean = quality.samples > 0 ? residualSum / (2.0 * quality.samples) : 0.0;
    quality.meanFoldDegrees = creases.empty() ? 0.0 : foldSum / static_cast<double>(creases.size());
    return quality;
}

std::vector<CreaseResidual> curvedFoldResiduals(const model::CompositeSurface& surface,
                                                int samplesPerInterval) {
    std::vector<CreaseResidual> result;
    const auto derived = model::DerivedGeometry::of(surface, 8);
    const std::vector<model::Strip>& strips = derived->strips();
    for (const model::Crease& crease : derived->creases()) {
        if (!between2Strips(crease, surface.edge(crease.edge))) {
            continue;
        }
        const Residuals r = creaseResiduals(surface, strips, crease,
                                            model::CreaseCondition::CurvedFold, samplesPerInterval);
        result.push_back({crease.edge, r.max, r.samples > 0 ? r.sum / (2.0 * r.samples) : 0.0});
    }
    return result;
}

} // namespace devsurf::solver
