#include "curve_import.h"

#include <QFile>
#include <QFileInfo>

namespace devsurf::io {

std::optional<CurveFormat> curveFormatOf(const QString& path) {
    const QString suffix = QFileInfo(path).suffix().toLower();
    if (suffix == QLatin1String("dxf")) {
        return CurveFormat::Dxf;
    }
    if (suffix == QLatin1String("step") || suffix == QLatin1String("stp")) {
        return CurveFormat::Step;
    }
    if (suffix == QLatin1String("iges") || suffix == QLatin1String("igs")) {
        return CurveFormat::Iges;
    }
    if (suffix == QLatin1String("svg")) {
        return CurveFormat::Svg;
    }
    return std::nullopt;
}

CurveImportResult importCurveFile(const QString& path, const CurveImportOptions& options) {
    using Code = CurveImportError::Code;
    const std::optional<CurveFormat> format = curveFormatOf(path);
    if (!format) {
        return curveImportFailure(Code::UnknownFormat);
    }
    const QFileInfo info(path);
    if (!info.exists() || !info.isFile()) {
        return curveImportFailure(Code::Unreadable, "it does not exist or is not a file");
    }
    if (static_cast<std::uint64_t>(info.size()) > kMaxCurveFileSize) {
        return curveImportFailure(Code::TooLarge);
    }
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) {
        return curveImportFailure(Code::Unreadable, file.errorString().toStdString());
    }
    if (*format == CurveFormat::Step || *format == CurveFormat::Iges) {
#ifdef DEVSURF_CAD_CURVES
        file.close();
        return readCadCurves(path, *format, options);
#else
        return curveImportFailure(Code::NotAvailable);
#endif
    }
    const QByteArray bytes = file.readAll();
    if (file.error() != QFileDevice::NoError) {
        return curveImportFailure(Code::Unreadable, file.errorString().toStdString());
    }
    if (*format == CurveFormat::Svg) {
        return readSvgCurves(bytes, options);
    }
    return readDxfCurves(bytes.toStdString(), options);
}

} // namespace devsurf::io
