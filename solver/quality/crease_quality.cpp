#include "crease_quality.h"

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

} // namespace

CreaseQuality measureCreaseQuality(const model::CompositeSurface& surface, int samplesPerInterval) {
    CreaseQuality quality;
    const std::vector<model::Strip> strips = model::stripsOf(surface);
    const std::vector<model::Crease> creases =
        model::creasesOf(surface, strips, model::sampleSurface(surface, 8));
    double foldSum = 0.0;
    double residualSum = 0.0;
    for (const model::Crease& crease : creases) {
        foldSum += std::abs(crease.foldAngleDegrees);
        const model::EdgeRecord& record = surface.edge(crease.edge);
        const bool fold = record.condition == model::CreaseCondition::CurvedFold;
        const bool geodesic = record.condition == model::CreaseCondition::Geodesic;
        if ((!fold && !geodesic) || crease.left.strip == model::CreaseSide::kNoStrip ||
            crease.right.strip == model::CreaseSide::kNoStrip || record.space.degree < 2) {
            continue;
        }
        ++quality.creases;
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
            const model::Vec3 nr = unitNormal(right, crease.right, u);
            const model::Vec3 n = fold ? nl + nr : nl - nr;
            for (int k = 0; k < 2; ++k) {
                const double r = normalisedProduct(points.secondDerivativePoints[k] -
                                                       points.secondDerivativePoints[k + 1],
                                                   n, tiny);
                quality.residualMax = std::max(quality.residualMax, r);
                residualSum += r;
            }
            ++quality.samples;
        }
    }
    quality.residualMean = quality.samples > 0 ? residualSum / (2.0 * quality.samples) : 0.0;
    quality.meanFoldDegrees = creases.empty() ? 0.0 : foldSum / static_cast<double>(creases.size());
    return quality;
}

} // namespace devsurf::solver
