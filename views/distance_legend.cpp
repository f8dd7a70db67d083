#include "distance_legend.h"

#include <QCoreApplication>
#include <QFontMetricsF>
#include <QLocale>
#include <QPainter>
#include <QStringList>

#include <algorithm>
#include <cmath>

namespace devsurf::views {

namespace {

// Four significant digits, whole millimetres from a metre on (no exponent).
QString lengthLabel(double millimetres) {
    return std::abs(millimetres) >= 1000.0 ? QLocale().toString(millimetres, 'f', 0)
                                           : QLocale().toString(millimetres, 'g', 4);
}

} // namespace

QColor fadedColour(const QColor& colour) {
    constexpr float kGrey = 0.62f;
    return QColor::fromRgbF(0.5f * (colour.redF() + kGrey), 0.5f * (colour.greenF() + kGrey),
                            0.5f * (colour.blueF() + kGrey));
}

void paintDistanceLegend(QPainter& painter, const QRectF& box, const DistanceLegend& legend,
                         const QFont& font) {
    const QFontMetricsF metrics(font);
    painter.setPen(Qt::NoPen);
    painter.setBrush(QColor(255, 255, 255, 200));
    painter.drawRoundedRect(box, 4, 4);
    QStringList lines = legend.title.split(QLatin1Char('\n'));
    if (!legend.note.isEmpty()) {
        lines << legend.note;
    }
    double y = box.top() + 4.0;
    for (int i = 0; i < lines.size(); ++i) {
        const bool note = !legend.note.isEmpty() && i == lines.size() - 1;
        painter.setPen(note ? QColor(150, 90, 0) : QColor(25, 25, 25));
        painter.drawText(QRectF(box.left() + 4.0, y, box.width() - 8.0, metrics.height()),
                         Qt::AlignLeft | Qt::AlignVCenter,
                         metrics.elidedText(lines[i], Qt::ElideRight, box.width() - 8.0));
        y += metrics.height();
    }
    const double top = y + 0.5 * metrics.height() + 4.0;
    const double bottom = box.bottom() - 0.5 * metrics.height() - 6.0;
    if (bottom <= top || legend.colours.empty() || legend.high <= 0.0) {
        return;
    }
    // The bar, 0 at the bottom, linear in mm.
    const QRectF bar(box.left() + 6.0, top, 14.0, bottom - top);
    const auto count = static_cast<double>(legend.colours.size());
    for (std::size_t i = 0; i < legend.colours.size(); ++i) {
        const double from = bottom - (static_cast<double>(i) + 1.0) / count * bar.height();
        const double to = bottom - static_cast<double>(i) / count * bar.height();
        const QColor& colour = legend.colours[i];
        painter.fillRect(QRectF(bar.left(), from, bar.width(), to - from + 0.5),
                         legend.stale ? fadedColour(colour) : colour);
    }
    painter.setPen(QPen(QColor(60, 60, 60), 1.0));
    painter.setBrush(Qt::NoBrush);
    painter.drawRect(bar);
    auto heightOf = [&](double mm) { return bottom - mm / legend.high * bar.height(); };
    QFont strong = font;
    strong.setBold(true);
    const QFontMetricsF strongMetrics(strong);
    // The tolerance's label sits just below its mark (inside the bar's height).
    const double mark = heightOf(std::clamp(legend.tolerance, 0.0, legend.high));
    const double labelCentre =
        std::min(bottom - 0.5 * strongMetrics.height(), mark + 0.5 * strongMetrics.height() + 2.0);
    // Five steps of a fifth of the top (a round length, so are they), "mm" at the top.
    for (int step = 0; step <= 5; ++step) {
        const double mm = legend.high * step / 5.0;
        const double at = heightOf(mm);
        painter.drawLine(QPointF(bar.right(), at), QPointF(bar.right() + 4.0, at));
        if (std::abs(at - labelCentre) < 0.5 * (metrics.height() + strongMetrics.height())) {
            continue; // the tolerance's label is written there
        }
        const QString text =
            step == 5 ? QCoreApplication::translate("SceneView", "%1 mm").arg(lengthLabel(mm))
                      : lengthLabel(mm);
        painter.drawText(QRectF(bar.right() + 6.0, at - metrics.height(), box.right() - bar.right(),
                                2.0 * metrics.height()),
                         Qt::AlignLeft | Qt::AlignVCenter, text);
    }
    // The tolerance, its label beside the colours below it.
    paintLegendTolerance(painter, box, bar, mark, labelCentre, legend.toleranceLabel, font);
}

void paintLegendTolerance(QPainter& painter, const QRectF& box, const QRectF& bar, double mark,
                          double labelCentre, const QString& label, const QFont& font) {
    painter.setPen(QPen(QColor(20, 20, 20), 2.5));
    painter.drawLine(QPointF(bar.left() - 3.0, mark), QPointF(bar.right() + 3.0, mark));
    QFont strong = font;
    strong.setBold(true);
    painter.setFont(strong);
    const QFontMetricsF strongMetrics(strong);
    const QRectF labelBox(bar.right() + 6.0, labelCentre - 0.5 * strongMetrics.height(),
                          box.right() - bar.right() - 8.0, strongMetrics.height());
    painter.setPen(Qt::NoPen);
    painter.setBrush(QColor(255, 255, 255, 235));
    painter.drawRect(labelBox);
    painter.setPen(QColor(0x1b, 0x7a, 0x2e));
    painter.drawText(labelBox, Qt::AlignLeft | Qt::AlignVCenter,
                     strongMetrics.elidedText(label, Qt::ElideRight, labelBox.width()));
    painter.setFont(font);
}

} // namespace devsurf::views
