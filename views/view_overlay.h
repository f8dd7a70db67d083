#pragma once

#include <QPointF>
#include <QString>
#include <QWidget>

#include <vector>

namespace devsurf::views {

// What a view paints over its rendering with QPainter: a scale bar in the lower right corner
// and, optionally, the patch numbers at their patches. It ignores the mouse, so picking and
// the camera work through it.
class ViewOverlay : public QWidget {
    Q_OBJECT
public:
    struct Label {
        QPointF position; // widget coordinates
        QString text;
    };

    explicit ViewOverlay(QWidget* parent);

    // Scale bar of the given length on screen (logical pixels) and its text, e.g. "50 mm";
    // none when pixels is not positive.
    void setScaleBar(double pixels, const QString& text);
    void setLabels(std::vector<Label> labels);
    // The fold legend in the upper left corner: a red line "Mountain fold" and a blue line
    // "Valley fold", for those present.
    void setFoldLegend(bool mountains, bool valleys);
    bool showsMountainLegend() const { return m_mountains; }
    bool showsValleyLegend() const { return m_valleys; }

    double scaleBarPixels() const { return m_barPixels; }
    QString scaleBarText() const { return m_barText; }
    const std::vector<Label>& labels() const { return m_labels; }

protected:
    void paintEvent(QPaintEvent* event) override;

private:
    double m_barPixels = 0.0;
    QString m_barText;
    std::vector<Label> m_labels;
    bool m_mountains = false;
    bool m_valleys = false;
};

} // namespace devsurf::views
