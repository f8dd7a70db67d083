#include "view_reactions.h"

#include "views/development_view.h"
#include "views/surface_view.h"

#include <QAction>
#include <QActionGroup>
#include <QSettings>

namespace devsurf::app {

ViewLayoutReaction::ViewLayoutReaction(QAction* only3d, QAction* onlyDevelopment, QAction* both,
                                       views::SurfaceView* surfaceView,
                                       views::DevelopmentView* developmentView)
    : QObject(both), m_only3d(only3d), m_onlyDevelopment(onlyDevelopment),
      m_surfaceView(surfaceView), m_developmentView(developmentView) {
    auto* group = new QActionGroup(this);
    for (QAction* action : {only3d, onlyDevelopment, both}) {
        action->setCheckable(true);
        group->addAction(action);
    }
    both->setChecked(true);
    connect(group, &QActionGroup::triggered, this, &ViewLayoutReaction::apply);
}

void ViewLayoutReaction::apply(QAction* chosen) {
    m_surfaceView->setVisible(chosen != m_onlyDevelopment);
    m_developmentView->setVisible(chosen != m_only3d);
}

ToggleDisplayReaction::ToggleDisplayReaction(QAction* controlPolygons, QAction* vertices,
                                             views::SurfaceView* surfaceView)
    : QObject(controlPolygons) {
    QSettings settings;
    controlPolygons->setCheckable(true);
    vertices->setCheckable(true);
    controlPolygons->setChecked(
        settings.value(QStringLiteral("view/controlPolygons"), true).toBool());
    vertices->setChecked(settings.value(QStringLiteral("view/vertices"), true).toBool());
    surfaceView->setShowControlPolygons(controlPolygons->isChecked());
    surfaceView->setShowVertices(vertices->isChecked());
    connect(controlPolygons, &QAction::toggled, surfaceView, [surfaceView](bool on) {
        surfaceView->setShowControlPolygons(on);
        QSettings().setValue(QStringLiteral("view/controlPolygons"), on);
    });
    connect(vertices, &QAction::toggled, surfaceView, [surfaceView](bool on) {
        surfaceView->setShowVertices(on);
        QSettings().setValue(QStringLiteral("view/vertices"), on);
    });
}

} // namespace devsurf::app
