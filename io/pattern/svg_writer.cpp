// SVG at true size: 1 user unit = 1 mm (width/height in mm, viewBox in mm), one Inkscape layer
// per pattern layer so that cutter software and Inkscape list them by name.

#include "pattern_sheets.h"
#include "pattern_writers.h"

#include <QBuffer>
#include <QXmlStreamWriter>

#include <cmath>

namespace devsurf::io {

using model::PatternLayer;
using model::Vec2;

namespace {

// Capital height of the sans-serif fonts used, as a fraction of the em.
constexpr double kCapHeight = 0.72;

QString number(double value) {
    // 1e-4 mm is far below any cutter's resolution and the pattern's tolerance.
    QString text = QString::number(value, 'f', 4);
    while (text.contains(QLatin1Char('.')) && (text.endsWith(QLatin1Char('0')))) {
        text.chop(1);
    }
    if (text.endsWith(QLatin1Char('.'))) {
        text.chop(1);
    }
    return text == QLatin1String("-0") ? QStringLiteral("0") : text;
}

QString colour(std::uint32_t rgb) {
    return QStringLiteral("#%1").arg(rgb, 6, 16, QLatin1Char('0'));
}

QString layerCss(const LayerStyle& style) {
    if (style.layer == PatternLayer::Labels) {
        return QStringLiteral("fill:%1;stroke:none;font-family:sans-serif").arg(colour(style.rgb));
    }
    QString css = QStringLiteral("fill:none;stroke:%1;stroke-width:%2;stroke-linecap:round;"
                                 "stroke-linejoin:round")
                      .arg(colour(style.rgb), number(style.strokeWidth));
    if (!style.dashes.empty()) {
        QStringList dashes;
        for (double d : style.dashes) {
            dashes << number(d);
        }
        css += QStringLiteral(";stroke-dasharray:") + dashes.join(QLatin1Char(','));
    }
    if (!style.onByDefault) {
        css += QStringLiteral(";display:none");
    }
    return css;
}

} // namespace

QByteArray patternSvg(const model::CuttingPattern& pattern, const PatternWriteOptions& options) {
    const std::vector<SheetGroup> groups = sheetGroups(pattern);
    const auto [lo, hi] = drawingBounds(groups);
    const double margin = std::max(0.0, options.margin);
    const double width = hi.x - lo.x + 2.0 * margin;
    const double height = hi.y - lo.y + 2.0 * margin;
    // Pattern y points up, SVG y points down.
    auto x = [&, lo = lo](double value) { return number(value - lo.x + margin); };
    auto y = [&, hi = hi](double value) { return number(hi.y + margin - value); };

    QByteArray bytes;
    QBuffer buffer(&bytes);
    buffer.open(QIODevice::WriteOnly);
    QXmlStreamWriter xml(&buffer);
    xml.setAutoFormatting(true);
    xml.setAutoFormattingIndent(1);
    xml.writeStartDocument();
    xml.writeStartElement(QStringLiteral("svg"));
    xml.writeDefaultNamespace(QStringLiteral("http://www.w3.org/2000/svg"));
    xml.writeNamespace(QStringLiteral("http://www.inkscape.org/namespaces/inkscape"),
                       QStringLiteral("inkscape"));
    xml.writeAttribute(QStringLiteral("version"), QStringLiteral("1.1"));
    xml.writeAttribute(QStringLiteral("width"), number(width) + QStringLiteral("mm"));
    xml.writeAttribute(QStringLiteral("height"), number(height) + QStringLiteral("mm"));
    xml.writeAttribute(QStringLiteral("viewBox"),
                       QStringLiteral("0 0 %1 %2").arg(number(width), number(height)));
    xml.writeTextElement(QStringLiteral("title"), QStringLiteral("DevSurf cutting pattern"));

    const QString inkscape = QStringLiteral("http://www.inkscape.org/namespaces/inkscape");
    for (const LayerStyle& style : layerStyles()) {
        if ((options.layers & layerBit(style.layer)) == 0) {
            continue;
        }
        xml.writeStartElement(QStringLiteral("g"));
        xml.writeAttribute(QStringLiteral("id"), QString::fromLatin1(style.name).toLower());
        xml.writeAttribute(inkscape, QStringLiteral("groupmode"), QStringLiteral("layer"));
        xml.writeAttribute(inkscape, QStringLiteral("label"), QString::fromLatin1(style.name));
        xml.writeAttribute(QStringLiteral("style"), layerCss(style));
        for (const SheetGroup& group : groups) {
            for (int index : group.pieces) {
                const model::PatternPiece& piece = pattern.pieces[std::size_t(index)];
                const Vec2 offset = group.offset;
                if (style.layer == PatternLayer::Labels) {
                    for (const model::PatternLabel& label : piece.labels) {
                        const Vec2 p = label.position + offset;
                        xml.writeStartElement(QStringLiteral("text"));
                        xml.writeAttribute(QStringLiteral("x"), x(p.x));
                        xml.writeAttribute(QStringLiteral("y"), y(p.y));
                        // The label's height is that of its capitals (as in DXF): the em is
                        // larger.
                        xml.writeAttribute(QStringLiteral("font-size"),
                                           number(label.height / kCapHeight));
                        xml.writeAttribute(QStringLiteral("text-anchor"), QStringLiteral("middle"));
                        if (label.angleDegrees != 0.0) {
                            xml.writeAttribute(
                                QStringLiteral("transform"),
                                QStringLiteral("rotate(%1 %2 %3)")
                                    .arg(number(-label.angleDegrees), x(p.x), y(p.y)));
                        }
                        xml.writeCharacters(QString::fromStdString(label.text));
                        xml.writeEndElement();
                    }
                    continue;
                }
                for (const model::PatternPath& path : piece.paths) {
                    if (path.layer != style.layer || path.points.size() < 2) {
                        continue;
                    }
                    QString d;
                    for (std::size_t i = 0; i < path.points.size(); ++i) {
                        const Vec2 p = path.points[i] + offset;
                        d += (i == 0 ? QStringLiteral("M") : QStringLiteral(" L")) + x(p.x) +
                             QLatin1Char(' ') + y(p.y);
                    }
                    if (path.closed) {
                        d += QStringLiteral(" Z");
                    }
                    xml.writeEmptyElement(QStringLiteral("path"));
                    xml.writeAttribute(QStringLiteral("d"), d);
                }
            }
        }
        xml.writeEndElement();
    }
    xml.writeEndElement();
    xml.writeEndDocument();
    return bytes;
}

} // namespace devsurf::io
