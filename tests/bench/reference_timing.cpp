// Times the reference-shape preprocessing and the distance report on synthetic data (the
// figures in docs/tuning.md, "model/reference"). Built on request only:
//   cmake --build build --target devsurf-reference-timing && build/bin/devsurf-reference-timing
#include "model/examples.h"
#include "model/math_constants.h"
#include "model/reference/distance_report.h"
#include "model/reference/thinning.h"
#include "model/strip.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <random>

using namespace devsurf::model;
using namespace devsurf::model::reference;

namespace {

using devsurf::model::kPi;

double secondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// 2M random points on a torus (radii 100 and 40 mm): a scan-sized cloud of a closed surface.
void timeThinning() {
    std::mt19937 random(1);
    std::uniform_real_distribution<double> angle(0.0, 2.0 * kPi);
    std::vector<Vec3> points;
    points.reserve(2000000);
    for (int i = 0; i < 2000000; ++i) {
        const double a = angle(random);
        const double b = angle(random);
        const double ring = 100.0 + 40.0 * std::cos(b);
        points.emplace_back(ring * std::cos(a), ring * std::sin(a), 40.0 * std::sin(b));
    }
    for (double rho : {0.0, 1.0}) {
        const auto start = std::chrono::steady_clock::now();
        const ThinningResult thinned = thinReference(points, rho);
        std::printf("thinning: %zu points, rho %.3f mm%s: %zu kept, %.2f s\n", points.size(),
                    thinned.radius, rho > 0.0 ? "" : " (default)", thinned.points.size(),
                    secondsSince(start));
    }
}

// The cylinder example at size 24 (288 strips) against target points up to 2 mm off it.
void timeDistance() {
    const CompositeSurface surface = makeExample("cylinder", 24).surfaces.front();
    const std::vector<Strip> strips = stripsOf(surface);
    for (std::size_t count : {100000u, 1000000u}) {
        std::mt19937 random(2);
        std::uniform_real_distribution<double> unit(0.0, 1.0);
        std::uniform_real_distribution<double> offset(-2.0, 2.0);
        std::vector<Vec3> target;
        for (std::size_t i = 0; i < count; ++i) {
            const Strip& strip = strips[i % strips.size()];
            const Vec3 p = strip.point(unit(random), unit(random));
            const Vec3 radial(p.x, p.y, 0.0);
            target.push_back(p + radial / radial.norm() * offset(random));
        }
        const auto start = std::chrono::steady_clock::now();
        const DistanceReport report = measureDistance(surface, target, {1.0, 16});
        std::printf("distance: %zu strips (%zu samples) to %zu points: mean %.4f, p95 %.4f, "
                    "max %.4f mm, coverage %.3f, %.2f s\n",
                    strips.size(), report.surfaceSamples, count, report.targetToSurface.mean,
                    report.targetToSurface.percentile95, report.targetToSurface.max,
                    report.coverage, secondsSince(start));
    }
}

} // namespace

int main() {
    timeThinning();
    timeDistance();
    return 0;
}
