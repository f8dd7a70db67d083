#pragma once

// Writers of a cutting pattern: DXF (through dxflib), SVG, PDF (through Qt's PDF writer, the
// same painter as printing) and FOLD. They write the pattern as it is; model::buildCuttingPattern
// computes it.

#include "pattern_style.h"

#include "model/pattern/cutting_pattern.h"

#include <QByteArray>
#include <QString>

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace devsurf::io {

enum class PatternFormat { Dxf, Svg, Pdf, Fold };

// "dxf", "svg", "pdf", "fold" (also the file extensions).
const char* patternFormatName(PatternFormat format);
std::optional<PatternFormat> patternFormatFromName(const std::string& name);

enum class Paper { A4, A3, Letter };
const char* paperName(Paper paper);
std::optional<Paper> paperFromName(const std::string& name); // case-insensitive
model::Vec2 paperSize(Paper paper);                          // portrait, mm

struct PatternWriteOptions {
    LayerMask layers = kAllLayers; // layers written (an empty layer is still declared in DXF)
    // DXF: cubic SPLINE entities fitted within `tolerance` instead of polylines (R2000 only:
    // R12 has no splines, polylines are written instead).
    bool splines = false;
    double tolerance = 0.01; // mm
    bool r12 = false;        // DXF R12 instead of R2000
    double margin = 10.0;    // SVG: space around the drawing, mm
    Paper paper = Paper::A4; // PDF
    // PDF report page: the pattern's problems as the front end words them.
    std::vector<std::string> problemTexts;
};

// Called with (done, total) while pages are drawn; returning false cancels.
using PatternProgress = std::function<bool(int done, int total)>;

// The file contents. Throw FileError with one sentence when the pattern cannot be written.
QByteArray patternDxf(const model::CuttingPattern& pattern, const PatternWriteOptions& options);
QByteArray patternSvg(const model::CuttingPattern& pattern, const PatternWriteOptions& options);
QByteArray patternFold(const model::CuttingPattern& pattern, const PatternWriteOptions& options);

// Writes the pattern to a file atomically (the old file stays if anything fails). Throws
// FileError with a sentence naming the file. Returns false if the progress callback cancelled.
bool savePatternFile(const model::CuttingPattern& pattern, PatternFormat format,
                     const QString& path, const PatternWriteOptions& options,
                     const PatternProgress& progress = {});

} // namespace devsurf::io
