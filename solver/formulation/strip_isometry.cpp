#include "solver/formulation/strip_isometry.h"

#include <algorithm>

namespace devsurf::solver {

namespace {

constexpr double kNegligible = 1e-9; // in coordinates of diameter 1

void addLength(int p, int q, const std::vector<double>& x, SquaredDistanceTerm& term) {
    double squared = 0.0;
    for (int k = 0; k < 3; ++k) {
        const double d = x[static_cast<std::size_t>(p + k)] - x[static_cast<std::size_t>(q + k)];
        squared += d * d;
    }
    if (squared > kNegligible * kNegligible) {
        term.addRow({{p, 1.0}, {q, -1.0}}, squared);
    }
}

// Offsets of a strip side's control points in the order the strip traverses them.
std::vector<int> sideOffsets(const model::StripSide& side,
                             const std::map<model::EdgeId, std::vector<int>>& edgeOffsets) {
    std::vector<int> offsets = edgeOffsets.at(side.edge);
    if (side.reversed) {
        std::reverse(offsets.begin(), offsets.end());
    }
    return offsets;
}

} // namespace

void addStripIsometry(const std::vector<model::Strip>& strips,
                      const std::map<model::EdgeId, std::vector<int>>& edgeOffsets,
                      const std::vector<double>& x, SquaredDistanceTerm& term) {
    for (const model::Strip& strip : strips) {
        if (strip.isCone()) {
            continue;
        }
        const std::vector<int> a = sideOffsets(strip.aSide, edgeOffsets);
        const std::vector<int> b = sideOffsets(strip.bSide, edgeOffsets);
        for (std::size_t i = 0; i + 1 < a.size(); ++i) {
            addLength(a[i], a[i + 1], x, term);
        }
        for (std::size_t i = 0; i < a.size(); ++i) { // both curves share their spline space
            if (i + 1 < a.size()) {
                addLength(b[i], b[i + 1], x, term);
                addLength(a[i], b[i + 1], x, term);
            }
            addLength(a[i], b[i], x, term);
        }
    }
}

} // namespace devsurf::solver
