#pragma once

// π for the whole code base: C++17 has no std::numbers, and one definition keeps files that
// are compiled together (unity builds) free of clashing copies.

namespace devsurf::model {

inline constexpr double kPi = 3.14159265358979323846;
inline constexpr double kTwoPi = 2.0 * kPi;

} // namespace devsurf::model
