#pragma once

// The bench's hand-written JSON: a number in %.6g and a quoted string (control characters
// blanked), and the median of timings; shared by the default report and --paper.

#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

namespace devsurf::bench {

// The median of the values (0 for none): the benchmark's timings and ratios.
inline double median(std::vector<double> values) {
    if (values.empty()) {
        return 0.0;
    }
    std::sort(values.begin(), values.end());
    const std::size_t n = values.size();
    return n % 2 == 1 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

inline std::string number(double value) {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.6g", value);
    return buffer;
}

inline std::string quoted(const std::string& text) {
    std::string out = "\"";
    for (char c : text) {
        if (c == '"' || c == '\\') {
            out += '\\';
        }
        out += c >= 0 && c < 0x20 ? ' ' : c;
    }
    return out + "\"";
}

} // namespace devsurf::bench
