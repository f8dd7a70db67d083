#include "pattern_legend.h"

#include "dashed_line.h"
#include "pattern_style.h"

#include <QFont>
#include <QFontMetricsF>
#include <QLineF>
#include <QPainter>

#include <algorithm>
#include <cmath>

namespace devsurf::io {

using model::PatternLayer;

namespace {

// A font whose em is `size` mm on a device of `dpi`, the painter scaling millimetres to pixels.
QFont fontOf(double size, double dpi) {
    QFont font(QStringLiteral("DejaVu Sans"));
    font.setPointSizeF(size * 72.0 / dpi);
    return font;
}

// A short stretch of the layer's line as the tiles draw it.
void sample(QPainter& p, const LayerStyle& style, const QLineF& line) {
    QPen pen(colourOf(style.rgb), style.strokeWidth);
    pen.setCapStyle(Qt::RoundCap);
    p.setPen(pen);
    p.setBrush(Qt::NoBrush);
    const DashedLine dashed = dashLine(QPolygonF{line.p1(), line.p2()}, false, style.dashes);
    for (const QPolygonF& dash : dashed.dashes) {
        p.drawPolyline(dash);
    }
    p.setPen(Qt::NoPen);
    p.setBrush(colourOf(style.rgb));
    for (const QPointF& dot : dashed.dots) {
        p.drawEllipse(dot, 0.5 * style.strokeWidth, 0.5 * style.strokeWidth);
    }
}

bool hasLayer(const model::CuttingPattern& pattern, PatternLayer layer) {
    for (const model::PatternPiece& piece : pattern.pieces) {
        for (const model::PatternPath& path : piece.paths) {
            if (path.layer == layer) {
                return true;
            }
        }
    }
    return false;
}

// Where along a polyline half its length lies, and its direction there.
QLineF middleOf(const std::vector<model::Vec2>& points) {
    double length = 0.0;
    for (std::size_t i = 1; i < points.size(); ++i) {
        length += std::hypot(points[i].x - points[i - 1].x, points[i].y - points[i - 1].y);
    }
    double left = 0.5 * length;
    for (std::size_t i = 1; i < points.size(); ++i) {
        const QLineF segment(points[i - 1].x, points[i - 1].y, points[i].x, points[i].y);
        if (segment.length() >= left && segment.length() > 0.0) {
            const QPointF at = segment.pointAt(left / segment.length());
            return QLineF(at, at + (segment.p2() - segment.p1()) / segment.length());
        }
        left -= segment.length();
    }
    return {};
}

} // namespace

QColor colourOf(std::uint32_t rgb) {
    return QColor(int(rgb >> 16) & 0xff, int(rgb >> 8) & 0xff, int(rgb) & 0xff);
}

void paintLineLegend(QPainter& painter, const QRectF& box, const model::CuttingPattern& pattern,
                     double dpi) {
    struct Entry {
        PatternLayer layer;
        const char* name;
    };
    std::vector<Entry> entries{{PatternLayer::Cut, "Cut"},
                               {PatternLayer::Mountain, "Mountain"},
                               {PatternLayer::Valley, "Valley"},
                               {PatternLayer::Crease, "Crease"},
                               {PatternLayer::Seam, "Seam"}};
    if (hasLayer(pattern, PatternLayer::Score)) {
        entries.push_back({PatternLayer::Score, "Score"});
    }
    constexpr double kCell = 30.0; // mm: a sample and its name
    constexpr double kRow = 5.0;
    const int columns = std::max(1, int(box.width() / kCell));
    const int rows = (int(entries.size()) + columns - 1) / columns;
    const double top = box.bottom() - rows * kRow;
    painter.save();
    painter.setFont(fontOf(2.8, dpi));
    for (std::size_t i = 0; i < entries.size(); ++i) {
        const QRectF cell(box.left() + (int(i) % columns) * kCell, top + (int(i) / columns) * kRow,
                          kCell, kRow);
        const double y = cell.center().y();
        sample(painter, layerStyle(entries[i].layer),
               QLineF(cell.left() + 0.5, y, cell.left() + 10.5, y));
        painter.setPen(Qt::black);
        painter.drawText(QRectF(cell.left() + 12.0, cell.top(), kCell - 12.0, kRow),
                         Qt::AlignLeft | Qt::AlignVCenter, QString::fromLatin1(entries[i].name));
    }
    painter.restore();
}

void paintFoldAngles(QPainter& painter, const model::PatternPiece& piece, const QRectF& visible,
                     double dpi) {
    const QFont font = fontOf(2.5, dpi);
    const QFontMetricsF metrics(font, painter.device());
    painter.save();
    painter.setFont(font);
    for (const model::PatternPath& path : piece.paths) {
        if ((path.layer != PatternLayer::Mountain && path.layer != PatternLayer::Valley) ||
            !path.foldAngleDegrees || path.points.size() < 2) {
            continue;
        }
        const QLineF middle = middleOf(path.points);
        if (middle.isNull() || (!visible.isNull() && !visible.contains(middle.p1()))) {
            continue;
        }
        const bool mountain = path.layer == PatternLayer::Mountain;
        const QString text = QStringLiteral("%1 %2°")
                                 .arg(mountain ? QLatin1Char('M') : QLatin1Char('V'))
                                 .arg(std::abs(*path.foldAngleDegrees), 0, 'f', 1);
        // Along the fold (counter-clockwise from +x, the pattern's y up) and upright: a
        // direction pointing left is turned round.
        double angle = std::atan2(middle.dy(), middle.dx()) * 180.0 / M_PI;
        if (angle > 90.0) {
            angle -= 180.0;
        } else if (angle <= -90.0) {
            angle += 180.0;
        }
        painter.setPen(colourOf(layerStyle(path.layer).rgb));
        painter.save();
        painter.translate(middle.p1());
        painter.scale(1.0, -1.0); // the page's y points down again for the text
        painter.rotate(-angle);
        painter.drawText(QPointF(-0.5 * metrics.horizontalAdvance(text), -0.8), text);
        painter.restore();
    }
    painter.restore();
}

} // namespace devsurf::io
