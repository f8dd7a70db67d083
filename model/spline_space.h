#pragma once

#include <string>
#include <vector>

namespace devsurf::model {

// The uniform spline space S(n, m, k) on [0,1] (docs/math.md §1): degree m, smoothness C^k,
// n intervals of equal length. Interior breakpoints i/n carry knot multiplicity m - k.
struct SplineSpace {
    int degree = 3;     // m >= 1
    int smoothness = 2; // 0 <= k < m
    int intervals = 1;  // n >= 1

    static constexpr int maxDegree = 10;
    static constexpr int maxIntervals = 100000;

    // Also enforces the upper bounds above so that counts can never overflow an int.
    bool isValid() const;

    // Open (clamped): n(m+1) - (n-1)(k+1). Closed (periodic): n(m-k). 0 for an invalid space.
    int controlPointCount(bool closed) const;

    // Open: clamped knot vector, end knots of multiplicity m+1, interior breakpoints i/n of
    // multiplicity m-k; size controlPointCount(false) + m + 1.
    // Closed: the periodic knot sequence t_0 .. t_{N+2m} (N = controlPointCount(true)) in the
    // representation BSplineCurve uses for closed curves: t_m = 0 is the first of the knots at
    // 0, t_{m+N} = 1, and t_{i+N} = t_i + 1. Throws std::invalid_argument for an invalid space.
    std::vector<double> knots(bool closed) const;

    // "S(n=4, m=3, k=2)": for logs and exception texts (app::ProblemText::splineSpace words it).
    std::string technicalKey() const;

    bool operator==(const SplineSpace& o) const {
        return degree == o.degree && smoothness == o.smoothness && intervals == o.intervals;
    }
    bool operator!=(const SplineSpace& o) const { return !(*this == o); }
    // Lexicographic in (degree, smoothness, intervals), so the space can key a std::map.
    bool operator<(const SplineSpace& o) const {
        if (degree != o.degree) {
            return degree < o.degree;
        }
        if (smoothness != o.smoothness) {
            return smoothness < o.smoothness;
        }
        return intervals < o.intervals;
    }
};

} // namespace devsurf::model
