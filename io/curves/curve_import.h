#pragma once

// Reference curves from other programs' files: DXF (dxflib), STEP and IGES (OpenCASCADE),
// SVG (Qt's SVG renderer; needs a QGuiApplication).
// Every reader returns the curves as polylines in mm or a typed error; none throws, and no
// input, however damaged, may crash it.

#include "model/reference_curve.h"

#include <QByteArray>
#include <QString>

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace devsurf::io {

enum class CurveFormat { Dxf, Step, Iges, Svg };

struct CurveImportError {
    enum class Code {
        UnknownFormat, // the extension is none of .dxf, .step, .stp, .iges, .igs, .svg
        NotAvailable,  // STEP or IGES in a build without OpenCASCADE
        Unreadable,    // the file cannot be opened or read
        TooLarge,      // larger than kMaxCurveFileSize
        Damaged,       // the reader refused the file's contents
        NoCurves,      // read, but it holds no curve DevSurf can use
        Cancelled,     // the progress callback said stop
    };
    Code code = Code::Damaged;
    std::string detail; // the reader's own words, for the command line's diagnostics; may be empty
};

struct CurveImportOptions {
    // mm: a sampled curve stays within this distance of the exact one.
    double tolerance = 0.05;
    // Given the fraction done (0 … 1); returns false to cancel (Code::Cancelled).
    std::function<bool(double fraction)> progress;
};

struct CurveImportResult {
    std::vector<model::ReferenceCurve> curves; // empty when error is set
    std::optional<CurveImportError> error;
    int skipped = 0; // entities that were not curves DevSurf can read (texts, meshes, damaged)
};

// A result that carries only the error: what every reader returns when it gives up.
inline CurveImportResult curveImportFailure(CurveImportError::Code code, std::string detail = {}) {
    CurveImportResult result;
    result.error = CurveImportError{code, std::move(detail)};
    return result;
}

inline constexpr std::uint64_t kMaxCurveFileSize = 256ull * 1024 * 1024;
// No curve is sampled to more points than this (a damaged knot vector cannot exhaust memory).
inline constexpr std::size_t kMaxCurvePoints = 200'000;

// By extension, case-insensitively: dxf; step, stp; iges, igs; svg.
std::optional<CurveFormat> curveFormatOf(const QString& path);

// Reads the file in the format its extension names.
CurveImportResult importCurveFile(const QString& path, const CurveImportOptions& options = {});

// The readers behind importCurveFile, for tests and callers that hold the bytes.
CurveImportResult readDxfCurves(const std::string& bytes, const CurveImportOptions& options);
// SVG: every shape drawn (paths, polygons, rectangles, circles, lines; text left out) in the
// plane z = 0, in mm by the root's width and viewBox (CSS pixels without them), y up.
CurveImportResult readSvgCurves(const QByteArray& bytes, const CurveImportOptions& options);
// STEP or IGES from a file (OpenCASCADE reads paths only).
CurveImportResult readCadCurves(const QString& path, CurveFormat format,
                                const CurveImportOptions& options);

} // namespace devsurf::io
