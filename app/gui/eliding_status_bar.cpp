#include "eliding_status_bar.h"

#include <QPainter>
#include <QSizeGrip>
#include <QStyleOption>

#include <algorithm>

namespace devsurf::app {

ElidingStatusBar::ElidingStatusBar(QWidget* parent) : QStatusBar(parent) {
    setObjectName(QStringLiteral("statusBar"));
    connect(this, &QStatusBar::messageChanged, this, [this](const QString& message) {
        setToolTip(shownMessage() != message ? message : QString());
    });
}

QRect ElidingStatusBar::messageRect() const {
    const bool rtl = layoutDirection() == Qt::RightToLeft;
    int left = 6;
    int right = width() - 12;
    // While a message shows, the visible children are the permanent widgets (and the grip).
    for (const QWidget* child : findChildren<QWidget*>(QString(), Qt::FindDirectChildrenOnly)) {
        if (!child->isVisible() || qobject_cast<const QSizeGrip*>(child) != nullptr) {
            continue;
        }
        if (rtl) {
            left = std::max(left, child->geometry().right() + 6);
        } else {
            right = std::min(right, child->x() - 6);
        }
    }
    return QRect(left, 0, std::max(0, right - left), height());
}

QString ElidingStatusBar::shownMessage() const {
    const QString message = currentMessage();
    return message.isEmpty()
               ? message
               : fontMetrics().elidedText(message, Qt::ElideRight, messageRect().width());
}

void ElidingStatusBar::paintEvent(QPaintEvent* event) {
    if (currentMessage().isEmpty()) {
        QStatusBar::paintEvent(event);
        return;
    }
    QPainter painter(this);
    QStyleOption option;
    option.initFrom(this);
    style()->drawPrimitive(QStyle::PE_PanelStatusBar, &option, &painter, this);
    painter.setPen(palette().windowText().color());
    painter.drawText(messageRect(), Qt::AlignLeading | Qt::AlignVCenter | Qt::TextSingleLine,
                     shownMessage());
}

} // namespace devsurf::app
