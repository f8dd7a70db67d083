// The structural check of PLY files before OpenMesh reads them (see mesh_check.cpp): the
// header's elements and properties, every record walked through, face indices in range.

#include "line_reader.h"
#include "reference_readers.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <fstream>
#include <map>
#include <vector>

namespace devsurf::io::reference {

namespace {

using Code = ReferenceImportError::Code;
using Error = std::optional<ReferenceImportError>;

// Buffered big or little endian binary input for PLY bodies.
class BinaryInput {
public:
    BinaryInput(std::ifstream& in, bool bigEndian) : m_in(in), m_bigEndian(bigEndian) {}
    bool read(unsigned char* out, std::size_t n) {
        if (m_end - m_begin < n) {
            std::memmove(m_buffer.data(), m_buffer.data() + m_begin, m_end - m_begin);
            m_end -= m_begin;
            m_begin = 0;
            m_in.read(reinterpret_cast<char*>(m_buffer.data() + m_end),
                      static_cast<std::streamsize>(m_buffer.size() - m_end));
            m_end += static_cast<std::size_t>(m_in.gcount());
            if (m_end < n) {
                return false;
            }
        }
        std::memcpy(out, m_buffer.data() + m_begin, n);
        if (m_bigEndian) {
            std::reverse(out, out + n);
        }
        m_begin += n;
        m_consumed += n;
        return true;
    }
    // An integer or floating value of the given PLY type, as a long long (floats truncated).
    bool value(char type, std::size_t bytes, long long& out) {
        std::array<unsigned char, 8> raw{};
        if (!read(raw.data(), bytes)) {
            return false;
        }
        switch (type) {
        case 'i': { // signed
            std::int64_t v = 0;
            std::memcpy(&v, raw.data(), 8);
            const int shift = static_cast<int>(64 - 8 * bytes);
            out = static_cast<long long>((v << shift) >> shift);
            return true;
        }
        case 'u': {
            std::uint64_t v = 0;
            std::memcpy(&v, raw.data(), 8);
            out = static_cast<long long>(v & (bytes == 8 ? ~0ull : ((1ull << (8 * bytes)) - 1)));
            return true;
        }
        default: { // a float or double used as a count or index: refused
            out = -1;
            return true;
        }
        }
    }
    bool atEnd() {
        if (m_begin < m_end) {
            return false;
        }
        unsigned char c = 0;
        return !read(&c, 1);
    }
    std::uint64_t consumed() const { return m_consumed; }

private:
    std::ifstream& m_in;
    bool m_bigEndian;
    std::array<unsigned char, 1 << 16> m_buffer{};
    std::size_t m_begin = 0;
    std::size_t m_end = 0;
    std::uint64_t m_consumed = 0;
};

struct PlyType {
    char kind = 0; // 'i' signed, 'u' unsigned, 'f' floating
    std::size_t bytes = 0;
};

std::optional<PlyType> plyType(std::string_view name) {
    static const std::map<std::string_view, PlyType> types{
        {"char", {'i', 1}},  {"int8", {'i', 1}},    {"uchar", {'u', 1}},  {"uint8", {'u', 1}},
        {"short", {'i', 2}}, {"int16", {'i', 2}},   {"ushort", {'u', 2}}, {"uint16", {'u', 2}},
        {"int", {'i', 4}},   {"int32", {'i', 4}},   {"uint", {'u', 4}},   {"uint32", {'u', 4}},
        {"float", {'f', 4}}, {"float32", {'f', 4}}, {"double", {'f', 8}}, {"float64", {'f', 8}}};
    const auto it = types.find(name);
    return it == types.end() ? std::nullopt : std::optional<PlyType>(it->second);
}

struct PlyProperty {
    std::string name;
    PlyType type;
    bool list = false;
    PlyType countType;
};

struct PlyElement {
    std::string name;
    std::uint64_t count = 0;
    std::vector<PlyProperty> properties;
};

} // namespace

// PLY: the header's elements and properties, then every element's records walked through,
// the face lists' indices checked against the number of vertices.
Error checkPly(const std::string& path, std::uint64_t size, ProgressTicker& progress,
               std::uint64_t& pointCount) {
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        return importProblem(Code::Unreadable);
    }
    std::string line;
    std::vector<std::string_view> fields;
    std::vector<PlyElement> elements;
    std::string format;
    int lines = 0;
    bool ended = false;
    while (std::getline(in, line)) {
        if (!line.empty() && line.back() == '\r') {
            line.pop_back();
        }
        if (++lines == 1) {
            if (line != "ply") {
                return importProblem(Code::Damaged, "it does not start with 'ply'");
            }
            continue;
        }
        if (line.size() > 4096 || lines > 10'000) {
            return importProblem(Code::Damaged, "its header is damaged");
        }
        splitFields(line, fields);
        if (fields.empty() || fields[0] == "comment" || fields[0] == "obj_info") {
            continue;
        }
        if (fields[0] == "end_header") {
            ended = true;
            break;
        }
        // As strict as OpenMesh's reader, which loops forever on some header it cannot parse.
        if (fields[0] == "format" && fields.size() == 3 && fields[2] == "1.0" && format.empty()) {
            format = std::string(fields[1]);
        } else if (fields[0] == "element" && fields.size() == 3) {
            long long count = 0;
            if (!parseInteger(fields[2], count) || count < 0) {
                return importProblem(Code::Damaged, "its header gives an invalid element count");
            }
            elements.push_back({std::string(fields[1]), static_cast<std::uint64_t>(count), {}});
        } else if (fields[0] == "property" && !elements.empty() && fields.size() == 3 &&
                   plyType(fields[1])) {
            elements.back().properties.push_back(
                {std::string(fields[2]), *plyType(fields[1]), false, {}});
        } else if (fields[0] == "property" && !elements.empty() && fields.size() == 5 &&
                   fields[1] == "list" && plyType(fields[2]) && plyType(fields[3]) &&
                   plyType(fields[2])->kind != 'f') {
            elements.back().properties.push_back(
                {std::string(fields[4]), *plyType(fields[3]), true, *plyType(fields[2])});
        } else {
            return importProblem(Code::Damaged,
                                 "its header line '" + line.substr(0, 60) + "' is not understood");
        }
    }
    if (!ended) {
        return importProblem(Code::Truncated, "its header does not end");
    }
    const bool ascii = format == "ascii";
    if (!ascii && format != "binary_little_endian" && format != "binary_big_endian") {
        return importProblem(Code::Damaged,
                             "its format '" + format.substr(0, 40) + "' is not known");
    }
    const auto vertex = std::find_if(elements.begin(), elements.end(),
                                     [](const PlyElement& e) { return e.name == "vertex"; });
    if (vertex == elements.end() || vertex->count == 0) {
        return importProblem(Code::NoPoints);
    }
    if (vertex != elements.begin()) {
        return importProblem(Code::Damaged, "its vertices are not its first element");
    }
    for (const char* axis : {"x", "y", "z"}) {
        if (std::none_of(vertex->properties.begin(), vertex->properties.end(),
                         [axis](const PlyProperty& p) { return !p.list && p.name == axis; })) {
            return importProblem(Code::Damaged, std::string("its vertices have no ") + axis);
        }
    }
    // Every record takes at least one byte per property (two in ASCII).
    std::uint64_t least = 0;
    for (const PlyElement& e : elements) {
        const std::uint64_t perRecord = std::max<std::size_t>(e.properties.size(), 1);
        if (e.count > size || e.count * perRecord > size) {
            return importProblem(Code::Damaged, "it announces " + std::to_string(e.count) + " " +
                                                    e.name.substr(0, 40) +
                                                    " elements, more than the file can hold");
        }
        least += e.count * perRecord;
    }
    if (least > size) {
        return importProblem(Code::Damaged, "its header announces more than the file can hold");
    }
    if (vertex->count > kMaxReferencePoints) {
        return importProblem(Code::TooLarge, std::to_string(vertex->count) + " points");
    }
    const std::uint64_t points = vertex->count;
    pointCount = points;
    std::uint64_t triangles = 0;
    std::uint64_t done = 0;
    auto faceCorner = [&](const PlyElement& e, const PlyProperty& p) {
        return e.name == "face" && (p.name == "vertex_indices" || p.name == "vertex_index");
    };
    if (ascii) {
        LineReader reader(path);
        std::string_view text;
        for (int i = 0; i < lines; ++i) {
            reader.next(text);
        }
        for (const PlyElement& e : elements) {
            for (std::uint64_t r = 0; r < e.count; ++r) {
                if (!reader.next(text)) {
                    return importProblem(Code::Truncated, "it holds " + std::to_string(r) + " of " +
                                                              std::to_string(e.count) + " " +
                                                              e.name.substr(0, 40) + " elements");
                }
                splitFields(text, fields);
                std::size_t at = 0;
                for (const PlyProperty& p : e.properties) {
                    long long n = 1;
                    if (p.list) {
                        if (at >= fields.size() || !parseInteger(fields[at], n) || n < 0) {
                            return importProblem(reader.lineWasEnded() ? Code::Damaged
                                                                       : Code::Truncated,
                                                 lineText(reader.lineNumber()) + " is damaged");
                        }
                        ++at;
                        if (faceCorner(e, p)) {
                            if (n < 3) {
                                return importProblem(Code::BadFaces,
                                                     lineText(reader.lineNumber()) +
                                                         " has a face of fewer than three corners");
                            }
                            triangles += static_cast<std::uint64_t>(n - 2);
                        }
                    }
                    for (long long k = 0; k < n; ++k, ++at) {
                        double value = 0.0;
                        if (at >= fields.size() || !parseNumber(fields[at], value)) {
                            return importProblem(reader.lineWasEnded() ? Code::Damaged
                                                                       : Code::Truncated,
                                                 lineText(reader.lineNumber()) + " is damaged");
                        }
                        if (p.list && faceCorner(e, p) &&
                            (value < 0 || value >= static_cast<double>(points) ||
                             value != std::floor(value))) {
                            return importProblem(
                                Code::BadFaces,
                                lineText(reader.lineNumber()) +
                                    ": a face names a point the file does not have");
                        }
                    }
                }
                if (at != fields.size()) {
                    return importProblem(Code::Damaged, lineText(reader.lineNumber()) +
                                                            " does not fit the header");
                }
                if ((++done & 0x3FFF) == 0 && !progress.at(static_cast<double>(reader.bytesRead()) /
                                                           static_cast<double>(size))) {
                    return importProblem(Code::Cancelled);
                }
            }
        }
    } else {
        BinaryInput input(in, format == "binary_big_endian");
        std::array<unsigned char, 8> skip{};
        for (const PlyElement& e : elements) {
            for (std::uint64_t r = 0; r < e.count; ++r) {
                for (const PlyProperty& p : e.properties) {
                    long long n = 1;
                    if (p.list) {
                        if (!input.value(p.countType.kind, p.countType.bytes, n)) {
                            return importProblem(Code::Truncated, "its " + e.name.substr(0, 40) +
                                                                      " elements end early");
                        }
                        if (n < 0 || n > 1'000'000) {
                            return importProblem(Code::Damaged, "it holds a list of " +
                                                                    std::to_string(n) + " values");
                        }
                        if (faceCorner(e, p)) {
                            if (n < 3 || p.type.kind == 'f') {
                                return importProblem(Code::BadFaces,
                                                     "face " + std::to_string(r) +
                                                         " is not a polygon of points");
                            }
                            triangles += static_cast<std::uint64_t>(n - 2);
                        }
                    }
                    for (long long k = 0; k < n; ++k) {
                        long long index = 0;
                        const bool ok = p.list && faceCorner(e, p)
                                            ? input.value(p.type.kind, p.type.bytes, index)
                                            : input.read(skip.data(), p.type.bytes);
                        if (!ok) {
                            return importProblem(Code::Truncated, "its " + e.name.substr(0, 40) +
                                                                      " elements end early");
                        }
                        if (p.list && faceCorner(e, p) &&
                            (index < 0 || static_cast<std::uint64_t>(index) >= points)) {
                            return importProblem(Code::BadFaces,
                                                 "face " + std::to_string(r) + " names point " +
                                                     std::to_string(index) + " of " +
                                                     std::to_string(points));
                        }
                    }
                }
                if ((++done & 0x3FFF) == 0 && !progress.at(static_cast<double>(input.consumed()) /
                                                           static_cast<double>(size))) {
                    return importProblem(Code::Cancelled);
                }
            }
        }
        if (!input.atEnd()) {
            return importProblem(Code::Damaged, "it holds data after its last element");
        }
    }
    if (triangles > kMaxReferenceTriangles) {
        return importProblem(Code::TooLarge, std::to_string(triangles) + " triangles");
    }
    return std::nullopt;
}

} // namespace devsurf::io::reference
