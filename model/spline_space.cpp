#include "spline_space.h"

#include <stdexcept>

namespace devsurf::model {

bool SplineSpace::isValid() const {
    return degree >= 1 && degree <= maxDegree && smoothness >= 0 && smoothness < degree &&
           intervals >= 1 && intervals <= maxIntervals;
}

int SplineSpace::controlPointCount(bool closed) const {
    if (!isValid()) {
        return 0;
    }
    const int m = degree;
    const int k = smoothness;
    const int n = intervals;
    return closed ? n * (m - k) : n * (m + 1) - (n - 1) * (k + 1);
}

std::vector<double> SplineSpace::knots(bool closed) const {
    if (!isValid()) {
        throw std::invalid_argument("Invalid spline space: " + technicalKey() + ".");
    }
    const int m = degree;
    const int mult = degree - smoothness;
    const int n = intervals;
    std::vector<double> t;
    if (!closed) {
        t.reserve(static_cast<std::size_t>(controlPointCount(false) + m + 1));
        t.insert(t.end(), static_cast<std::size_t>(m + 1), 0.0);
        for (int i = 1; i < n; ++i) {
            t.insert(t.end(), static_cast<std::size_t>(mult), static_cast<double>(i) / n);
        }
        t.insert(t.end(), static_cast<std::size_t>(m + 1), 1.0);
        return t;
    }
    const int count = controlPointCount(true);
    t.reserve(static_cast<std::size_t>(count + 2 * m + 1));
    for (int i = 0; i <= count + 2 * m; ++i) {
        const int q = i - m;
        // Floor division: indices left of t_m belong to the previous period.
        const int period = q >= 0 ? q / count : -((-q + count - 1) / count);
        const int r = q - period * count;
        // Base knot plus a whole number of periods, computed exactly the way BSplineCurve
        // regenerates wrapped knots, so that both agree bit for bit.
        t.push_back(static_cast<double>(r / mult) / n + static_cast<double>(period));
    }
    return t;
}

std::string SplineSpace::technicalKey() const {
    return "S(n=" + std::to_string(intervals) + ", m=" + std::to_string(degree) +
           ", k=" + std::to_string(smoothness) + ")";
}

} // namespace devsurf::model
