#pragma once

// Small helpers for the linear combinations of state values that the formulation's terms are
// built from.

#include "solver/core/term.h"

#include <algorithm>
#include <vector>

namespace devsurf::solver {

// The u values of the collocation of (4): `count` distinct interior values per interval.
inline std::vector<double> collocationValues(int intervals, int count) {
    std::vector<double> values;
    for (int i = 0; i < intervals; ++i) {
        for (int j = 0; j < count; ++j) {
            values.push_back((i + (j + 0.5) / count) / intervals);
        }
    }
    return values;
}

// Merges repeated offsets and drops zero coefficients, so that Jacobian rows stay short.
inline PointCombination simplified(const PointCombination& in) {
    PointCombination out;
    for (const PointTerm& t : in) {
        auto it = std::find_if(out.begin(), out.end(),
                               [&t](const PointTerm& o) { return o.offset == t.offset; });
        if (it == out.end()) {
            out.push_back(t);
        } else {
            it->coefficient += t.coefficient;
        }
    }
    out.erase(std::remove_if(out.begin(), out.end(),
                             [](const PointTerm& t) { return t.coefficient == 0.0; }),
              out.end());
    return out;
}

// a + scale · b (not simplified).
inline PointCombination plus(PointCombination a, const PointCombination& b, double scale = 1.0) {
    for (const PointTerm& t : b) {
        a.push_back({t.offset, scale * t.coefficient});
    }
    return a;
}

} // namespace devsurf::solver
