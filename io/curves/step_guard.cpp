#include "step_guard.h"

#include <cctype>
#include <unordered_set>

namespace devsurf::io {

std::optional<std::string> unsafeStepContent(const std::string& bytes) {
    const std::size_t data = bytes.find("DATA;");
    if (data == std::string::npos) {
        return std::nullopt; // nothing to number; the reader says what is wrong
    }
    std::unordered_set<std::string> numbers;
    bool statementStart = true;
    for (std::size_t i = data + 5; i < bytes.size(); ++i) {
        const char c = bytes[i];
        if (c == '\'') { // a string: '' is a quote inside it
            for (++i; i < bytes.size(); ++i) {
                if (bytes[i] == '\'') {
                    if (i + 1 < bytes.size() && bytes[i + 1] == '\'') {
                        ++i;
                    } else {
                        break;
                    }
                }
            }
            statementStart = false;
        } else if (c == '/' && i + 1 < bytes.size() && bytes[i + 1] == '*') {
            const std::size_t end = bytes.find("*/", i + 2);
            i = end == std::string::npos ? bytes.size() : end + 1;
        } else if (c == ';') {
            statementStart = true;
        } else if (std::isspace(static_cast<unsigned char>(c))) {
            continue;
        } else if (statementStart && c == '#') {
            std::size_t end = i + 1;
            while (end < bytes.size() && std::isdigit(static_cast<unsigned char>(bytes[end]))) {
                ++end;
            }
            std::size_t after = end;
            while (after < bytes.size() && std::isspace(static_cast<unsigned char>(bytes[after]))) {
                ++after;
            }
            if (end > i + 1 && after < bytes.size() && bytes[after] == '=') {
                std::string number = bytes.substr(i + 1, end - i - 1);
                const std::size_t first = number.find_first_not_of('0');
                number = first == std::string::npos ? "0" : number.substr(first);
                if (!numbers.insert(number).second) {
                    return "entity #" + number + " is defined twice";
                }
            }
            statementStart = false;
            i = end - 1;
        } else {
            statementStart = false;
        }
    }
    return std::nullopt;
}

} // namespace devsurf::io
