#include "camera_actions.h"

#include "views/development_view.h"
#include "views/surface_view.h"

#include <QAction>
#include <QIcon>
#include <QMenu>
#include <QSettings>

namespace devsurf::app {

using views::SceneView;

QIcon actionIcon(const QString& name) {
    return QIcon(QStringLiteral(":/actions/%1.svg").arg(name));
}

CameraActions::CameraActions(QMenu* viewMenu, views::SurfaceView* surfaceView,
                             views::DevelopmentView* developmentView, QObject* parent)
    : QObject(parent) {
    QAction* reset =
        viewMenu->addAction(actionIcon(QStringLiteral("reset-view")), tr("&Reset View"));
    reset->setObjectName(QStringLiteral("actionResetView"));
    reset->setShortcut(QKeySequence(Qt::Key_Home));
    reset->setToolTip(tr("Reset View (Home): the starting direction, the whole design in view"));
    connect(reset, &QAction::triggered, surfaceView, &SceneView::resetView);
    connect(reset, &QAction::triggered, developmentView, &SceneView::resetView);
    m_toolbar << reset;

    QMenu* standard = viewMenu->addMenu(tr("&Standard Views"));
    standard->setObjectName(QStringLiteral("menuStandardViews"));
    struct Entry {
        const char* name;
        const char* icon; // empty: menu only
        QString text;
        QString tip;
        Qt::Key key;
        SceneView::StandardView view;
    };
    const Entry entries[] = {
        {"actionViewIsometric", "view-isometric", tr("&Isometric"),
         tr("Isometric view (0): from the front right and above"), Qt::Key_0,
         SceneView::StandardView::Isometric},
        {"actionViewFront", "view-front", tr("&Front"), tr("Front view (1): looking along +y"),
         Qt::Key_1, SceneView::StandardView::Front},
        {"actionViewTop", "view-top", tr("&Top"), tr("Top view (2): looking down along −z"),
         Qt::Key_2, SceneView::StandardView::Top},
        {"actionViewRight", "view-right", tr("&Right"), tr("Right view (3): looking along −x"),
         Qt::Key_3, SceneView::StandardView::Right},
        {"actionViewRear", "", tr("R&ear"), tr("Rear view (4): looking along −y"), Qt::Key_4,
         SceneView::StandardView::Rear},
        {"actionViewBottom", "", tr("&Bottom"), tr("Bottom view (5): looking up along +z"),
         Qt::Key_5, SceneView::StandardView::Bottom},
        {"actionViewLeft", "", tr("&Left"), tr("Left view (6): looking along +x"), Qt::Key_6,
         SceneView::StandardView::Left},
    };
    for (const Entry& entry : entries) {
        QAction* action = standard->addAction(entry.text);
        action->setObjectName(QString::fromLatin1(entry.name));
        action->setShortcut(QKeySequence(entry.key));
        action->setToolTip(entry.tip);
        action->setStatusTip(entry.tip);
        const SceneView::StandardView view = entry.view;
        connect(action, &QAction::triggered, surfaceView,
                [surfaceView, view] { surfaceView->setStandardView(view); });
        if (entry.icon[0] != '\0') {
            action->setIcon(actionIcon(QString::fromLatin1(entry.icon)));
            m_toolbar << action;
        }
    }
    // The keys are plain digits: they act when a view or panel has focus, while a number field
    // being edited keeps its digits.
    for (QAction* action : standard->actions()) {
        action->setShortcutContext(Qt::WindowShortcut);
    }

    m_labels =
        viewMenu->addAction(actionIcon(QStringLiteral("patch-labels")), tr("Patch &Numbers"));
    m_labels->setObjectName(QStringLiteral("actionPatchLabels"));
    m_labels->setShortcut(QKeySequence(tr("Ctrl+Shift+N")));
    m_labels->setToolTip(tr("Patch Numbers (Ctrl+Shift+N): write each patch's number on it"));
    m_labels->setCheckable(true);
    m_labels->setChecked(QSettings().value(QStringLiteral("view/patchLabels"), false).toBool());
    surfaceView->setShowPatchLabels(m_labels->isChecked());
    developmentView->setShowPatchLabels(m_labels->isChecked());
    connect(m_labels, &QAction::toggled, this, [surfaceView, developmentView](bool on) {
        surfaceView->setShowPatchLabels(on);
        developmentView->setShowPatchLabels(on);
        QSettings().setValue(QStringLiteral("view/patchLabels"), on);
    });
}

} // namespace devsurf::app
