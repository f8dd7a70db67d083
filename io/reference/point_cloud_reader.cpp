#include "line_reader.h"
#include "reference_readers.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace devsurf::io::reference {

namespace {

using Code = ReferenceImportError::Code;

bool isCloudComment(std::string_view line) {
    const std::size_t at = line.find_first_not_of(" \t");
    return at == std::string_view::npos || line[at] == '#' || line.substr(at, 2) == "//";
}

} // namespace

// One point per line: x y z, optionally nx ny nz. A PTS file may start with the number of
// points and carry more columns (intensity, r g b): the first three are the point, and with
// exactly six the last three its normal. Every point line has as many numbers as the first.
ReferenceImportResult readPointCloud(const std::string& path, ReferenceFormat format,
                                     std::uint64_t size, ProgressTicker& progress) {
    LineReader reader(path);
    if (!reader.isOpen()) {
        return failure(Code::Unreadable);
    }
    model::ReferenceShape shape;
    std::vector<std::string_view> fields;
    std::vector<double> values;
    std::size_t columns = 0;
    std::optional<std::uint64_t> announced;
    std::string_view line;
    // The shortest point line is "0 0 0\n".
    const std::uint64_t mostPoints = size / 6 + 1;
    while (reader.next(line)) {
        if ((reader.lineNumber() & 0xFFFF) == 0 &&
            !progress.at(static_cast<double>(reader.bytesRead()) / static_cast<double>(size))) {
            return failure(Code::Cancelled);
        }
        if (isCloudComment(line)) {
            continue;
        }
        splitFields(line, fields);
        const bool last = !reader.lineWasEnded();
        if (format == ReferenceFormat::Pts && fields.size() == 1 && columns == 0 && !announced) {
            long long count = 0;
            if (!parseInteger(fields[0], count) || count < 0) {
                return failure(Code::Damaged,
                               lineText(reader.lineNumber()) + " is neither a count nor a point");
            }
            if (static_cast<std::uint64_t>(count) > mostPoints) {
                return failure(Code::Damaged, "it announces " + std::to_string(count) +
                                                  " points, more than the file can hold");
            }
            if (static_cast<std::uint64_t>(count) > kMaxReferencePoints) {
                return failure(Code::TooLarge, std::to_string(count) + " points");
            }
            announced = static_cast<std::uint64_t>(count);
            shape.points.reserve(static_cast<std::size_t>(count));
            continue;
        }
        values.resize(fields.size());
        for (std::size_t i = 0; i < fields.size(); ++i) {
            if (!parseNumber(fields[i], values[i])) {
                return failure(last ? Code::Truncated : Code::Damaged,
                               lineText(reader.lineNumber()) + ": '" +
                                   std::string(fields[i].substr(0, 40)) + "' is not a number");
            }
        }
        if (columns == 0) {
            if (values.size() < 3) {
                return failure(last ? Code::Truncated : Code::Damaged,
                               lineText(reader.lineNumber()) + " has fewer than three numbers");
            }
            columns = values.size();
            if (!announced) {
                // Room for every point the file could hold at this line's length.
                const std::uint64_t estimate = size / std::max<std::size_t>(line.size() + 1, 6);
                shape.points.reserve(static_cast<std::size_t>(
                    std::min<std::uint64_t>(estimate + 16, kMaxReferencePoints)));
            }
            if (columns == 6) {
                shape.normals.reserve(shape.points.capacity());
            }
        } else if (values.size() != columns) {
            return failure(last ? Code::Truncated : Code::Damaged,
                           lineText(reader.lineNumber()) + " has " + std::to_string(values.size()) +
                               " numbers where the first point had " + std::to_string(columns));
        }
        const model::Vec3 point(values[0], values[1], values[2]);
        if (!isSane(point)) {
            return failure(Code::NotANumber, lineText(reader.lineNumber()));
        }
        if (shape.points.size() == kMaxReferencePoints) {
            return failure(Code::TooLarge,
                           "more than " + std::to_string(kMaxReferencePoints) + " points");
        }
        shape.points.push_back(point);
        if (columns == 6) {
            const model::Vec3 normal(values[3], values[4], values[5]);
            if (!std::isfinite(normal.x) || !std::isfinite(normal.y) || !std::isfinite(normal.z)) {
                return failure(Code::NotANumber, lineText(reader.lineNumber()) + " (its normal)");
            }
            shape.normals.push_back(normal);
        }
    }
    if (reader.tooLong()) {
        return failure(Code::Damaged, lineText(reader.lineNumber() + 1) + " is too long");
    }
    if (announced && shape.points.size() != *announced) {
        return failure(shape.points.size() < *announced ? Code::Truncated : Code::Damaged,
                       "it announces " + std::to_string(*announced) + " points and holds " +
                           std::to_string(shape.points.size()));
    }
    if (shape.points.empty()) {
        return failure(Code::NoPoints);
    }
    shape.points.shrink_to_fit();
    shape.normals.shrink_to_fit();
    ReferenceImportResult result;
    result.shape = std::move(shape);
    return result;
}

} // namespace devsurf::io::reference
