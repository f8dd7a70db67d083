#include "pattern_painter.h"

#include "dashed_line.h"
#include "fabrication_report.h"
#include "pattern_legend.h"

#include <QFontMetricsF>
#include <QPageLayout>
#include <QPagedPaintDevice>
#include <QPainter>

#include <algorithm>
#include <cmath>

namespace devsurf::io {

using model::PatternLayer;
using model::Vec2;

namespace {

constexpr double kRowHeight = 6.5;     // mm, a row of the report's table
constexpr double kProblemHeight = 8.5; // mm, one problem sentence (up to two lines)
constexpr int kProblemsShown = 5;      // on the report page; all are in the CLI report

// Rows of the report's table on its first page (after the summary and the problems) and on
// the following ones.
int reportRows(const PagePlan& plan, bool firstPage) {
    const double reserved = firstPage ? 12.0 + kProblemsShown * kProblemHeight + 13.0 : 0.0;
    return std::max(1, int((plan.content.y - 11.0 - reserved - kRowHeight) / kRowHeight));
}

// Draws in millimetres from the page's top-left corner whatever the device resolution.
class PagePainter {
public:
    PagePainter(QPainter& painter, double dpi) : m_p(painter), m_dpi(dpi) {}

    void startPage() {
        m_p.resetTransform();
        m_p.scale(m_dpi / 25.4, m_dpi / 25.4);
        m_p.setClipping(false);
    }

    // Text whose em is `size` mm; flags as QPainter::drawText in a rectangle.
    void text(const QRectF& box, double size, const QString& text, int flags = 0,
              bool bold = false) {
        m_p.setFont(font(size, bold));
        m_p.setPen(Qt::black);
        m_p.drawText(box, flags | Qt::TextWordWrap, text);
    }

    QFont font(double size, bool bold = false) const {
        QFont f(QStringLiteral("DejaVu Sans"));
        // The painter scales millimetres to device pixels; a font's point size is resolved
        // against the device resolution, so this point size gives an em of `size` mm.
        f.setPointSizeF(size * 72.0 / m_dpi);
        f.setBold(bold);
        return f;
    }

    QPen pen(const QColor& colour, double width) const {
        QPen pen(colour, width);
        pen.setCapStyle(Qt::RoundCap);
        pen.setJoinStyle(Qt::RoundJoin);
        return pen;
    }

    QPainter& painter() { return m_p; }
    double dpi() const { return m_dpi; }

private:
    QPainter& m_p;
    double m_dpi;
};

// A dashed layer is drawn as its dashes (dashed_line.h), each with a solid pen; dots are discs
// as wide as the line.
void drawLayerLine(PagePainter& pages, const LayerStyle& style, const QPolygonF& line,
                   bool closed) {
    QPainter& p = pages.painter();
    const QColor colour = colourOf(style.rgb);
    p.setPen(pages.pen(colour, style.strokeWidth));
    p.setBrush(Qt::NoBrush);
    if (style.dashes.empty()) {
        if (closed) {
            p.drawPolygon(line);
        } else {
            p.drawPolyline(line);
        }
        return;
    }
    const DashedLine dashed = dashLine(line, closed, style.dashes);
    for (const QPolygonF& dash : dashed.dashes) {
        p.drawPolyline(dash);
    }
    if (!dashed.dots.empty()) {
        p.setPen(Qt::NoPen);
        p.setBrush(colour);
        const double r = 0.5 * style.strokeWidth;
        for (const QPointF& dot : dashed.dots) {
            p.drawEllipse(dot, r, r);
        }
    }
}

bool meets(const std::vector<Vec2>& points, const QRectF& visible) {
    if (visible.isNull()) {
        return true;
    }
    double x0 = points.front().x, x1 = x0, y0 = points.front().y, y1 = y0;
    for (const Vec2& q : points) {
        x0 = std::min(x0, q.x);
        x1 = std::max(x1, q.x);
        y0 = std::min(y0, q.y);
        y1 = std::max(y1, q.y);
    }
    return x1 >= visible.left() && x0 <= visible.right() && y1 >= visible.top() &&
           y0 <= visible.bottom();
}

// Everything of the given pieces, in pattern coordinates (the caller sets the transform).
// Lines wholly outside `visible` (pattern coordinates; null: everything) are left out, so
// that a tiled page holds only what it shows.
void drawPieces(PagePainter& pages, const model::CuttingPattern& pattern,
                const std::vector<int>& pieces, bool cutOnly, const QRectF& visible = {}) {
    QPainter& p = pages.painter();
    static const PatternLayer order[] = {PatternLayer::Score,    PatternLayer::Seam,
                                         PatternLayer::Crease,   PatternLayer::Valley,
                                         PatternLayer::Mountain, PatternLayer::Cut};
    for (PatternLayer layer : order) {
        if (cutOnly && layer != PatternLayer::Cut) {
            continue;
        }
        for (int index : pieces) {
            for (const model::PatternPath& path : pattern.pieces[std::size_t(index)].paths) {
                if (path.layer != layer || path.points.size() < 2 || !meets(path.points, visible)) {
                    continue;
                }
                QPolygonF polygon;
                for (const Vec2& q : path.points) {
                    polygon << QPointF(q.x, q.y);
                }
                drawLayerLine(pages, layerStyle(layer), polygon, path.closed);
            }
        }
    }
    if (cutOnly) {
        return;
    }
    p.setPen(colourOf(layerStyle(PatternLayer::Labels).rgb));
    for (int index : pieces) {
        for (const model::PatternLabel& label : pattern.pieces[std::size_t(index)].labels) {
            // The label's height is its capitals' (as in DXF); the em is larger.
            const QFont font = pages.font(label.height / 0.72);
            p.setFont(font);
            const QString text = QString::fromStdString(label.text);
            const double width = QFontMetricsF(font, p.device()).horizontalAdvance(text);
            p.save();
            // The pattern's y points up: undo the flip for the text, then rotate about the
            // anchor (counter-clockwise in the pattern is counter-clockwise on paper).
            p.translate(label.position.x, label.position.y);
            p.scale(1.0, -1.0);
            p.rotate(-label.angleDegrees);
            p.drawText(QPointF(-0.5 * width, 0.0), text);
            p.restore();
        }
        paintFoldAngles(p, pattern.pieces[std::size_t(index)], visible, pages.dpi());
    }
}

// "Sheet 2", or the piece that the layout could not place on a sheet.
QString groupName(const model::CuttingPattern& pattern, const SheetGroup& group, bool why) {
    if (group.sheet >= 0) {
        return QStringLiteral("Sheet %1").arg(group.sheet + 1);
    }
    const QString name =
        QString::fromStdString(pattern.pieces[std::size_t(group.pieces.front())].name);
    return why ? QStringLiteral("Piece %1 (not placed on a sheet)").arg(name)
               : QStringLiteral("Piece %1").arg(name);
}

void registrationMark(QPainter& p, const QPointF& c) {
    p.drawEllipse(c, 3.0, 3.0);
    p.drawLine(QPointF(c.x() - 5.0, c.y()), QPointF(c.x() + 5.0, c.y()));
    p.drawLine(QPointF(c.x(), c.y() - 5.0), QPointF(c.x(), c.y() + 5.0));
}

// The band on every page: the scale squares (drawn inside their nominal size, so that the
// outer edge of the line measures 50 mm and 1 inch), a large label, where the page belongs and
// a note.
void paintBand(PagePainter& pages, const PagePlan& plan, const QString& label, const QString& where,
               const QString& note, const model::CuttingPattern* legendOf = nullptr) {
    QPainter& p = pages.painter();
    const QPointF band(plan.bandOrigin.x, plan.bandOrigin.y);
    const double line = 0.3;
    const QPointF squareAt = band + QPointF(4.0, 4.0);
    const QPointF inchAt =
        plan.landscape ? squareAt + QPointF(0.0, 58.0) : squareAt + QPointF(58.0, 0.0);
    QPen squarePen(Qt::black, line);
    squarePen.setJoinStyle(Qt::MiterJoin);
    p.setPen(squarePen);
    p.setBrush(Qt::NoBrush);
    const double half = 0.5 * line;
    p.drawRect(QRectF(squareAt + QPointF(half, half), QSizeF(50.0 - line, 50.0 - line)));
    p.drawRect(QRectF(inchAt + QPointF(half, half), QSizeF(25.4 - line, 25.4 - line)));
    pages.text(QRectF(squareAt, QSizeF(50.0, 50.0)), 4.0, QStringLiteral("50 mm"), Qt::AlignCenter);
    pages.text(QRectF(inchAt, QSizeF(25.4, 25.4)), 3.2, QStringLiteral("1 in"), Qt::AlignCenter);
    const QRectF box = plan.landscape
                           ? QRectF(band + QPointF(4.0, 90.0),
                                    QSizeF(plan.bandSize.x - 4.0, plan.bandSize.y - 90.0))
                           : QRectF(band + QPointF(94.0, 4.0),
                                    QSizeF(plan.bandSize.x - 94.0, plan.bandSize.y - 4.0));
    double y = 0.0;
    if (!label.isEmpty()) {
        pages.text(QRectF(box.topLeft(), QSizeF(box.width(), 14.0)), 10.0, label,
                   Qt::AlignLeft | Qt::AlignTop, true);
        y = 15.0;
    }
    pages.text(QRectF(box.topLeft() + QPointF(0.0, y), QSizeF(box.width(), 8.0)), 3.5, where,
               Qt::AlignLeft | Qt::AlignTop, true);
    pages.text(
        QRectF(box.topLeft() + QPointF(0.0, y + 8.0), QSizeF(box.width(), box.height() - y - 8.0)),
        3.0, note, Qt::AlignLeft | Qt::AlignTop);
    if (legendOf != nullptr) {
        paintLineLegend(p, box, *legendOf, pages.dpi());
    }
}

void paintReportPage(PagePainter& pages, const PagePlan& plan, const FabricationReport& report,
                     int page, int reportPages, int pageCount) {
    QPainter& p = pages.painter();
    const double left = plan.contentOrigin.x;
    const double width = plan.content.x;
    double y = plan.contentOrigin.y;
    paintBand(pages, plan, QString(), QStringLiteral("Fabrication report"),
              QStringLiteral("Page %1 of %2. Print at 100 % (no fit to page): the squares "
                             "measure 50 mm and 1 inch.")
                  .arg(page + 1)
                  .arg(pageCount));
    pages.text(QRectF(left, y, width, 10), 6.0,
               reportPages > 1
                   ? QStringLiteral("Fabrication report (%1 of %2)").arg(page + 1).arg(reportPages)
                   : QStringLiteral("Fabrication report"),
               Qt::AlignLeft | Qt::AlignTop, true);
    y += 11;
    if (page == 0) {
        const QString summary =
            QStringLiteral("%1 on %2 of %3 × %4 mm. Total area %5 mm². Largest isometry error "
                           "%6 mm.")
                .arg(report.pieces.size() == 1
                         ? QStringLiteral("1 piece")
                         : QStringLiteral("%1 pieces").arg(report.pieces.size()))
                .arg(report.sheetCount == 1 ? QStringLiteral("1 sheet")
                                            : QStringLiteral("%1 sheets").arg(report.sheetCount))
                .arg(report.sheetSize.x, 0, 'f', 0)
                .arg(report.sheetSize.y, 0, 'f', 0)
                .arg(report.totalArea, 0, 'f', 0)
                .arg(report.maxIsometryError, 0, 'g', 3);
        pages.text(QRectF(left, y, width, 12), 3.5, summary, Qt::AlignLeft | Qt::AlignTop);
        y += 12;
        const int problems = int(report.problems.size());
        for (int i = 0; i < std::min(problems, kProblemsShown); ++i) {
            const QString text =
                i + 1 == kProblemsShown && problems > kProblemsShown
                    ? QStringLiteral("… and %1 more problems (devsurf-cli report lists them).")
                          .arg(problems - kProblemsShown + 1)
                    : QStringLiteral("Problem: ") +
                          QString::fromStdString(report.problems[std::size_t(i)]);
            pages.text(QRectF(left, y, width, kProblemHeight), 3.2, text,
                       Qt::AlignLeft | Qt::AlignTop, true);
            y += kProblemHeight;
        }
        if (report.hasOverlaps()) {
            pages.text(QRectF(left, y, width, 8.0), 3.2,
                       QStringLiteral("Warning: overlapping pieces cannot be cut as laid out."),
                       Qt::AlignLeft | Qt::AlignTop, true);
        }
        y = plan.contentOrigin.y + 11.0 + 12.0 + kProblemsShown * kProblemHeight + 13.0;
    }
    const double columns[] = {0.0, 0.13, 0.23, 0.45, 0.62, 0.79, 0.88};
    const QString headers[] = {QStringLiteral("Piece"),          QStringLiteral("Sheet"),
                               QStringLiteral("Size (mm)"),      QStringLiteral("Area (mm²)"),
                               QStringLiteral("Isometry error"), QStringLiteral("Fits"),
                               QStringLiteral("Overlaps")};
    auto row = [&](const QString* cells, bool bold) {
        for (int c = 0; c < 7; ++c) {
            const double x0 = left + columns[c] * width;
            const double x1 = c == 6 ? left + width : left + columns[c + 1] * width;
            pages.text(QRectF(x0, y, x1 - x0 - 1.0, kRowHeight), 3.2, cells[c],
                       Qt::AlignLeft | Qt::AlignVCenter, bold);
        }
        y += kRowHeight;
    };
    row(headers, true);
    p.setPen(pages.pen(Qt::black, 0.2));
    p.drawLine(QPointF(left, y), QPointF(left + width, y));
    const int first = page == 0 ? 0 : reportRows(plan, true) + (page - 1) * reportRows(plan, false);
    const int last = std::min<int>(int(report.pieces.size()), first + reportRows(plan, page == 0));
    for (int i = first; i < last; ++i) {
        const PieceReport& piece = report.pieces[std::size_t(i)];
        QString overlaps;
        if (piece.selfOverlapping) {
            overlaps = QStringLiteral("itself");
        }
        for (const std::string& other : piece.overlapsWith) {
            overlaps += (overlaps.isEmpty() ? QString() : QStringLiteral(", ")) +
                        QString::fromStdString(other);
        }
        const QString cells[] = {
            QString::fromStdString(piece.name),
            piece.sheet >= 0 ? QString::number(piece.sheet + 1) : QStringLiteral("–"),
            QStringLiteral("%1 × %2").arg(piece.size.x, 0, 'f', 1).arg(piece.size.y, 0, 'f', 1),
            QString::number(piece.area, 'f', 0),
            QStringLiteral("%1 mm").arg(piece.maxIsometryError, 0, 'g', 3),
            piece.fitsSheet ? QStringLiteral("yes") : QStringLiteral("no"),
            overlaps.isEmpty() ? QStringLiteral("none") : overlaps};
        row(cells, false);
    }
}

void paintOverview(PagePainter& pages, const model::CuttingPattern& pattern, const PagePlan& plan,
                   int group, int pageNumber, int pageCount) {
    QPainter& p = pages.painter();
    const SheetGroup& g = plan.groups[std::size_t(group)];
    const int rows = plan.rows[std::size_t(group)];
    const int columns = plan.columns[std::size_t(group)];
    const QString title = groupName(pattern, g, true) +
                          QStringLiteral(": %1 × %2 pages (rows A–%3, columns 1–%4), overlap %5 mm")
                              .arg(rows)
                              .arg(columns)
                              .arg(QString::fromStdString(rowName(rows - 1)))
                              .arg(columns)
                              .arg(plan.overlap, 0, 'f', 0);
    const QRectF area(plan.contentOrigin.x, plan.contentOrigin.y, plan.content.x, plan.content.y);
    pages.text(QRectF(area.topLeft(), QSizeF(area.width(), 14)), 5.0, title,
               Qt::AlignLeft | Qt::AlignTop, true);
    paintBand(pages, plan, QString(), QStringLiteral("Overview"),
              QStringLiteral("Page %1 of %2. The pages that follow, in reading order; each "
                             "is labelled with its row and column.")
                  .arg(pageNumber)
                  .arg(pageCount));
    // The tiled region in pattern coordinates.
    const double stepX = plan.content.x - plan.overlap;
    const double stepY = plan.content.y - plan.overlap;
    const double width = stepX * columns + plan.overlap;
    const double height = stepY * rows + plan.overlap;
    const QRectF box = area.adjusted(0.0, 16.0, 0.0, 0.0);
    const double scale = std::min(box.width() / width, box.height() / height);
    p.save();
    p.translate(box.left(), box.top());
    p.scale(scale, scale);
    // Now in pattern millimetres, y down from the tiled region's top-left.
    p.save();
    p.translate(-g.min.x, g.max.y);
    p.scale(1.0, -1.0);
    drawPieces(pages, pattern, g.pieces, true);
    p.restore();
    for (int r = 0; r < rows; ++r) {
        for (int c = 0; c < columns; ++c) {
            const QRectF tile(c * stepX, r * stepY, plan.content.x, plan.content.y);
            QPen pen = pages.pen(QColor(0x30, 0x70, 0xc0), 0.4 / scale);
            pen.setStyle(Qt::DashLine);
            p.setPen(pen);
            p.setBrush(Qt::NoBrush);
            p.drawRect(tile);
            p.setFont(pages.font(std::min(plan.content.x, plan.content.y) * 0.12));
            p.setPen(QColor(0x30, 0x70, 0xc0));
            p.drawText(tile, Qt::AlignCenter,
                       QString::fromStdString(rowName(r)) + QString::number(c + 1));
        }
    }
    p.restore();
}

void paintTile(PagePainter& pages, const model::CuttingPattern& pattern, const PagePlan& plan,
               const PageTile& tile, int pageNumber, int pageCount) {
    QPainter& p = pages.painter();
    const SheetGroup& g = plan.groups[std::size_t(tile.group)];
    const int rows = plan.rows[std::size_t(tile.group)];
    const int columns = plan.columns[std::size_t(tile.group)];
    const QRectF content(plan.contentOrigin.x, plan.contentOrigin.y, plan.content.x,
                         plan.content.y);
    const double o = plan.overlap;

    // Overlap strips (shared with the next page to the right and below): lightly shaded.
    p.setPen(Qt::NoPen);
    p.setBrush(QColor(0xee, 0xee, 0xee));
    if (tile.column + 1 < columns) {
        p.drawRect(QRectF(content.right() - o, content.top(), o, content.height()));
    }
    if (tile.row + 1 < rows) {
        p.drawRect(QRectF(content.left(), content.bottom() - o, content.width(), o));
    }

    // The pattern at 1:1, clipped to the content area.
    p.save();
    p.setClipRect(content);
    p.translate(content.left() - tile.origin.x, content.top() + tile.origin.y);
    p.scale(1.0, -1.0);
    drawPieces(
        pages, pattern, g.pieces, false,
        QRectF(tile.origin.x, tile.origin.y - plan.content.y, plan.content.x, plan.content.y));
    // Registration marks in the middle of every shared strip, at the same pattern points on
    // both pages, so that taped pages line up.
    p.setPen(pages.pen(Qt::black, 0.15));
    p.setBrush(Qt::NoBrush);
    const double stepX = plan.content.x - o;
    const double stepY = plan.content.y - o;
    for (int c : {tile.column, tile.column + 1}) { // strips left and right of this tile
        if (c < 1 || c >= columns) {
            continue;
        }
        const double x = g.min.x + c * stepX + 0.5 * o;
        for (double f : {0.25, 0.75}) {
            registrationMark(p, QPointF(x, tile.origin.y - f * plan.content.y));
        }
    }
    for (int r : {tile.row, tile.row + 1}) {
        if (r < 1 || r >= rows) {
            continue;
        }
        const double y = g.max.y - r * stepY - 0.5 * o;
        for (double f : {0.25, 0.75}) {
            registrationMark(p, QPointF(tile.origin.x + f * plan.content.x, y));
        }
    }
    p.restore();

    // Crop marks at the corners of the content area, outside it.
    p.setPen(pages.pen(Qt::black, 0.2));
    for (const QPointF& corner :
         {content.topLeft(), content.topRight(), content.bottomLeft(), content.bottomRight()}) {
        const double sx = corner.x() < content.center().x() ? -1.0 : 1.0;
        const double sy = corner.y() < content.center().y() ? -1.0 : 1.0;
        p.drawLine(corner + QPointF(sx * 1.0, 0.0), corner + QPointF(sx * 6.0, 0.0));
        p.drawLine(corner + QPointF(0.0, sy * 1.0), corner + QPointF(0.0, sy * 6.0));
    }

    const QString where =
        groupName(pattern, g, false) + QStringLiteral(", row %1 of %2, column %3 of %4")
                                           .arg(QString::fromStdString(rowName(tile.row)))
                                           .arg(rows)
                                           .arg(tile.column + 1)
                                           .arg(columns);
    paintBand(pages, plan, QString::fromStdString(tile.label), where,
              QStringLiteral("Page %1 of %2. Print at 100 % (no fit to page): the squares "
                             "measure 50 mm and 1 inch. Trim at the crop marks, overlap the "
                             "shaded strip, align the registration marks.")
                  .arg(pageNumber)
                  .arg(pageCount),
              &pattern);
}

int reportPageCount(const model::CuttingPattern& pattern, const PagePlan& plan) {
    const int rest = static_cast<int>(pattern.pieces.size()) - reportRows(plan, true);
    const int perPage = reportRows(plan, false);
    return 1 + std::max(0, (rest + perPage - 1) / perPage);
}

} // namespace

QPageSize pageSizeOf(Paper paper) {
    switch (paper) {
    case Paper::A3:
        return QPageSize(QPageSize::A3);
    case Paper::Letter:
        return QPageSize(QPageSize::Letter);
    case Paper::A4:
        break;
    }
    return QPageSize(QPageSize::A4);
}

void preparePagedDevice(QPagedPaintDevice& device, const QPageSize& pageSize,
                        const PagePlan& plan) {
    // One at a time: a printer that refuses zero margins still gets the size and orientation.
    device.setPageSize(pageSize);
    device.setPageOrientation(plan.landscape ? QPageLayout::Landscape : QPageLayout::Portrait);
    device.setPageMargins(QMarginsF(0, 0, 0, 0), QPageLayout::Millimeter);
}

int patternPageCount(const model::CuttingPattern& pattern, const PagePlan& plan) {
    return reportPageCount(pattern, plan) + int(plan.groups.size()) + int(plan.tiles.size());
}

bool paintPatternPages(QPagedPaintDevice& device, const model::CuttingPattern& pattern,
                       const PagePlan& plan, const std::vector<std::string>& problemTexts,
                       const PatternProgress& progress) {
    QPainter painter;
    if (!painter.begin(&device)) {
        return false;
    }
    painter.setRenderHint(QPainter::Antialiasing);
    PagePainter pages(painter, device.logicalDpiX());
    const FabricationReport report = fabricationReport(pattern, problemTexts);
    const int reportPages = reportPageCount(pattern, plan);
    const int total = patternPageCount(pattern, plan);
    int page = 0;
    auto next = [&]() {
        if (page > 0) {
            device.newPage();
        }
        pages.startPage();
    };
    auto done = [&]() {
        ++page;
        return !progress || progress(page, total);
    };
    for (int r = 0; r < reportPages; ++r) {
        next();
        paintReportPage(pages, plan, report, r, reportPages, total);
        if (!done()) {
            painter.end();
            return false;
        }
    }
    for (std::size_t g = 0; g < plan.groups.size(); ++g) {
        next();
        paintOverview(pages, pattern, plan, int(g), page + 1, total);
        if (!done()) {
            painter.end();
            return false;
        }
        for (const PageTile& tile : plan.tiles) {
            if (tile.group != int(g)) {
                continue;
            }
            next();
            paintTile(pages, pattern, plan, tile, page + 1, total);
            if (!done()) {
                painter.end();
                return false;
            }
        }
    }
    return painter.end();
}

} // namespace devsurf::io
