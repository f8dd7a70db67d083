// OFF is read here rather than by OpenMesh: OpenMesh's reader takes neither comments nor the
// counts on the header line, and reads a file with a comment after the counts as a different
// mesh, so its faces could not be trusted to name the right points.

#include "line_reader.h"
#include "reference_readers.h"

#include <algorithm>
#include <array>

namespace devsurf::io::reference {

namespace {

using Code = ReferenceImportError::Code;

bool isOffComment(std::string_view line) {
    const std::size_t at = line.find_first_not_of(" \t");
    return at == std::string_view::npos || line[at] == '#';
}

} // namespace

// ASCII OFF: a header ([ST][C][N]OFF, perhaps followed by the counts), the counts "points
// faces edges", one line per point (x y z, then perhaps a normal or a colour), one per face
// ("k i1 … ik", then perhaps a colour); comments from # to the end of a line. Polygons become
// triangle fans.
ReferenceImportResult readOffFile(const std::string& path, std::uint64_t size,
                                  ProgressTicker& progress) {
    LineReader reader(path);
    if (!reader.isOpen()) {
        return failure(Code::Unreadable);
    }
    std::vector<std::string_view> fields;
    std::string_view line;
    auto nextLine = [&]() {
        while (reader.next(line)) {
            if (!isOffComment(line)) {
                splitFields(line.substr(0, line.find('#')), fields);
                return true;
            }
        }
        return false;
    };
    if (!nextLine()) {
        return failure(reader.tooLong() ? Code::Damaged : Code::NoPoints);
    }
    const std::string_view header = fields[0];
    static const std::array<std::string_view, 8> headers{"OFF",   "COFF",   "NOFF",   "CNOFF",
                                                         "STOFF", "STCOFF", "STNOFF", "STCNOFF"};
    if (std::find(headers.begin(), headers.end(), header) == headers.end()) {
        return failure(Code::Damaged, header.find("OFF") == std::string_view::npos
                                          ? "it does not start with OFF"
                                          : "only OFF files of three dimensions are read");
    }
    const bool normals = header.find('N') != std::string_view::npos;
    if (fields.size() > 1 && fields[1] == "BINARY") {
        return failure(Code::Damaged, "binary OFF files are not read; save it as ASCII OFF");
    }
    std::vector<std::string_view> counts(fields.begin() + 1, fields.end());
    std::string countLine;
    if (counts.empty()) {
        if (!nextLine()) {
            return failure(Code::Truncated, "the counts are missing");
        }
        counts = fields;
    }
    long long points = 0;
    long long faces = 0;
    if (counts.size() < 2 || !parseInteger(counts[0], points) || !parseInteger(counts[1], faces) ||
        points < 0 || faces < 0) {
        return failure(Code::Damaged, lineText(reader.lineNumber()) +
                                          " does not hold the numbers of points and faces");
    }
    // A point takes at least "0 0 0\n", a face "3 0 1 2\n".
    if (static_cast<std::uint64_t>(points) > size / 6 ||
        static_cast<std::uint64_t>(faces) > size / 8) {
        return failure(Code::Damaged, "it announces " + std::to_string(points) + " points and " +
                                          std::to_string(faces) +
                                          " faces, more than the file can hold");
    }
    if (static_cast<std::uint64_t>(points) > kMaxReferencePoints) {
        return failure(Code::TooLarge, std::to_string(points) + " points");
    }
    if (points == 0) {
        return failure(Code::NoPoints);
    }
    model::ReferenceShape shape;
    shape.points.reserve(static_cast<std::size_t>(points));
    if (normals) {
        shape.normals.reserve(static_cast<std::size_t>(points));
    }
    const std::size_t least = normals ? 6 : 3;
    auto tick = [&]() {
        return (reader.lineNumber() & 0x3FFF) != 0 ||
               progress.at(static_cast<double>(reader.bytesRead()) / static_cast<double>(size));
    };
    for (long long i = 0; i < points; ++i) {
        if (!nextLine()) {
            return failure(reader.tooLong() ? Code::Damaged : Code::Truncated,
                           "it holds " + std::to_string(i) + " of " + std::to_string(points) +
                               " points");
        }
        std::array<double, 6> v{};
        for (std::size_t k = 0; k < least; ++k) {
            if (k >= fields.size() || !parseNumber(fields[k], v[k])) {
                return failure(reader.lineWasEnded() ? Code::Damaged : Code::Truncated,
                               lineText(reader.lineNumber()) + " is not a point");
            }
        }
        shape.points.emplace_back(v[0], v[1], v[2]);
        if (!isSane(shape.points.back())) {
            return failure(Code::NotANumber, lineText(reader.lineNumber()));
        }
        if (normals) {
            const model::Vec3 n(v[3], v[4], v[5]);
            if (!std::isfinite(n.x) || !std::isfinite(n.y) || !std::isfinite(n.z)) {
                return failure(Code::NotANumber, lineText(reader.lineNumber()) + " (its normal)");
            }
            shape.normals.push_back(n);
        }
        if (!tick()) {
            return failure(Code::Cancelled);
        }
    }
    shape.triangles.reserve(static_cast<std::size_t>(faces));
    std::vector<int> corners;
    for (long long i = 0; i < faces; ++i) {
        if (!nextLine()) {
            return failure(reader.tooLong() ? Code::Damaged : Code::Truncated,
                           "it holds " + std::to_string(i) + " of " + std::to_string(faces) +
                               " faces");
        }
        long long count = 0;
        if (!parseInteger(fields[0], count) || count < 3 ||
            static_cast<std::size_t>(count) + 1 > fields.size()) {
            return failure(reader.lineWasEnded() ? Code::BadFaces : Code::Truncated,
                           lineText(reader.lineNumber()) +
                               " is not a face of three or more corners");
        }
        corners.clear();
        for (long long k = 1; k <= count; ++k) {
            const std::string_view field = fields[static_cast<std::size_t>(k)];
            long long index = 0;
            if (!parseInteger(field, index) || index < 0 || index >= points) {
                return failure(Code::BadFaces, lineText(reader.lineNumber()) + ": corner '" +
                                                   std::string(field.substr(0, 40)) +
                                                   "' is not one of its " + std::to_string(points) +
                                                   " points");
            }
            corners.push_back(static_cast<int>(index));
        }
        if (shape.triangles.size() + corners.size() - 2 > kMaxReferenceTriangles) {
            return failure(Code::TooLarge,
                           "more than " + std::to_string(kMaxReferenceTriangles) + " triangles");
        }
        for (std::size_t k = 1; k + 1 < corners.size(); ++k) {
            shape.triangles.push_back({corners[0], corners[k], corners[k + 1]});
        }
        if (!tick()) {
            return failure(Code::Cancelled);
        }
    }
    if (reader.tooLong()) {
        return failure(Code::Damaged, lineText(reader.lineNumber() + 1) + " is too long");
    }
    ReferenceImportResult result;
    result.shape = std::move(shape);
    return result;
}

} // namespace devsurf::io::reference
