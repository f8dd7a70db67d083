#include "distance_colours.h"

#include "quality_colours.h"

#include <vtkUnsignedCharArray.h>

#include <algorithm>
#include <cmath>

namespace devsurf::views {

namespace {

// The smallest 1, 2 or 5 × 10^k at or above value (> 0).
double roundUp(double value) {
    const double decade = std::pow(10.0, std::floor(std::log10(value)));
    for (double step : {1.0, 2.0, 5.0, 10.0}) {
        if (step * decade >= value * (1.0 - 1e-12)) {
            return step * decade;
        }
    }
    return 10.0 * decade;
}

} // namespace

void DistanceColouring::setRange(double tolerance, double largest) {
    m_tolerance = tolerance > 0.0 && std::isfinite(tolerance) ? tolerance : 1.0;
    const double top = std::max({largest, 2.0 * m_tolerance, 1e-9});
    m_high = roundUp(std::isfinite(top) ? top : 2.0 * m_tolerance);
    m_colours = toleranceScale(m_tolerance / m_high, kColours);
}

QColor DistanceColouring::colour(double distance) const {
    if (m_colours.empty()) {
        return QColor();
    }
    const double t = std::isfinite(distance) ? std::clamp(distance / m_high, 0.0, 1.0) : 1.0;
    const auto i = std::min(static_cast<std::size_t>(t * kColours), m_colours.size() - 1);
    return m_colours[i];
}

vtkSmartPointer<vtkUnsignedCharArray>
DistanceColouring::pointColours(const std::vector<double>& distances, bool stale) const {
    auto colours = vtkSmartPointer<vtkUnsignedCharArray>::New();
    colours->SetNumberOfComponents(3);
    colours->SetName("distance");
    colours->SetNumberOfTuples(static_cast<vtkIdType>(distances.size()));
    // The table once in bytes, then one lookup per point (a million points in a few ms).
    std::vector<std::array<unsigned char, 3>> table;
    for (const QColor& each : m_colours) {
        const QColor c = stale ? fadedColour(each) : each;
        table.push_back({static_cast<unsigned char>(c.red()), static_cast<unsigned char>(c.green()),
                         static_cast<unsigned char>(c.blue())});
    }
    unsigned char* out = colours->GetPointer(0);
    for (double d : distances) {
        const double t = std::isfinite(d) ? std::clamp(d / m_high, 0.0, 1.0) : 1.0;
        const auto& rgb = table[std::min(static_cast<std::size_t>(t * kColours), table.size() - 1)];
        *out++ = rgb[0];
        *out++ = rgb[1];
        *out++ = rgb[2];
    }
    return colours;
}

} // namespace devsurf::views
