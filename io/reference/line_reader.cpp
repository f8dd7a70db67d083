#include "line_reader.h"

#include <algorithm>
#include <charconv>
#include <cstdlib>
#include <cstring>

namespace devsurf::io {

LineReader::LineReader(const std::string& path)
    : m_in(path, std::ios::binary), m_buffer(1u << 16) {}

// Moves the unread rest to the front and reads more behind it; false when nothing was added.
bool LineReader::fill() {
    if (m_eof) {
        return false;
    }
    if (m_begin > 0) {
        std::memmove(m_buffer.data(), m_buffer.data() + m_begin, m_end - m_begin);
        m_end -= m_begin;
        m_begin = 0;
    }
    m_in.read(m_buffer.data() + m_end, static_cast<std::streamsize>(m_buffer.size() - m_end));
    const auto got = static_cast<std::size_t>(m_in.gcount());
    if (got == 0 || !m_in) {
        m_eof = true;
    }
    m_end += got;
    return got > 0;
}

bool LineReader::next(std::string_view& line) {
    std::size_t searched = m_begin;
    for (;;) {
        const void* found = std::memchr(m_buffer.data() + searched, '\n', m_end - searched);
        if (found != nullptr) {
            const auto at =
                static_cast<std::size_t>(static_cast<const char*>(found) - m_buffer.data());
            std::size_t stop = at;
            if (stop > m_begin && m_buffer[stop - 1] == '\r') {
                --stop;
            }
            line = std::string_view(m_buffer.data() + m_begin, stop - m_begin);
            m_consumed += at + 1 - m_begin;
            m_begin = at + 1;
            m_ended = true;
            ++m_lineNumber;
            return true;
        }
        const std::size_t pending = m_end - m_begin;
        if (pending >= kMaxLineLength) {
            m_tooLong = true;
            return false;
        }
        if (pending == m_buffer.size()) {
            // A line longer than the buffer: room for it, up to the limit.
            m_buffer.resize(std::min(2 * m_buffer.size(), kMaxLineLength + 1));
        }
        if (!fill()) {
            if (m_end == m_begin) {
                return false;
            }
            std::size_t stop = m_end;
            if (m_buffer[stop - 1] == '\r') {
                --stop;
            }
            line = std::string_view(m_buffer.data() + m_begin, stop - m_begin);
            m_consumed += m_end - m_begin;
            m_begin = m_end;
            m_ended = false;
            ++m_lineNumber;
            return true;
        }
        searched = m_begin + pending;
    }
}

void splitFields(std::string_view line, std::vector<std::string_view>& fields) {
    fields.clear();
    std::size_t i = 0;
    const auto separator = [](char c) {
        return c == ' ' || c == '\t' || c == ',' || c == '\r' || c == '\v' || c == '\f';
    };
    while (i < line.size()) {
        while (i < line.size() && separator(line[i])) {
            ++i;
        }
        const std::size_t start = i;
        while (i < line.size() && !separator(line[i])) {
            ++i;
        }
        if (i > start) {
            fields.push_back(line.substr(start, i - start));
        }
    }
}

bool parseNumber(std::string_view field, double& value) {
    const char* first = field.data();
    const char* last = field.data() + field.size();
    if (first != last && *first == '+') {
        ++first;
    }
    const auto [end, error] = std::from_chars(first, last, value);
    if (error == std::errc::result_out_of_range && end == last) {
        // Beyond the range of a double (1e400 becomes infinite, 1e-400 zero or subnormal):
        // strtod says which, and the caller refuses what is not finite.
        value = std::strtod(std::string(first, last).c_str(), nullptr);
        return true;
    }
    return error == std::errc() && end == last;
}

bool parseInteger(std::string_view field, long long& value) {
    const char* first = field.data();
    const char* last = field.data() + field.size();
    if (first != last && *first == '+') {
        ++first;
    }
    const auto [end, error] = std::from_chars(first, last, value);
    return error == std::errc() && end == last;
}

} // namespace devsurf::io
