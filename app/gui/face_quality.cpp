#include "face_quality.h"

#include "model/strip.h"
#include "solver/quality/quality_measures.h"

#include <algorithm>
#include <exception>

namespace devsurf::app {

std::vector<std::pair<model::FaceId, double>>
faceDevelopability(const model::CompositeSurface& surface, int samplesPerInterval) {
    std::vector<std::pair<model::FaceId, double>> result;
    std::vector<model::Strip> strips;
    try {
        strips = model::stripsOf(surface);
    } catch (const std::exception&) {
        return result; // an invalid surface has no strips to measure
    }
    const int samples = std::max(1, samplesPerInterval);
    for (const model::Strip& strip : strips) {
        if (strip.isCone()) {
            continue;
        }
        const int intervals = std::max(1, surface.edge(strip.aSide.edge).space.intervals);
        double worst = 0.0;
        for (int i = 0; i < intervals * samples; ++i) {
            const double u = (i + 0.5) / (intervals * samples);
            worst = std::max(worst, solver::normalizedDevelopabilityResidual(
                                        strip.a.evaluate(u) - strip.b.evaluate(u),
                                        strip.a.derivative(u, 1), strip.b.derivative(u, 1)));
        }
        result.emplace_back(strip.face, worst);
    }
    std::sort(result.begin(), result.end(),
              [](const auto& a, const auto& b) { return a.second > b.second; });
    return result;
}

} // namespace devsurf::app
