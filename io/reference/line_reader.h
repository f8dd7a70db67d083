#pragma once

#include <cstdint>
#include <fstream>
#include <string>
#include <string_view>
#include <vector>

namespace devsurf::io {

// "line N", for the detail of a refusal.
inline std::string lineText(std::uint64_t line) {
    return "line " + std::to_string(line);
}

// Reads a text file line by line through one buffer (64 KB, larger only for a longer line), so
// that files of hundreds of megabytes stream without being held whole. A line longer than
// kMaxLineLength is an error.
class LineReader {
public:
    static constexpr std::size_t kMaxLineLength = 1u << 20;

    explicit LineReader(const std::string& path);
    bool isOpen() const { return m_in.is_open(); }

    // The next line without its end of line ("\n" or "\r\n"); false at the end of the file or
    // when a line is too long (then tooLong() says so).
    bool next(std::string_view& line);
    bool tooLong() const { return m_tooLong; }
    // Whether the line last returned was ended by a line break (a truncated file's last line
    // usually is not).
    bool lineWasEnded() const { return m_ended; }
    std::uint64_t lineNumber() const { return m_lineNumber; }
    std::uint64_t bytesRead() const { return m_consumed; }

private:
    bool fill();

    std::ifstream m_in;
    std::vector<char> m_buffer;
    std::size_t m_begin = 0;
    std::size_t m_end = 0;
    bool m_eof = false;
    bool m_tooLong = false;
    bool m_ended = false;
    std::uint64_t m_lineNumber = 0;
    std::uint64_t m_consumed = 0;
};

// Splits a line into fields separated by white space or commas.
void splitFields(std::string_view line, std::vector<std::string_view>& fields);
// The whole field as a number, or false.
bool parseNumber(std::string_view field, double& value);
bool parseInteger(std::string_view field, long long& value);

} // namespace devsurf::io
