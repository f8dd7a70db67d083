#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <vector>

namespace devsurf::solver {

// Whether every value is finite, by their bits: a value is infinite or NaN exactly when its
// exponent bits are all set, and then adding one to the exponent carries into the sign bit.
// Branch-free, so the compiler vectorises it: the Jacobian of the 40,200-variable annulus has
// 2.1 million entries, and testing them value by value (std::isfinite) took 2 of the 65 ms of
// an iteration.
inline bool allFinite(const double* values, std::size_t count) {
    constexpr std::uint64_t kExponent = 0x7ff0000000000000ull;
    constexpr std::uint64_t kExponentOne = 0x0010000000000000ull;
    std::uint64_t carried = 0;
    for (std::size_t i = 0; i < count; ++i) {
        std::uint64_t bits = 0;
        std::memcpy(&bits, values + i, sizeof bits);
        carried |= (bits & kExponent) + kExponentOne;
    }
    return (carried & 0x8000000000000000ull) == 0;
}

inline bool allFinite(const std::vector<double>& values) {
    return allFinite(values.data(), values.size());
}

} // namespace devsurf::solver
