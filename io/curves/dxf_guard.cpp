#include "dxf_guard.h"

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <string_view>

namespace devsurf::io {

namespace {

// dxflib reads lines into a buffer of 1024 characters; a longer line stops its stream without
// ending it, and it reads on forever.
constexpr std::size_t kLongestLine = 1000;

std::string_view trimmed(std::string_view line) {
    const auto first = line.find_first_not_of(" \t\r");
    if (first == std::string_view::npos) {
        return {};
    }
    const auto last = line.find_last_not_of(" \t\r");
    return line.substr(first, last - first + 1);
}

// The integer a line holds as dxflib reads it (leading digits); nullopt if it has none.
std::optional<long long> integerOf(std::string_view text) {
    const std::string copy(text);
    errno = 0;
    char* end = nullptr;
    const long long value = std::strtoll(copy.c_str(), &end, 10);
    if (end == copy.c_str()) {
        return std::nullopt;
    }
    return errno == ERANGE ? (value < 0 ? -1 : (1ll << 40)) : value;
}

bool isCountCode(std::string_view entity, long long code) {
    if (entity == "LWPOLYLINE") {
        return code == 90;
    }
    if (entity == "SPLINE") {
        return code == 72 || code == 73 || code == 74;
    }
    if (entity == "LEADER") {
        return code == 76;
    }
    return false;
}

} // namespace

std::optional<std::string> unsafeDxfContent(const std::string& bytes) {
    // Every element of an announced list takes a group code and a value: four bytes at least.
    const long long limit = static_cast<long long>(bytes.size() / 4) + 1;
    std::string_view rest(bytes);
    std::string entity;
    bool countSeen = false;  // LWPOLYLINE: its vertex count was given
    bool vertexSeen = false; // LWPOLYLINE: a vertex followed the latest count
    while (!rest.empty()) {
        const auto codeEnd = rest.find('\n');
        if (std::min(codeEnd, rest.size()) >= kLongestLine) {
            return std::string("a line is longer than DXF allows");
        }
        const std::string_view codeLine = trimmed(rest.substr(0, codeEnd));
        if (codeEnd == std::string_view::npos) {
            break;
        }
        rest.remove_prefix(codeEnd + 1);
        const auto valueEnd = rest.find('\n');
        if (std::min(valueEnd, rest.size()) >= kLongestLine) {
            return std::string("a line is longer than DXF allows");
        }
        const std::string_view value = trimmed(rest.substr(0, valueEnd));
        rest.remove_prefix(valueEnd == std::string_view::npos ? rest.size() : valueEnd + 1);
        const std::optional<long long> code = integerOf(codeLine);
        if (!code) {
            continue; // dxflib stops or skips there itself
        }
        if (*code == 0) {
            entity = std::string(value);
            countSeen = false;
            vertexSeen = false;
            continue;
        }
        if (isCountCode(entity, *code)) {
            const long long count = integerOf(value).value_or(0);
            if (count > limit) {
                return entity + " announces " + std::to_string(count) +
                       " elements, more than the file can hold";
            }
            if (entity == "LWPOLYLINE") {
                if (count < 1) {
                    return "an LWPOLYLINE announces no vertices";
                }
                countSeen = true;
                vertexSeen = false;
            }
        } else if (entity == "LWPOLYLINE") {
            if (*code == 10) {
                vertexSeen = countSeen;
            } else if (*code == 42 && !vertexSeen) {
                return "an LWPOLYLINE has a bulge before its first vertex";
            }
        }
    }
    return std::nullopt;
}

} // namespace devsurf::io
