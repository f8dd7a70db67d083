#pragma once

#include <QRect>
#include <QStatusBar>

namespace devsurf::app {

// The main window's status bar: a temporary message longer than the space left of the
// permanent widgets (the counts, the solve progress) is elided at its end instead of running
// into them, with the whole message in the tooltip.
class ElidingStatusBar : public QStatusBar {
    Q_OBJECT
public:
    explicit ElidingStatusBar(QWidget* parent = nullptr);

    // Where the message is drawn: from the left edge to the first visible permanent widget.
    QRect messageRect() const;
    // The message as drawn (elided to messageRect()), empty without one.
    QString shownMessage() const;

protected:
    void paintEvent(QPaintEvent* event) override;
};

} // namespace devsurf::app
