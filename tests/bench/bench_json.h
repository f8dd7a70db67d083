#pragma once

// The bench's hand-written JSON: a number in %.6g and a quoted string (control characters
// blanked), shared by the default report and --paper.

#include <cstdio>
#include <string>

namespace devsurf::bench {

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
