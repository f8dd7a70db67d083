#pragma once

#include "model/problem.h"

#include <stdexcept>
#include <string>
#include <vector>

namespace devsurf::io {

// A file could not be read or written. The message is one sentence for the user; where the
// file describes an impossible design, `problems` lists what the model found, for the front end
// to word (app/text).
class FileError : public std::runtime_error {
public:
    explicit FileError(const std::string& message, std::vector<model::Problem> problems = {})
        : std::runtime_error(message), m_problems(std::move(problems)) {}
    const std::vector<model::Problem>& problems() const { return m_problems; }

private:
    std::vector<model::Problem> m_problems;
};

// A reason without its final period and spaces, to be quoted inside a longer sentence.
inline std::string withoutFinalPeriod(std::string text) {
    while (!text.empty() && (text.back() == '.' || text.back() == ' ')) {
        text.pop_back();
    }
    return text;
}

} // namespace devsurf::io
