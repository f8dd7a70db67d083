#include "page_plan.h"
#include "pattern_painter.h"
#include "pattern_writers.h"

#include "io/file_error.h"
#include "io/output_file.h"

#include <QBuffer>
#include <QPdfWriter>

#include <algorithm>
#include <cctype>

namespace devsurf::io {

const char* patternFormatName(PatternFormat format) {
    switch (format) {
    case PatternFormat::Dxf:
        return "dxf";
    case PatternFormat::Svg:
        return "svg";
    case PatternFormat::Pdf:
        return "pdf";
    case PatternFormat::Fold:
        return "fold";
    }
    return "dxf";
}

std::optional<PatternFormat> patternFormatFromName(const std::string& name) {
    for (PatternFormat format :
         {PatternFormat::Dxf, PatternFormat::Svg, PatternFormat::Pdf, PatternFormat::Fold}) {
        if (name == patternFormatName(format)) {
            return format;
        }
    }
    return std::nullopt;
}

const char* paperName(Paper paper) {
    switch (paper) {
    case Paper::A4:
        return "A4";
    case Paper::A3:
        return "A3";
    case Paper::Letter:
        return "Letter";
    }
    return "A4";
}

std::optional<Paper> paperFromName(const std::string& name) {
    std::string lower = name;
    std::transform(lower.begin(), lower.end(), lower.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    for (Paper paper : {Paper::A4, Paper::A3, Paper::Letter}) {
        std::string candidate = paperName(paper);
        std::transform(candidate.begin(), candidate.end(), candidate.begin(),
                       [](unsigned char c) { return char(std::tolower(c)); });
        if (lower == candidate) {
            return paper;
        }
    }
    return std::nullopt;
}

model::Vec2 paperSize(Paper paper) {
    const QSizeF size = pageSizeOf(paper).size(QPageSize::Millimeter);
    return {size.width(), size.height()};
}

bool savePatternFile(const model::CuttingPattern& pattern, PatternFormat format,
                     const QString& path, const PatternWriteOptions& options,
                     const PatternProgress& progress) {
    if (pattern.pieces.empty()) {
        throw FileError("Cannot write '" + path.toStdString() +
                        "': the cutting pattern has no pieces.");
    }
    if (format == PatternFormat::Pdf) {
        // Drawn into memory, then written as the other formats are: a file device reports a
        // short write (the disk filling up within a large page) without an error and
        // QPdfWriter then stops writing, so a streamed PDF could end truncated without a word.
        QBuffer buffer;
        buffer.open(QIODevice::WriteOnly);
        const PagePlan plan = planPages(pattern, paperSize(options.paper));
        bool cancelled = false;
        bool drawn = false;
        {
            QPdfWriter writer(&buffer);
            writer.setResolution(1200);
            writer.setCreator(QStringLiteral("DevSurf"));
            writer.setTitle(QStringLiteral("DevSurf cutting pattern"));
            preparePagedDevice(writer, pageSizeOf(options.paper), plan);
            const PatternProgress watch = [&](int done, int total) {
                cancelled = progress && !progress(done, total);
                return !cancelled;
            };
            drawn = paintPatternPages(writer, pattern, plan, options.problemTexts, watch);
        }
        if (!drawn) {
            if (cancelled) {
                return false;
            }
            throw FileError("Cannot write '" + path.toStdString() +
                            "': the PDF pages could not be drawn.");
        }
        writeFileAtomically(path, buffer.data());
        return true;
    }
    QByteArray bytes;
    switch (format) {
    case PatternFormat::Dxf:
        bytes = patternDxf(pattern, options);
        break;
    case PatternFormat::Svg:
        bytes = patternSvg(pattern, options);
        break;
    case PatternFormat::Fold:
        bytes = patternFold(pattern, options);
        break;
    case PatternFormat::Pdf:
        break;
    }
    writeFileAtomically(path, bytes);
    return true;
}

} // namespace devsurf::io
