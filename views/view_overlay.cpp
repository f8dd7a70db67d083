#include "view_overlay.h"

#include <QFontMetricsF>
#include <QPaintEvent>
#include <QPainter>
#include <QPainterPath>
#include <QPen>

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

void ViewOverlay::setFoldLegend(bool mountains, bool valleys) {
    if (mountains != m_mountains || valleys != m_valleys) {
        m_mountains = mountains;
        m_valleys = valleys;
        update();
    }
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

    // Fold legend: the origami colours of the creases, upper left.
    std::vector<std::pair<QColor, QString>> folds;
    if (m_mountains) {
        folds.emplace_back(QColor(230, 25, 25), tr("Mountain fold"));
    }
    if (m_valleys) {
        folds.emplace_back(QColor(25, 90, 240), tr("Valley fold"));
    }
    double top = 10.0;
    for (const auto& [colour, text] : folds) {
        const QRectF box(10.0, top, 40.0 + metrics.horizontalAdvance(text) + 12.0,
                         metrics.height() + 6.0);
        painter.setPen(Qt::NoPen);
        painter.setBrush(halo);
        painter.drawRoundedRect(box, 3, 3);
        painter.setPen(QPen(colour, 4.0));
        painter.drawLine(QPointF(box.left() + 6.0, box.center().y()),
                         QPointF(box.left() + 34.0, box.center().y()));
        painter.setPen(ink);
        painter.drawText(box.adjusted(40.0, 0, 0, 0), Qt::AlignVCenter | Qt::AlignLeft, text);
        top += box.height() + 4.0;
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
