#pragma once

#include <cstddef>
#include <stdexcept>
#include <string>

// Small helpers shared by the sources of BSplineCurve (bspline_curve.cpp: construction and
// editing; bspline_evaluation.cpp: evaluation); not part of the model's interface.
namespace devsurf::model::bspline_support {

[[noreturn]] inline void fail(const std::string& message) {
    throw std::invalid_argument(message);
}

// i modulo n in [0, n).
inline int wrapIndex(int i, int n) {
    const int r = i % n;
    return r < 0 ? r + n : r;
}

inline std::size_t idx(int i) {
    return static_cast<std::size_t>(i);
}

} // namespace devsurf::model::bspline_support
