#pragma once

#include <algorithm>
#include <cstddef>
#include <vector>

namespace devsurf::solver {

// Keeps row scales within a factor 100 of the median of the positive ones: a side that nearly
// vanishes at the reference (a normal spline passing close to zero on a rough start) would
// otherwise make its row dominate every other. Rows of scale 0 (a vanishing side) take the
// median; if no scale is positive, every row takes 1.
inline void clampScalesToMedian(std::vector<double>& scales) {
    std::vector<double> positive;
    for (double v : scales) {
        if (v > 0.0) {
            positive.push_back(v);
        }
    }
    if (positive.empty()) {
        std::fill(scales.begin(), scales.end(), 1.0);
        return;
    }
    const auto middle = positive.begin() + static_cast<std::ptrdiff_t>(positive.size() / 2);
    std::nth_element(positive.begin(), middle, positive.end());
    const double median = *middle;
    for (double& v : scales) {
        v = v > 0.0 ? std::clamp(v, median / 100.0, median * 100.0) : median;
    }
}

} // namespace devsurf::solver
