#include "solver/formulation/strip_isometry.h"

#include <cmath>

namespace devsurf::solver {

namespace {

void addLength(int p, int q, const std::vector<double>& x, double negligible,
               SquaredDistanceTerm& term) {
    double squared = 0.0;
    for (int k = 0; k < 3; ++k) {
        const double d = x[static_cast<std::size_t>(p + k)] - x[static_cast<std::size_t>(q + k)];
        squared += d * d;
    }
    const double length = std::sqrt(squared);
    if (length <= negligible) {
        return;
    }
    term.addRow({{p, 1.0}, {q, -1.0}}, squared);
}

} // namespace

void addStripIsometry(const std::vector<int>& a, const std::vector<int>& b,
                      const std::vector<double>& x, double negligible, SquaredDistanceTerm& term) {
    const std::size_t n = a.size();
    for (std::size_t i = 0; i + 1 < n; ++i) {
        addLength(a[i], a[i + 1], x, negligible, term);
    }
    if (b.size() != n) {
        return;
    }
    for (std::size_t i = 0; i < n; ++i) {
        if (i + 1 < n) {
            addLength(b[i], b[i + 1], x, negligible, term);
            addLength(a[i], b[i + 1], x, negligible, term);
        }
        addLength(a[i], b[i], x, negligible, term);
    }
}

} // namespace devsurf::solver
