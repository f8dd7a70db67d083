// The structural check of mesh files before OpenMesh reads them: OpenMesh's readers trust the
// counts in headers and the indices in faces, so a damaged file could make them allocate
// without bound or index out of range. Whatever passes here has counts the file can hold and
// faces that name existing points.

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

Error problem(Code code, std::string detail = {}) {
    return ReferenceImportError{code, std::move(detail)};
}

bool ticks(LineReader& reader, ProgressTicker& progress, std::uint64_t size) {
    return (reader.lineNumber() & 0x3FFF) != 0 ||
           progress.at(static_cast<double>(reader.bytesRead()) / static_cast<double>(size));
}

// An OBJ index (1-based, or negative counting back from the last element read) into `count`
// elements.
bool objIndexFits(std::string_view field, std::uint64_t count) {
    long long index = 0;
    if (!parseInteger(field, index) || index == 0) {
        return false;
    }
    return index > 0 ? static_cast<std::uint64_t>(index) <= count
                     : static_cast<std::uint64_t>(-(index + 1)) < count;
}

// The 0-based element an OBJ index that fits names.
std::uint64_t objIndex(std::string_view field, std::uint64_t count) {
    long long index = 0;
    parseInteger(field, index);
    return index > 0 ? static_cast<std::uint64_t>(index - 1)
                     : count - static_cast<std::uint64_t>(-index);
}

// Also gathers the normal of every point from the faces' "v//n" corners (the first one named
// for it): OpenMesh leaves a point's normal uninitialised where no face names one.
Error checkObj(const std::string& path, std::uint64_t size, ProgressTicker& progress,
               std::uint64_t& points, std::vector<model::Vec3>& pointNormals) {
    LineReader reader(path);
    if (!reader.isOpen()) {
        return problem(Code::Unreadable);
    }
    std::uint64_t texture = 0;
    std::uint64_t normals = 0;
    std::uint64_t triangles = 0;
    std::vector<model::Vec3> normalList;
    std::vector<std::int64_t> normalOfPoint; // index into normalList, -1 for none
    std::vector<std::string_view> fields;
    std::string_view line;
    while (reader.next(line)) {
        if (!ticks(reader, progress, size)) {
            return problem(Code::Cancelled);
        }
        splitFields(line, fields);
        if (fields.empty()) {
            continue;
        }
        if (fields[0] == "v") {
            // OpenMesh skips a vertex it cannot read, which would renumber every later one.
            model::Vec3 p;
            if (fields.size() < 4 || !parseNumber(fields[1], p.x) || !parseNumber(fields[2], p.y) ||
                !parseNumber(fields[3], p.z)) {
                return problem(reader.lineWasEnded() ? Code::Damaged : Code::Truncated,
                               lineText(reader.lineNumber()) + " is not a point");
            }
            if (!isSane(p)) {
                return problem(Code::NotANumber, lineText(reader.lineNumber()));
            }
            normalOfPoint.push_back(-1);
            if (++points > kMaxReferencePoints) {
                return problem(Code::TooLarge,
                               "more than " + std::to_string(kMaxReferencePoints) + " points");
            }
        } else if (fields[0] == "vt" || fields[0] == "vn") {
            // Likewise a normal: OpenMesh keeps an uninitialised one for a line it cannot read.
            const bool normal = fields[0] == "vn";
            model::Vec3 v;
            const bool read = normal
                                  ? fields.size() >= 4 && parseNumber(fields[1], v.x) &&
                                        parseNumber(fields[2], v.y) && parseNumber(fields[3], v.z)
                                  : fields.size() >= 2 && parseNumber(fields[1], v.x) &&
                                        (fields.size() < 3 || parseNumber(fields[2], v.y));
            if (!read) {
                return problem(reader.lineWasEnded() ? Code::Damaged : Code::Truncated,
                               lineText(reader.lineNumber()) + " is not a " +
                                   (normal ? "normal" : "texture coordinate"));
            }
            if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z)) {
                return problem(Code::NotANumber, lineText(reader.lineNumber()));
            }
            ++(normal ? normals : texture);
            if (normal) {
                normalList.push_back(v);
            }
        } else if (fields[0] == "f") {
            if (fields.size() < 4) {
                return problem(reader.lineWasEnded() ? Code::BadFaces : Code::Truncated,
                               lineText(reader.lineNumber()) + " has a face of fewer than three "
                                                               "corners");
            }
            for (std::size_t i = 1; i < fields.size(); ++i) {
                // v, v/t, v//n or v/t/n
                std::array<std::string_view, 3> parts{};
                std::string_view rest = fields[i];
                for (std::size_t k = 0; k < 3; ++k) {
                    const std::size_t slash = rest.find('/');
                    parts[k] = rest.substr(0, slash);
                    if (slash == std::string_view::npos) {
                        rest = {};
                        break;
                    }
                    rest = rest.substr(slash + 1);
                }
                if (!rest.empty() || !objIndexFits(parts[0], points) ||
                    (!parts[1].empty() && !objIndexFits(parts[1], texture)) ||
                    (!parts[2].empty() && !objIndexFits(parts[2], normals))) {
                    return problem(Code::BadFaces, lineText(reader.lineNumber()) + ": '" +
                                                       std::string(fields[i].substr(0, 40)) +
                                                       "' names no point of the file");
                }
                if (!parts[2].empty()) {
                    const std::uint64_t point = objIndex(parts[0], points);
                    if (normalOfPoint[point] < 0) {
                        normalOfPoint[point] =
                            static_cast<std::int64_t>(objIndex(parts[2], normals));
                    }
                }
            }
            triangles += fields.size() - 3;
            if (triangles > kMaxReferenceTriangles) {
                return problem(Code::TooLarge, "more than " +
                                                   std::to_string(kMaxReferenceTriangles) +
                                                   " triangles");
            }
        }
    }
    if (reader.tooLong()) {
        return problem(Code::Damaged, lineText(reader.lineNumber() + 1) + " is too long");
    }
    if (!normalOfPoint.empty() && std::all_of(normalOfPoint.begin(), normalOfPoint.end(),
                                              [](std::int64_t n) { return n >= 0; })) {
        pointNormals.reserve(normalOfPoint.size());
        for (std::int64_t n : normalOfPoint) {
            pointNormals.push_back(normalList[static_cast<std::size_t>(n)]);
        }
    }
    return std::nullopt;
}

// ASCII STL, line by line: solid, then per facet "facet normal", "outer loop", three
// "vertex x y z", "endloop", "endfacet", and "endsolid". OpenMesh's reader keeps whatever it
// finds in a line it cannot read (an uninitialised point), so every line is checked here.
Error checkStlText(const std::string& path, std::uint64_t size, ProgressTicker& progress) {
    LineReader reader(path);
    if (!reader.isOpen()) {
        return problem(Code::Unreadable);
    }
    enum class In { Nothing, Solid, Facet, Loop, LoopDone };
    In state = In::Nothing;
    int corners = 0;
    std::uint64_t triangles = 0;
    std::vector<std::string_view> fields;
    std::string_view line;
    auto numbers = [&fields](std::size_t from, model::Vec3& p) {
        return fields.size() == from + 3 && parseNumber(fields[from], p.x) &&
               parseNumber(fields[from + 1], p.y) && parseNumber(fields[from + 2], p.z);
    };
    while (reader.next(line)) {
        if (!ticks(reader, progress, size)) {
            return problem(Code::Cancelled);
        }
        splitFields(line, fields);
        if (fields.empty()) {
            continue;
        }
        const std::string_view word = fields[0];
        model::Vec3 p;
        bool fits = false;
        if (state == In::Nothing) {
            fits = word == "solid";
            state = In::Solid;
        } else if (state == In::Solid && word == "facet") {
            fits = fields.size() >= 2 && fields[1] == "normal" && numbers(2, p);
            state = In::Facet;
        } else if (state == In::Solid && word == "endsolid") {
            fits = true;
            state = In::Nothing;
        } else if (state == In::Facet) {
            fits = word == "outer" && fields.size() == 2 && fields[1] == "loop";
            state = In::Loop;
            corners = 0;
        } else if (state == In::Loop && word == "vertex") {
            fits = numbers(1, p) && ++corners <= 3;
            if (fits && !isSane(p)) {
                return problem(Code::NotANumber, lineText(reader.lineNumber()));
            }
        } else if (state == In::Loop && word == "endloop") {
            fits = corners == 3 && fields.size() == 1;
            state = In::LoopDone;
        } else if (state == In::LoopDone) {
            fits = word == "endfacet" && fields.size() == 1;
            state = In::Solid;
            if (++triangles > kMaxReferenceTriangles) {
                return problem(Code::TooLarge, "more than " +
                                                   std::to_string(kMaxReferenceTriangles) +
                                                   " triangles");
            }
        }
        if (!fits) {
            return problem(reader.lineWasEnded() ? Code::Damaged : Code::Truncated,
                           lineText(reader.lineNumber()) + " is not what an STL file holds there");
        }
    }
    if (reader.tooLong()) {
        return problem(Code::Damaged, lineText(reader.lineNumber() + 1) + " is too long");
    }
    if (state != In::Nothing) {
        return problem(Code::Truncated, "it does not end with 'endsolid'");
    }
    return triangles == 0 ? problem(Code::NoPoints) : std::nullopt;
}

// Binary STL: an 80-byte header, the triangle count, 50 bytes per triangle, and nothing else.
// ASCII STL: "solid" … "endsolid".
Error checkStl(const std::string& path, std::uint64_t size, ProgressTicker& progress) {
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        return problem(Code::Unreadable);
    }
    std::array<unsigned char, 84> head{};
    in.read(reinterpret_cast<char*>(head.data()), static_cast<std::streamsize>(head.size()));
    const auto got = static_cast<std::size_t>(in.gcount());
    std::uint64_t triangles = 0;
    for (int i = 0; i < 4; ++i) {
        triangles |= static_cast<std::uint64_t>(head[80 + static_cast<std::size_t>(i)]) << (8 * i);
    }
    if (got == head.size() && size == 84 + 50 * triangles) {
        if (triangles == 0) {
            return problem(Code::NoPoints);
        }
        if (triangles > kMaxReferenceTriangles) {
            return problem(Code::TooLarge, std::to_string(triangles) + " triangles");
        }
        return std::nullopt;
    }
    const std::string start(reinterpret_cast<const char*>(head.data()), got);
    const std::size_t first = start.find_first_not_of(" \t\r\n");
    if (first == std::string::npos || start.compare(first, 5, "solid") != 0) {
        if (got < head.size() || size < 84 + 50 * triangles) {
            return problem(Code::Truncated, "it holds fewer bytes than its " +
                                                std::to_string(triangles) + " triangles need");
        }
        return problem(Code::Damaged, "it holds more bytes than its " + std::to_string(triangles) +
                                          " triangles need");
    }
    in.close();
    return checkStlText(path, size, progress);
}

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

// PLY: the header's elements and properties, then every element's records walked through,
// the face lists' indices checked against the number of vertices.
Error checkPly(const std::string& path, std::uint64_t size, ProgressTicker& progress,
               std::uint64_t& pointCount) {
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        return problem(Code::Unreadable);
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
                return problem(Code::Damaged, "it does not start with 'ply'");
            }
            continue;
        }
        if (line.size() > 4096 || lines > 10'000) {
            return problem(Code::Damaged, "its header is damaged");
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
                return problem(Code::Damaged, "its header gives an invalid element count");
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
            return problem(Code::Damaged,
                           "its header line '" + line.substr(0, 60) + "' is not understood");
        }
    }
    if (!ended) {
        return problem(Code::Truncated, "its header does not end");
    }
    const bool ascii = format == "ascii";
    if (!ascii && format != "binary_little_endian" && format != "binary_big_endian") {
        return problem(Code::Damaged, "its format '" + format.substr(0, 40) + "' is not known");
    }
    const auto vertex = std::find_if(elements.begin(), elements.end(),
                                     [](const PlyElement& e) { return e.name == "vertex"; });
    if (vertex == elements.end() || vertex->count == 0) {
        return problem(Code::NoPoints);
    }
    if (vertex != elements.begin()) {
        return problem(Code::Damaged, "its vertices are not its first element");
    }
    for (const char* axis : {"x", "y", "z"}) {
        if (std::none_of(vertex->properties.begin(), vertex->properties.end(),
                         [axis](const PlyProperty& p) { return !p.list && p.name == axis; })) {
            return problem(Code::Damaged, std::string("its vertices have no ") + axis);
        }
    }
    // Every record takes at least one byte per property (two in ASCII).
    std::uint64_t least = 0;
    for (const PlyElement& e : elements) {
        const std::uint64_t perRecord = std::max<std::size_t>(e.properties.size(), 1);
        if (e.count > size || e.count * perRecord > size) {
            return problem(Code::Damaged, "it announces " + std::to_string(e.count) + " " +
                                              e.name.substr(0, 40) +
                                              " elements, more than the file can hold");
        }
        least += e.count * perRecord;
    }
    if (least > size) {
        return problem(Code::Damaged, "its header announces more than the file can hold");
    }
    if (vertex->count > kMaxReferencePoints) {
        return problem(Code::TooLarge, std::to_string(vertex->count) + " points");
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
                    return problem(Code::Truncated, "it holds " + std::to_string(r) + " of " +
                                                        std::to_string(e.count) + " " +
                                                        e.name.substr(0, 40) + " elements");
                }
                splitFields(text, fields);
                std::size_t at = 0;
                for (const PlyProperty& p : e.properties) {
                    long long n = 1;
                    if (p.list) {
                        if (at >= fields.size() || !parseInteger(fields[at], n) || n < 0) {
                            return problem(reader.lineWasEnded() ? Code::Damaged : Code::Truncated,
                                           lineText(reader.lineNumber()) + " is damaged");
                        }
                        ++at;
                        if (faceCorner(e, p)) {
                            if (n < 3) {
                                return problem(Code::BadFaces,
                                               lineText(reader.lineNumber()) +
                                                   " has a face of fewer than three corners");
                            }
                            triangles += static_cast<std::uint64_t>(n - 2);
                        }
                    }
                    for (long long k = 0; k < n; ++k, ++at) {
                        double value = 0.0;
                        if (at >= fields.size() || !parseNumber(fields[at], value)) {
                            return problem(reader.lineWasEnded() ? Code::Damaged : Code::Truncated,
                                           lineText(reader.lineNumber()) + " is damaged");
                        }
                        if (p.list && faceCorner(e, p) &&
                            (value < 0 || value >= static_cast<double>(points) ||
                             value != std::floor(value))) {
                            return problem(Code::BadFaces,
                                           lineText(reader.lineNumber()) +
                                               ": a face names a point the file does not have");
                        }
                    }
                }
                if (at != fields.size()) {
                    return problem(Code::Damaged,
                                   lineText(reader.lineNumber()) + " does not fit the header");
                }
                if ((++done & 0x3FFF) == 0 && !progress.at(static_cast<double>(reader.bytesRead()) /
                                                           static_cast<double>(size))) {
                    return problem(Code::Cancelled);
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
                            return problem(Code::Truncated,
                                           "its " + e.name.substr(0, 40) + " elements end early");
                        }
                        if (n < 0 || n > 1'000'000) {
                            return problem(Code::Damaged,
                                           "it holds a list of " + std::to_string(n) + " values");
                        }
                        if (faceCorner(e, p)) {
                            if (n < 3 || p.type.kind == 'f') {
                                return problem(Code::BadFaces, "face " + std::to_string(r) +
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
                            return problem(Code::Truncated,
                                           "its " + e.name.substr(0, 40) + " elements end early");
                        }
                        if (p.list && faceCorner(e, p) &&
                            (index < 0 || static_cast<std::uint64_t>(index) >= points)) {
                            return problem(Code::BadFaces, "face " + std::to_string(r) +
                                                               " names point " +
                                                               std::to_string(index) + " of " +
                                                               std::to_string(points));
                        }
                    }
                }
                if ((++done & 0x3FFF) == 0 && !progress.at(static_cast<double>(input.consumed()) /
                                                           static_cast<double>(size))) {
                    return problem(Code::Cancelled);
                }
            }
        }
        if (!input.atEnd()) {
            return problem(Code::Damaged, "it holds data after its last element");
        }
    }
    if (triangles > kMaxReferenceTriangles) {
        return problem(Code::TooLarge, std::to_string(triangles) + " triangles");
    }
    return std::nullopt;
}

} // namespace

MeshCheck checkMeshFile(const std::string& path, ReferenceFormat format, std::uint64_t size,
                        ProgressTicker& progress) {
    MeshCheck check;
    switch (format) {
    case ReferenceFormat::Obj:
        check.error = checkObj(path, size, progress, check.points, check.normals);
        break;
    case ReferenceFormat::Ply:
        check.error = checkPly(path, size, progress, check.points);
        break;
    case ReferenceFormat::Stl:
        check.error = checkStl(path, size, progress);
        break;
    case ReferenceFormat::Off:
    case ReferenceFormat::Xyz:
    case ReferenceFormat::Pts:
        break;
    }
    return check;
}

} // namespace devsurf::io::reference
