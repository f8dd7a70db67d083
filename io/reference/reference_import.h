#pragma once

// Reference shapes from other programs' files: meshes (OBJ, PLY and STL read by OpenMesh after
// our own structural check; OFF read here) and point clouds (XYZ, PTS). Every reader returns the
// shape in mm or a typed error; none throws, and no input, however damaged, may crash it. The
// command line and the application word the errors.

#include "model/reference_shape.h"

#include <cstdint>
#include <functional>
#include <optional>
#include <string>

namespace devsurf::io {

enum class ReferenceFormat { Obj, Ply, Stl, Off, Xyz, Pts };

struct ReferenceImportError {
    enum class Code {
        UnknownFormat, // the extension is none of .obj, .ply, .stl, .off, .xyz, .pts
        Unreadable,    // the file cannot be opened or read
        TooLarge,      // larger than kMaxReferenceFileSize, or more points or triangles than
                       // the limits below
        Damaged,       // the contents do not follow the format (a header count larger than
                       // the file could hold included)
        Truncated,     // the file ends before what its header or its last line announces
        NotANumber,    // a coordinate or normal that is NaN, infinite or absurdly large
        BadFaces,      // a face names a point the file does not have
        NoPoints,      // read, but it holds no point
        Cancelled,     // the progress callback said stop
    };
    Code code = Code::Damaged;
    std::string detail; // where and what, for the command line's diagnostics; may be empty
};

struct ReferenceImportResult {
    model::ReferenceShape shape; // empty when error is set
    std::optional<ReferenceImportError> error;
};

// Given the fraction done (0 … 1); returns false to cancel (Code::Cancelled).
using ReferenceProgress = std::function<bool(double fraction)>;

inline constexpr std::uint64_t kMaxReferenceFileSize = 4ull * 1024 * 1024 * 1024;
// A project file holds about 60 bytes per point and 25 per triangle, and at most 512 MB.
inline constexpr std::size_t kMaxReferencePoints = 8'000'000;
inline constexpr std::size_t kMaxReferenceTriangles = 16'000'000;
// mm: a coordinate beyond a thousand kilometres is a damaged or misread file.
inline constexpr double kMaxReferenceCoordinate = 1e9;

// By extension, case-insensitively.
std::optional<ReferenceFormat> referenceFormatOf(const std::string& path);

// Reads the file in the format its extension names. The shape is named after the file (its
// base name without the extension) and its source is the file's name.
ReferenceImportResult readReferenceShape(const std::string& path,
                                         const ReferenceProgress& progress = {});

} // namespace devsurf::io
