// DXF through dxflib (QCAD's library): it encodes entities and tables; the order of the
// sections is ours (header, tables, blocks, entities, objects), as R2000 readers expect.

#include "pattern_sheets.h"
#include "pattern_writers.h"
#include "spline_fit.h"

#include "io/file_error.h"

#include <dxflib/dl_dxf.h>

#include <QFile>
#include <QString>

#include <sys/mman.h>
#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstring>
#include <memory>
#include <string>

namespace devsurf::io {

using model::PatternLayer;
using model::Vec2;

namespace {

constexpr int kByLayer = 256;

// DXF text is 8-bit: characters outside ASCII are written as \U+XXXX, which every reader
// since R12-era AutoCAD understands.
std::string dxfText(const std::string& utf8) {
    std::string out;
    const QString text = QString::fromStdString(utf8);
    for (const char32_t c : text.toUcs4()) {
        if (c >= 32 && c < 127) {
            out += static_cast<char>(c);
        } else if (c >= 127) {
            char buffer[16];
            std::snprintf(buffer, sizeof buffer, "\\U+%04X", static_cast<unsigned>(c));
            out += buffer;
        }
    }
    return out;
}

class DxfBuilder {
public:
    DxfBuilder(const model::CuttingPattern& pattern, const PatternWriteOptions& options,
               const std::string& path)
        : m_pattern(pattern), m_options(options),
          m_version(options.r12 ? DL_Codes::AC1009 : DL_Codes::AC1015),
          m_writer(m_dxf.out(path.c_str(), m_version)) {}

    bool opened() const { return m_writer != nullptr && !m_writer->openFailed(); }

    void write() {
        const std::vector<SheetGroup> groups = sheetGroups(m_pattern);
        const auto [lo, hi] = drawingBounds(groups);
        writeHeader(lo, hi);
        writeTables();
        writeBlocks();
        m_writer->sectionEntities();
        for (const SheetGroup& group : groups) {
            for (int index : group.pieces) {
                writePiece(m_pattern.pieces[static_cast<std::size_t>(index)], group.offset);
            }
        }
        m_writer->sectionEnd();
        if (m_version == DL_Codes::AC1015) {
            m_dxf.writeObjects(*m_writer);
            m_dxf.writeObjectsEnd(*m_writer);
        }
        m_writer->dxfEOF();
        m_writer->close();
    }

private:
    bool wanted(PatternLayer layer) const { return (m_options.layers & layerBit(layer)) != 0; }

    void point(int code, const Vec2& p) {
        m_writer->dxfReal(code, p.x);
        m_writer->dxfReal(code + 10, p.y);
        m_writer->dxfReal(code + 20, 0.0);
    }

    void writeHeader(const Vec2& lo, const Vec2& hi) {
        m_dxf.writeHeader(*m_writer);
        // Millimetres, metric drawing, line patterns in drawing units.
        m_writer->dxfString(9, "$INSUNITS");
        m_writer->dxfInt(70, 4);
        m_writer->dxfString(9, "$MEASUREMENT");
        m_writer->dxfInt(70, 1);
        m_writer->dxfString(9, "$LTSCALE");
        m_writer->dxfReal(40, 1.0);
        m_writer->dxfString(9, "$EXTMIN");
        point(10, lo);
        m_writer->dxfString(9, "$EXTMAX");
        point(10, hi);
        m_writer->sectionEnd();
    }

    void writeTables() {
        m_writer->sectionTables();
        m_dxf.writeVPort(*m_writer);

        std::vector<const LayerStyle*> patterned;
        for (const LayerStyle& style : layerStyles()) {
            if (!style.dashes.empty()) {
                patterned.push_back(&style);
            }
        }
        m_writer->tableLinetypes(static_cast<int>(3 + patterned.size()));
        m_dxf.writeLinetype(*m_writer, DL_LinetypeData("BYBLOCK", "", 0, 0, 0.0));
        m_dxf.writeLinetype(*m_writer, DL_LinetypeData("BYLAYER", "", 0, 0, 0.0));
        m_dxf.writeLinetype(*m_writer, DL_LinetypeData("CONTINUOUS", "Solid line", 0, 0, 0.0));
        for (const LayerStyle* style : patterned) {
            // Dashes positive, gaps negative, a dot is 0 (the DXF convention).
            std::vector<double> dashes;
            double length = 0.0;
            for (std::size_t i = 0; i < style->dashes.size(); ++i) {
                dashes.push_back(i % 2 == 0 ? style->dashes[i] : -style->dashes[i]);
                length += style->dashes[i];
            }
            m_dxf.writeLinetype(*m_writer, DL_LinetypeData(style->linetype, style->name, 0,
                                                           static_cast<int>(dashes.size()), length,
                                                           dashes.data()));
        }
        m_writer->tableEnd();

        m_writer->tableLayers(1 + model::kPatternLayerCount);
        m_dxf.writeLayer(*m_writer, DL_LayerData("0", 0),
                         DL_Attributes("", 7, 0, "CONTINUOUS", 1.0));
        for (const LayerStyle& style : layerStyles()) {
            m_dxf.writeLayer(*m_writer, DL_LayerData(style.name, 0, !style.onByDefault),
                             DL_Attributes("", style.aci, 0, style.linetype, 1.0));
        }
        m_writer->tableEnd();

        m_writer->tableStyle(1);
        m_dxf.writeStyle(*m_writer, DL_StyleData("Standard", 0, 0.0, 1.0, 0.0, 0, 5.0, "txt", ""));
        m_writer->tableEnd();
        m_dxf.writeView(*m_writer);
        m_dxf.writeUcs(*m_writer);
        m_writer->tableAppid(1);
        m_dxf.writeAppid(*m_writer, "ACAD");
        m_writer->tableEnd();
        m_dxf.writeDimStyle(*m_writer, 2.5, 0.625, 0.625, 0.625, 2.5);
        if (m_version == DL_Codes::AC1015) {
            m_dxf.writeBlockRecord(*m_writer);
            m_writer->tableEnd();
        }
        m_writer->sectionEnd();
    }

    void writeBlocks() {
        m_writer->sectionBlocks();
        for (const char* name : {"*Model_Space", "*Paper_Space"}) {
            m_dxf.writeBlock(*m_writer, DL_BlockData(name, 0, 0.0, 0.0, 0.0));
            m_dxf.writeEndBlock(*m_writer, name);
        }
        m_writer->sectionEnd();
    }

    DL_Attributes attributes(PatternLayer layer) const {
        return DL_Attributes(layerStyle(layer).name, kByLayer, 0, "BYLAYER", 1.0);
    }

    void writePolyline(PatternLayer layer, const std::vector<Vec2>& points, bool closed,
                       const Vec2& offset) {
        if (points.size() < 2) {
            return;
        }
        m_dxf.writePolyline(*m_writer,
                            DL_PolylineData(static_cast<int>(points.size()), 0, 0, closed ? 1 : 0),
                            attributes(layer));
        for (const Vec2& p : points) {
            m_dxf.writeVertex(*m_writer, DL_VertexData(p.x + offset.x, p.y + offset.y, 0.0, 0.0));
        }
        m_dxf.writePolylineEnd(*m_writer);
    }

    void writeSpline(PatternLayer layer, const std::vector<Vec2>& points, bool closed,
                     const Vec2& offset) {
        const CubicSpline spline = fitCubicSpline(points, closed, m_options.tolerance);
        if (spline.segments() == 0) {
            return;
        }
        // Flag 8: planar. A closed outline starts and ends at the same control point (a
        // clamped curve), which every reader draws as closed.
        m_dxf.writeSpline(*m_writer,
                          DL_SplineData(3, static_cast<int>(spline.knots.size()),
                                        static_cast<int>(spline.controlPoints.size()), 0, 8),
                          attributes(layer));
        for (double k : spline.knots) {
            m_dxf.writeKnot(*m_writer, DL_KnotData(k));
        }
        for (const Vec2& c : spline.controlPoints) {
            m_dxf.writeControlPoint(*m_writer,
                                    DL_ControlPointData(c.x + offset.x, c.y + offset.y, 0.0, 1.0));
        }
    }

    void writePiece(const model::PatternPiece& piece, const Vec2& offset) {
        const bool splines = m_options.splines && m_version == DL_Codes::AC1015;
        for (const model::PatternPath& path : piece.paths) {
            if (!wanted(path.layer) || path.layer == PatternLayer::Labels) {
                continue;
            }
            // Straight two-point paths (rulings, straight creases) stay lines in either mode.
            if (splines && path.points.size() > 2) {
                writeSpline(path.layer, path.points, path.closed, offset);
            } else {
                writePolyline(path.layer, path.points, path.closed, offset);
            }
        }
        if (!wanted(PatternLayer::Labels)) {
            return;
        }
        for (const model::PatternLabel& label : piece.labels) {
            const Vec2 p = label.position + offset;
            // Centred on the baseline (horizontal justification 1, vertical 0).
            m_dxf.writeText(*m_writer,
                            DL_TextData(p.x, p.y, 0.0, p.x, p.y, 0.0, label.height, 1.0, 0, 1, 0,
                                        dxfText(label.text), "Standard",
                                        label.angleDegrees * M_PI / 180.0),
                            attributes(PatternLayer::Labels));
        }
    }

    const model::CuttingPattern& m_pattern;
    const PatternWriteOptions& m_options;
    DL_Codes::version m_version;
    DL_Dxf m_dxf;
    std::unique_ptr<DL_WriterA> m_writer;
};

} // namespace

QByteArray patternDxf(const model::CuttingPattern& pattern, const PatternWriteOptions& options) {
    // dxflib writes to a named file only: it writes into an anonymous file in memory (named
    // through /proc/self/fd), whose bytes go to the caller, who saves them atomically. Nothing
    // is left behind when the process is killed, and no temporary folder is needed.
    const int fd = ::memfd_create("devsurf-pattern.dxf", MFD_CLOEXEC);
    if (fd < 0) {
        throw FileError(std::string("Cannot write the DXF file: ") + std::strerror(errno) + ".");
    }
    QFile file;
    if (!file.open(fd, QIODevice::ReadOnly, QFileDevice::AutoCloseHandle)) {
        ::close(fd);
        throw FileError("Cannot write the DXF file: " + file.errorString().toStdString() + ".");
    }
    {
        DxfBuilder builder(pattern, options, "/proc/self/fd/" + std::to_string(fd));
        if (!builder.opened()) {
            throw FileError("Cannot write the DXF file: the memory file could not be opened.");
        }
        builder.write();
    }
    QByteArray bytes = file.readAll();
    if (file.error() != QFileDevice::NoError) {
        throw FileError("Cannot write the DXF file: " + file.errorString().toStdString() + ".");
    }
    return bytes;
}

} // namespace devsurf::io
