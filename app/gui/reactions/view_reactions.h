#pragma once

#include <QObject>

class QAction;
class QActionGroup;

namespace devsurf::views {
class SurfaceView;
class DevelopmentView;
} // namespace devsurf::views

namespace devsurf::app {

// View ▸ 3D / Development / both: which of the two views the window shows.
class ViewLayoutReaction : public QObject {
    Q_OBJECT
public:
    ViewLayoutReaction(QAction* only3d, QAction* onlyDevelopment, QAction* both,
                       views::SurfaceView* surfaceView, views::DevelopmentView* developmentView);

private:
    void apply(QAction* chosen);
    QAction* m_only3d;
    QAction* m_onlyDevelopment;
    views::SurfaceView* m_surfaceView;
    views::DevelopmentView* m_developmentView;
};

// View ▸ Control Polygons / Vertices in the 3D view; the choice is remembered.
class ToggleDisplayReaction : public QObject {
    Q_OBJECT
public:
    ToggleDisplayReaction(QAction* controlPolygons, QAction* vertices,
                          views::SurfaceView* surfaceView);
};

} // namespace devsurf::app
