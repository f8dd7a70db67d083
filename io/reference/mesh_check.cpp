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
        return importProblem(Code::Unreadable);
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
            return importProblem(Code::Cancelled);
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
                return importProblem(reader.lineWasEnded() ? Code::Damaged : Code::Truncated,
                                     lineText(reader.lineNumber()) + " is not a point");
            }
            if (!isSane(p)) {
                return importProblem(Code::NotANumber, lineText(reader.lineNumber()));
            }
            normalOfPoint.push_back(-1);
            if (++points > kMaxReferencePoints) {
                return importProblem(
                    Code::TooLarge, "more than " + std::to_string(kMaxReferencePoints) + " points");
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
                return importProblem(reader.lineWasEnded() ? Code::Damaged : Code::Truncated,
                                     lineText(reader.lineNumber()) + " is not a " +
                                         (normal ? "normal" : "texture coordinate"));
            }
            if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z)) {
                return importProblem(Code::NotANumber, lineText(reader.lineNumber()));
            }
            ++(normal ? normals : texture);
            if (normal) {
                normalList.push_back(v);
            }
        } else if (fields[0] == "f") {
            if (fields.size() < 4) {
                return importProblem(reader.lineWasEnded() ? Code::BadFaces : Code::Truncated,
                                     lineText(reader.lineNumber()) +
                                         " has a face of fewer than three "
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
                    return importProblem(Code::BadFaces, lineText(reader.lineNumber()) + ": '" +
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
                return importProblem(Code::TooLarge, "more than " +
                                                         std::to_string(kMaxReferenceTriangles) +
                                                         " triangles");
            }
        }
    }
    if (reader.tooLong()) {
        return importProblem(Code::Damaged, lineText(reader.lineNumber() + 1) + " is too long");
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
        return importProblem(Code::Unreadable);
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
            return importProblem(Code::Cancelled);
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
                return importProblem(Code::NotANumber, lineText(reader.lineNumber()));
            }
        } else if (state == In::Loop && word == "endloop") {
            fits = corners == 3 && fields.size() == 1;
            state = In::LoopDone;
        } else if (state == In::LoopDone) {
            fits = word == "endfacet" && fields.size() == 1;
            state = In::Solid;
            if (++triangles > kMaxReferenceTriangles) {
                return importProblem(Code::TooLarge, "more than " +
                                                         std::to_string(kMaxReferenceTriangles) +
                                                         " triangles");
            }
        }
        if (!fits) {
            return importProblem(reader.lineWasEnded() ? Code::Damaged : Code::Truncated,
                                 lineText(reader.lineNumber()) +
                                     " is not what an STL file holds there");
        }
    }
    if (reader.tooLong()) {
        return importProblem(Code::Damaged, lineText(reader.lineNumber() + 1) + " is too long");
    }
    if (state != In::Nothing) {
        return importProblem(Code::Truncated, "it does not end with 'endsolid'");
    }
    return triangles == 0 ? importProblem(Code::NoPoints) : std::nullopt;
}

// Binary STL: an 80-byte header, the triangle count, 50 bytes per triangle, and nothing else.
// ASCII STL: "solid" … "endsolid".
Error checkStl(const std::string& path, std::uint64_t size, ProgressTicker& progress) {
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        return importProblem(Code::Unreadable);
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
            return importProblem(Code::NoPoints);
        }
        if (triangles > kMaxReferenceTriangles) {
            return importProblem(Code::TooLarge, std::to_string(triangles) + " triangles");
        }
        return std::nullopt;
    }
    const std::string start(reinterpret_cast<const char*>(head.data()), got);
    const std::size_t first = start.find_first_not_of(" \t\r\n");
    if (first == std::string::npos || start.compare(first, 5, "solid") != 0) {
        if (got < head.size() || size < 84 + 50 * triangles) {
            return importProblem(Code::Truncated, "it holds fewer bytes than its " +
                                                      std::to_string(triangles) +
                                                      " triangles need");
        }
        return importProblem(Code::Damaged, "it holds more bytes than its " +
                                                std::to_string(triangles) + " triangles need");
    }
    in.close();
    return checkStlText(path, size, progress);
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
