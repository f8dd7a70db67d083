#pragma once

#include <QList>
#include <QObject>

class QAction;
class QMenu;

namespace devsurf::views {
class SurfaceView;
class DevelopmentView;
} // namespace devsurf::views

namespace devsurf::app {

// View ▸ Standard Views with FreeCAD's keys (0 isometric, 1 front, 2 top, 3 right, 4 rear,
// 5 bottom, 6 left), View ▸ Reset View (Home) and View ▸ Patch Numbers (Ctrl+Shift+N), added to
// a menu and acting on both views.
class CameraActions : public QObject {
    Q_OBJECT
public:
    CameraActions(QMenu* viewMenu, views::SurfaceView* surfaceView,
                  views::DevelopmentView* developmentView, QObject* parent);

    // Reset View, Isometric, Front, Top, Right: the ones worth a toolbar button.
    QList<QAction*> toolbarActions() const { return m_toolbar; }
    QAction* patchLabelsAction() const { return m_labels; }

private:
    QList<QAction*> m_toolbar;
    QAction* m_labels = nullptr;
};

// An icon of our own set (resources/icons/actions/NAME.svg).
QIcon actionIcon(const QString& name);

} // namespace devsurf::app
