#pragma once

#include <stdexcept>
#include <string>
#include <vector>

namespace devsurf::io {

// A file could not be read or written. The message is one sentence for the user; details
// lists every problem found where there are several (e.g. all validation problems).
class FileError : public std::runtime_error {
public:
    explicit FileError(const std::string& message, std::vector<std::string> details = {})
        : std::runtime_error(message), m_details(std::move(details)) {}
    const std::vector<std::string>& details() const { return m_details; }

private:
    std::vector<std::string> m_details;
};

} // namespace devsurf::io
