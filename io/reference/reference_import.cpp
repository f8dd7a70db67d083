#include "reference_import.h"

#include "reference_readers.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <new>
#include <system_error>

namespace devsurf::io {

namespace reference {

ReferenceImportResult failure(ReferenceImportError::Code code, std::string detail) {
    ReferenceImportResult result;
    result.error = ReferenceImportError{code, std::move(detail)};
    return result;
}

bool isSane(const model::Vec3& p) {
    return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z) &&
           std::abs(p.x) <= kMaxReferenceCoordinate && std::abs(p.y) <= kMaxReferenceCoordinate &&
           std::abs(p.z) <= kMaxReferenceCoordinate;
}

bool ProgressTicker::at(double fraction) {
    if (m_cancelled) {
        return false;
    }
    if (!m_progress) {
        return true;
    }
    const double overall = m_from + (m_to - m_from) * std::clamp(fraction, 0.0, 1.0);
    if (overall - m_last < 0.01 && overall < 1.0) {
        return true;
    }
    m_last = overall;
    m_cancelled = !m_progress(overall);
    return !m_cancelled;
}

} // namespace reference

std::optional<ReferenceFormat> referenceFormatOf(const std::string& path) {
    std::string suffix = std::filesystem::path(path).extension().string();
    std::transform(suffix.begin(), suffix.end(), suffix.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (suffix == ".obj") {
        return ReferenceFormat::Obj;
    }
    if (suffix == ".ply") {
        return ReferenceFormat::Ply;
    }
    if (suffix == ".stl") {
        return ReferenceFormat::Stl;
    }
    if (suffix == ".off") {
        return ReferenceFormat::Off;
    }
    if (suffix == ".xyz") {
        return ReferenceFormat::Xyz;
    }
    if (suffix == ".pts") {
        return ReferenceFormat::Pts;
    }
    return std::nullopt;
}

namespace {

using Code = ReferenceImportError::Code;

ReferenceImportResult read(const std::string& path, ReferenceFormat format, std::uint64_t size,
                           const ReferenceProgress& progress) {
    using namespace reference;
    if (format == ReferenceFormat::Xyz || format == ReferenceFormat::Pts) {
        ProgressTicker ticker(progress, 0.0, 1.0);
        ReferenceImportResult result = readPointCloud(path, format, size, ticker);
        if (!result.error && !ticker.at(1.0)) {
            return failure(Code::Cancelled);
        }
        return result;
    }
    if (format == ReferenceFormat::Off) {
        ProgressTicker ticker(progress, 0.0, 1.0);
        ReferenceImportResult result = readOffFile(path, size, ticker);
        if (!result.error && !ticker.at(1.0)) {
            return failure(Code::Cancelled);
        }
        return result;
    }
    // The check streams through the file; OpenMesh then reads it whole, without progress.
    ProgressTicker check(progress, 0.0, 0.5);
    if (!check.at(0.0)) {
        return failure(Code::Cancelled);
    }
    MeshCheck checked = checkMeshFile(path, format, size, check);
    if (checked.error) {
        return failure(checked.error->code, std::move(checked.error->detail));
    }
    if (!check.at(1.0)) {
        return failure(Code::Cancelled);
    }
    ReferenceImportResult result =
        readMeshFile(path, checked.points, format == ReferenceFormat::Ply);
    if (!result.error && format == ReferenceFormat::Obj) {
        result.shape.normals = std::move(checked.normals);
    }
    ProgressTicker done(progress, 0.95, 1.0);
    if (!result.error && !done.at(1.0)) {
        return failure(Code::Cancelled);
    }
    return result;
}

} // namespace

ReferenceImportResult readReferenceShape(const std::string& path,
                                         const ReferenceProgress& progress) {
    using reference::failure;
    const std::optional<ReferenceFormat> format = referenceFormatOf(path);
    if (!format) {
        return failure(Code::UnknownFormat);
    }
    std::error_code error;
    const std::filesystem::path file(path);
    if (!std::filesystem::is_regular_file(file, error)) {
        return failure(Code::Unreadable, "it does not exist or is not a file");
    }
    const std::uintmax_t size = std::filesystem::file_size(file, error);
    if (error) {
        return failure(Code::Unreadable, error.message());
    }
    if (size > kMaxReferenceFileSize) {
        return failure(Code::TooLarge);
    }
    if (size == 0) {
        return failure(Code::NoPoints);
    }
    ReferenceImportResult result;
    try {
        result = read(path, *format, size, progress);
    } catch (const std::bad_alloc&) {
        return failure(Code::TooLarge, "there is not enough memory");
    }
    if (result.error) {
        result.shape = {};
        return result;
    }
    if (result.shape.points.size() > kMaxReferencePoints) {
        return failure(Code::TooLarge, std::to_string(result.shape.points.size()) + " points");
    }
    result.shape.name = file.stem().string();
    result.shape.source = file.filename().string();
    return result;
}

} // namespace devsurf::io
