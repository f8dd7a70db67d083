#include "view_overlay.h"

#include "crease_marks.h"
#include "model/document/commands/crease_condition_command.h"
#include "quality_colours.h"

#include <QFontMetricsF>
#include <QPaintEvent>
#include <QPainter>
#include <QPainterPath>
#include <QPen>
#include <QPolygonF>

#include <algorithm>
#include <cmath>

namespace devsurf::views {

ViewOverlay::ViewOverlay(QWidget* parent) : QWidget(parent) {
    setObjectName(QStringLiteral("viewOverlay"));
    setAttribute(Qt::WA_TransparentForMouseEvents);
    setAttribute(Qt::WA_NoSystemBackground);
    setAttribute(Qt::WA_TranslucentBackground);
    setFocusPolicy(Qt::NoFocus);
}

void ViewOverlay::setScaleBar(double pixels, const QString& text) {
    if (std::abs(pixels - m_barPixels) < 0.25 && text == m_barText) {
        return;
    }
    m_barPixels = pixels;
    m_barText = text;
    update();
}

void ViewOverlay::setLabels(std::vector<Label> labels) {
    bool same = labels.size() == m_labels.size();
    for (std::size_t i = 0; same && i < labels.size(); ++i) {
        same = labels[i].text == m_labels[i].text &&
               (labels[i].position - m_labels[i].position).manhattanLength() < 0.5;
    }
    if (!same) {
        m_labels = std::move(labels);
        update();
    }
}

void ViewOverlay::setFoldLegend(bool mountains, bool valleys, bool flat) {
    if (mountains != m_mountains || valleys != m_valleys || flat != m_flatCreases) {
        m_mountains = mountains;
        m_valleys = valleys;
        m_flatCreases = flat;
        update();
    }
}

QColor ViewOverlay::foldColour(model::FoldAssignment fold) {
    switch (fold) {
    case model::FoldAssignment::Mountain:
        return {230, 25, 25};
    case model::FoldAssignment::Valley:
        return {25, 90, 240};
    case model::FoldAssignment::Flat:
        break;
    }
    return {140, 0, 25};
}

QString ViewOverlay::badgeText(model::CreaseCondition condition) {
    switch (condition) {
    case model::CreaseCondition::CurvedFold:
        return tr("CF", "badge: curved fold");
    case model::CreaseCondition::Geodesic:
        return tr("G", "badge: geodesic");
    case model::CreaseCondition::Straight:
        return tr("SU", "badge: straight when unfolded");
    case model::CreaseCondition::None:
        break;
    }
    return QString();
}

QColor ViewOverlay::badgeColour(model::CreaseCondition condition) {
    switch (condition) {
    case model::CreaseCondition::CurvedFold:
        return {125, 45, 170};
    case model::CreaseCondition::Geodesic:
        return {0, 115, 120};
    case model::CreaseCondition::Straight:
        return {150, 85, 10};
    case model::CreaseCondition::None:
        break;
    }
    return {90, 90, 90};
}

QColor ViewOverlay::smoothRulingColour() {
    return {255, 255, 255};
}

QColor ViewOverlay::sheetColour() {
    return QColor::fromRgbF(0.86f, 0.62f, 0.30f);
}

void ViewOverlay::setSheetLegend(bool sheet) {
    if (sheet != m_sheet) {
        m_sheet = sheet;
        update();
    }
}

QColor ViewOverlay::sharpRulingColour() {
    return {89, 89, 89};
}

void ViewOverlay::setMarkLegend(std::vector<model::CreaseCondition> conditions, bool smoothRulings,
                                bool sharpRulings) {
    sharpRulings = sharpRulings && smoothRulings;
    if (conditions != m_conditions || smoothRulings != m_smoothRulings ||
        sharpRulings != m_sharpRulings) {
        m_conditions = std::move(conditions);
        m_smoothRulings = smoothRulings;
        m_sharpRulings = sharpRulings;
        update();
    }
}

void ViewOverlay::setBadges(std::vector<Badge> badges) {
    bool same = badges.size() == m_badges.size();
    for (std::size_t i = 0; same && i < badges.size(); ++i) {
        same = badges[i].condition == m_badges[i].condition &&
               (badges[i].position - m_badges[i].position).manhattanLength() < 0.5;
    }
    if (!same) {
        m_badges = std::move(badges);
        update();
    }
}

std::vector<ViewOverlay::LegendEntry> ViewOverlay::legend() const {
    std::vector<LegendEntry> entries;
    using model::FoldAssignment;
    if (m_mountains) {
        entries.push_back({foldColour(FoldAssignment::Mountain), QString(), tr("Mountain fold"),
                           foldDashes(FoldAssignment::Mountain)});
    }
    if (m_valleys) {
        entries.push_back({foldColour(FoldAssignment::Valley), QString(), tr("Valley fold"),
                           foldDashes(FoldAssignment::Valley)});
    }
    if (m_flatCreases) {
        entries.push_back({foldColour(FoldAssignment::Flat), QString(), tr("Crease, not folded"),
                           foldDashes(FoldAssignment::Flat)});
    }
    for (model::CreaseCondition condition : m_conditions) {
        entries.push_back({badgeColour(condition),
                           badgeText(condition),
                           document::CreaseConditionCommand::conditionText(condition),
                           {}});
    }
    if (m_smoothRulings) {
        entries.push_back({smoothRulingColour(), QString(), tr("Smooth ruling"), {}});
    }
    if (m_sharpRulings) {
        entries.push_back({sharpRulingColour(), QString(), tr("Sharp ruling"), {}});
    }
    if (m_sheet) {
        entries.push_back({sheetColour(), QString(), tr("Sheet"), {}});
    }
    return entries;
}

QStringList ViewOverlay::legendEntries() const {
    QStringList texts;
    for (const LegendEntry& entry : legend()) {
        texts << (entry.badge.isEmpty() ? entry.text : entry.badge + QLatin1Char(' ') + entry.text);
    }
    return texts;
}

void ViewOverlay::setVerdict(const QString& text, const QColor& colour) {
    m_verdict = text;
    m_verdictColour = colour;
    update();
}

// The verdict leaves this much of the width (logical pixels) to the legend in the upper left.
constexpr double kVerdictClear = 180.0;

QRectF ViewOverlay::verdictRect() const {
    if (m_verdict.isEmpty()) {
        return QRectF();
    }
    QFont strong = font();
    strong.setPointSizeF(strong.pointSizeF() * 0.9);
    strong.setBold(true);
    const QFontMetricsF metrics(strong);
    const double width = std::min(metrics.horizontalAdvance(m_verdict) + 12.0,
                                  std::max(40.0, this->width() - kVerdictClear));
    return QRectF(this->width() - 10.0 - width, 10.0, width, metrics.height() + 8.0);
}

void ViewOverlay::setMeasurement(std::vector<QPointF> points, const QString& text) {
    if (points == m_measured && text == m_measuredText) {
        return;
    }
    m_measured = std::move(points);
    m_measuredText = text;
    update();
}

void ViewOverlay::setLasso(std::vector<QPointF> points) {
    if (points == m_lasso) {
        return;
    }
    m_lasso = std::move(points);
    update();
}

void ViewOverlay::setQualityLegend(std::optional<QualityLegend> legend) {
    const bool same =
        legend.has_value() == m_quality.has_value() &&
        (!legend || (legend->title == m_quality->title && legend->colours == m_quality->colours &&
                     legend->tolerance == m_quality->tolerance &&
                     legend->toleranceLabel == m_quality->toleranceLabel));
    m_quality = std::move(legend);
    if (!same) {
        update();
    }
}

void ViewOverlay::setDistanceLegend(std::optional<DistanceLegend> legend) {
    if (legend == m_distance) {
        return;
    }
    m_distance = std::move(legend);
    update();
}

QRectF ViewOverlay::distanceLegendRect() const {
    if (!m_distance) {
        return QRectF();
    }
    const QualityColouring::Box box = QualityColouring::legendBox(width(), height());
    QRectF rect(QPointF(box.left, height() - box.top), QPointF(box.right, height() - box.bottom));
    if (m_quality) {
        rect.translate(-(rect.width() + 8.0), 0.0);
    }
    return rect;
}

QRectF ViewOverlay::qualityLegendRect() const {
    if (!m_quality) {
        return QRectF();
    }
    const QualityColouring::Box box = QualityColouring::legendBox(width(), height());
    return QRectF(QPointF(box.left, height() - box.top), QPointF(box.right, height() - box.bottom));
}

void ViewOverlay::paintQualityLegend(QPainter& painter, const QFont& font) const {
    const QualityLegend& legend = *m_quality;
    const QRectF box = qualityLegendRect();
    const QFontMetricsF metrics(font);
    painter.setPen(Qt::NoPen);
    painter.setBrush(QColor(255, 255, 255, 200));
    painter.drawRoundedRect(box, 4, 4);
    // The title, line by line, elided to the box.
    const QStringList lines = legend.title.split(QLatin1Char('\n'));
    double y = box.top() + 4.0;
    painter.setPen(QColor(25, 25, 25));
    for (const QString& line : lines) {
        painter.drawText(QRectF(box.left() + 4.0, y, box.width() - 8.0, metrics.height()),
                         Qt::AlignLeft | Qt::AlignVCenter,
                         metrics.elidedText(line, Qt::ElideRight, box.width() - 8.0));
        y += metrics.height();
    }
    // The bar, low at the bottom; a value's height is linear in its logarithm.
    const double top = y + 0.5 * metrics.height() + 4.0;
    const double bottom = box.bottom() - 0.5 * metrics.height() - 6.0;
    if (bottom <= top || legend.colours.empty() || legend.low <= 0.0 || legend.high <= legend.low) {
        return;
    }
    const QRectF bar(box.left() + 6.0, top, 14.0, bottom - top);
    const double lowLog = std::log10(legend.low);
    const double span = std::log10(legend.high) - lowLog;
    auto heightOf = [&](double value) {
        return bottom - (std::log10(value) - lowLog) / span * (bottom - top);
    };
    const auto count = static_cast<double>(legend.colours.size());
    for (std::size_t i = 0; i < legend.colours.size(); ++i) {
        const double from = bottom - (static_cast<double>(i) + 1.0) / count * bar.height();
        const double to = bottom - static_cast<double>(i) / count * bar.height();
        painter.fillRect(QRectF(bar.left(), from, bar.width(), to - from + 0.5), legend.colours[i]);
    }
    painter.setPen(QPen(QColor(60, 60, 60), 1.0));
    painter.setBrush(Qt::NoBrush);
    painter.drawRect(bar);
    // A label every second decade.
    for (int decade = static_cast<int>(std::ceil(lowLog - 1e-9));
         decade <= static_cast<int>(std::floor(lowLog + span + 1e-9)); decade += 2) {
        const double at = heightOf(std::pow(10.0, decade));
        painter.drawLine(QPointF(bar.right(), at), QPointF(bar.right() + 4.0, at));
        painter.drawText(QRectF(bar.right() + 6.0, at - metrics.height(), box.right() - bar.right(),
                                2.0 * metrics.height()),
                         Qt::AlignLeft | Qt::AlignVCenter, QStringLiteral("1e%1").arg(decade));
    }
    // The tolerance: a heavy line across the bar, "developable" beside the colours below it.
    const double mark = heightOf(std::clamp(legend.tolerance, legend.low, legend.high));
    paintLegendTolerance(painter, box, bar, mark, heightOf(legend.tolerance / 10.0),
                         legend.toleranceLabel, font);
}

void ViewOverlay::paintEvent(QPaintEvent*) {
    QPainter painter(this);
    painter.setRenderHint(QPainter::Antialiasing);
    const QColor ink(25, 25, 25);
    const QColor halo(255, 255, 255, 200);

    QFont font = painter.font();
    font.setPointSizeF(font.pointSizeF() * 0.9);
    painter.setFont(font);
    const QFontMetricsF metrics(font);

    // Patch numbers: dark text on a pale rounded box, readable over any patch colour.
    for (const Label& label : m_labels) {
        QRectF box = metrics.boundingRect(label.text).adjusted(-3, -1, 3, 1);
        box.moveCenter(label.position);
        if (!rect().intersects(box.toAlignedRect())) {
            continue;
        }
        painter.setPen(Qt::NoPen);
        painter.setBrush(halo);
        painter.drawRoundedRect(box, 3, 3);
        painter.setPen(ink);
        painter.drawText(box, Qt::AlignCenter, label.text);
    }

    // Crease conditions: white letters on a box in the condition's colour, at the midpoints.
    QFont bold = font;
    bold.setBold(true);
    bold.setPointSizeF(font.pointSizeF() * 0.85);
    const QFontMetricsF boldMetrics(bold);
    auto drawBadge = [&](const QPointF& centre, const QString& text, const QColor& colour) {
        QRectF box = boldMetrics.boundingRect(text).adjusted(-3, -1, 3, 1);
        box.moveCenter(centre);
        painter.setPen(QPen(QColor(255, 255, 255, 230), 1.5));
        painter.setBrush(colour);
        painter.drawRoundedRect(box, 3, 3);
        painter.setPen(Qt::white);
        painter.setFont(bold);
        painter.drawText(box, Qt::AlignCenter, text);
        painter.setFont(font);
    };
    for (const Badge& badge : m_badges) {
        if (rect().contains(badge.position.toPoint())) {
            drawBadge(badge.position, badgeText(badge.condition), badgeColour(badge.condition));
        }
    }

    // Legend, upper left: the origami colours of the creases, the condition badges and the
    // smooth and sharp rulings.
    double top = 10.0;
    for (const LegendEntry& entry : legend()) {
        // Swatches long enough for a whole period of the mountain's dash-dot.
        const QRectF box(10.0, top, 58.0 + metrics.horizontalAdvance(entry.text) + 10.0,
                         metrics.height() + 6.0);
        painter.setPen(Qt::NoPen);
        painter.setBrush(halo);
        painter.drawRoundedRect(box, 3, 3);
        const QPointF swatch(box.left() + 26.0, box.center().y());
        if (!entry.badge.isEmpty()) {
            drawBadge(swatch, entry.badge, entry.colour);
        } else {
            // A line as the views draw it, on a grey ground so that a light line shows.
            painter.setBrush(QColor(170, 175, 185));
            painter.drawRect(QRectF(swatch.x() - 23.0, swatch.y() - 4.0, 46.0, 8.0));
            QPen pen(entry.colour, 4.0);
            pen.setCapStyle(Qt::FlatCap);
            if (!entry.dashes.empty()) {
                // Qt counts dashes in pen widths.
                QVector<qreal> dashes;
                for (double length : entry.dashes) {
                    dashes << length * kFoldDashUnitPixels / pen.widthF();
                }
                pen.setDashPattern(dashes);
            }
            painter.setPen(pen);
            painter.drawLine(swatch - QPointF(22.0, 0.0), swatch + QPointF(22.0, 0.0));
        }
        painter.setPen(ink);
        painter.drawText(box.adjusted(58.0, 0, 0, 0), Qt::AlignVCenter | Qt::AlignLeft, entry.text);
        top += box.height() + 4.0;
    }

    // The measurement: a dark line with its picked points, its text beside the last one.
    if (!m_measured.empty()) {
        painter.setPen(QPen(QColor(20, 20, 20), 2.0));
        for (std::size_t i = 1; i < m_measured.size(); ++i) {
            painter.drawLine(m_measured[i - 1], m_measured[i]);
        }
        painter.setBrush(QColor(255, 200, 0));
        for (const QPointF& point : m_measured) {
            painter.drawEllipse(point, 4.0, 4.0);
        }
        if (!m_measuredText.isEmpty()) {
            QRectF box = metrics.boundingRect(m_measuredText).adjusted(-4, -2, 4, 2);
            box.moveTopLeft(m_measured.back() + QPointF(8.0, 8.0));
            // Kept inside the view: left of the point, or above it, where it would leave it.
            if (box.right() > width() - 4.0) {
                box.moveRight(m_measured.back().x() - 8.0);
            }
            if (box.bottom() > height() - 4.0) {
                box.moveBottom(m_measured.back().y() - 8.0);
            }
            painter.setPen(Qt::NoPen);
            painter.setBrush(QColor(255, 255, 255, 230));
            painter.drawRoundedRect(box, 3, 3);
            painter.setPen(QColor(20, 20, 20));
            painter.drawText(box, Qt::AlignCenter, m_measuredText);
        }
    }

    // The lasso: closed, dark under a dashed magenta line, so that it reads on any background.
    if (m_lasso.size() >= 2) {
        const QPolygonF polygon(QList<QPointF>(m_lasso.begin(), m_lasso.end()));
        painter.setBrush(QColor(215, 0, 215, 40));
        painter.setPen(QPen(QColor(20, 20, 20), 3.0));
        painter.drawPolygon(polygon);
        QPen dashed(QColor(215, 0, 215), 2.0, Qt::DashLine);
        painter.setPen(dashed);
        painter.setBrush(Qt::NoBrush);
        painter.drawPolygon(polygon);
    }

    if (m_quality) {
        paintQualityLegend(painter, font);
    }
    if (m_distance) {
        paintDistanceLegend(painter, distanceLegendRect(), *m_distance, font);
    }

    // The verdict of the last solve, upper right, in its colour; elided to half the width so
    // that it never covers the legend.
    if (!m_verdict.isEmpty()) {
        QFont strong = font;
        strong.setBold(true);
        const QFontMetricsF strongMetrics(strong);
        const QRectF box = verdictRect();
        painter.setPen(QPen(m_verdictColour, 1.5));
        painter.setBrush(halo);
        painter.drawRoundedRect(box, 4, 4);
        painter.setPen(m_verdictColour);
        painter.setFont(strong);
        painter.drawText(box, Qt::AlignCenter,
                         strongMetrics.elidedText(m_verdict, Qt::ElideRight, box.width() - 12.0));
        painter.setFont(font);
    }

    if (m_barPixels <= 0.0) {
        return;
    }
    // Scale bar: a bar with end ticks, its length written above it, in the lower right.
    const double margin = 14.0;
    const double right = width() - margin;
    const double left = right - m_barPixels;
    const double y = height() - margin;
    const QRectF textBox(left - 40.0, y - 8.0 - metrics.height(), m_barPixels + 80.0,
                         metrics.height());
    QRectF backing = QRectF(left, y - 8.0 - metrics.height(), m_barPixels, metrics.height() + 12.0)
                         .united(metrics.boundingRect(textBox, Qt::AlignCenter, m_barText))
                         .adjusted(-6, -3, 6, 3);
    painter.setPen(Qt::NoPen);
    painter.setBrush(halo);
    painter.drawRoundedRect(backing, 4, 4);
    QPen pen(ink, 2.0);
    pen.setCapStyle(Qt::FlatCap);
    painter.setPen(pen);
    painter.drawLine(QPointF(left, y), QPointF(right, y));
    painter.drawLine(QPointF(left, y - 6), QPointF(left, y + 1));
    painter.drawLine(QPointF(right, y - 6), QPointF(right, y + 1));
    painter.drawText(textBox, Qt::AlignCenter, m_barText);
}

} // namespace devsurf::views
