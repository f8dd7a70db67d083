#pragma once

#include "model/document/selection.h"
#include "model/vec3.h"

#include <QObject>
#include <QPoint>
#include <QString>

#include <vector>

class QAction;

namespace devsurf::views {
class SurfaceView;
}

namespace devsurf::app {

class Workspace;

// Tools ▸ Measure: two points clicked on the surface in the 3D view, their distance in space
// and along the sheet (between their places on the development, as the cut pattern has them),
// drawn in the view and said in the status bar; Tools ▸ Copy Measurement (Ctrl+C) copies it.
// A click without moving picks; dragging still turns the camera. A third click starts anew;
// an edit of the design clears the measurement. With the tool on, selecting one edge measures
// its length (along its curve) and two edges that meet the angle between them there.
class MeasureTool : public QObject {
    Q_OBJECT
public:
    MeasureTool(QAction* action, QAction* copy, Workspace* workspace, views::SurfaceView* view);

    // "3D 123.4 mm, along the sheet 130.2 mm", empty before the second point.
    QString text() const { return m_text; }
    double spaceDistance() const { return m_space; }
    // Negative when the points lie on different surfaces or off the development.
    double sheetDistance() const { return m_sheet; }

signals:
    void statusMessage(const QString& text);

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    struct Point {
        model::Vec3 space;
        document::Pick face;
    };
    void pick(const QPoint& widgetPos);
    // The length of one selected edge, or the angle of two that meet; false if neither.
    bool measureSelectedEdges();
    void clear();
    void show();

    QAction* m_action;
    QAction* m_copy;
    Workspace* m_workspace;
    views::SurfaceView* m_view;
    std::vector<Point> m_points;
    QPoint m_pressAt;
    bool m_pressed = false;
    QString m_text;
    double m_space = -1.0;
    double m_sheet = -1.0;
};

} // namespace devsurf::app
