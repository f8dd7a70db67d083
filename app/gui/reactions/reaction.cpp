#include "reaction.h"

#include "../workspace.h"
#include "model/document/document.h"
#include "model/document/selection.h"

#include <QAction>

namespace devsurf::app {

Reaction::Reaction(QAction* action, Workspace* workspace)
    : QObject(action), m_action(action), m_workspace(workspace) {
    connect(action, &QAction::triggered, this, [this] { onTriggered(); });
}

void Reaction::followDocumentAndSelection() {
    connect(m_workspace->document(), &document::Document::changed, this,
            [this] { updateEnableState(); });
    connect(m_workspace->selection(), &document::Selection::selectionChanged, this,
            [this] { updateEnableState(); });
    updateEnableState();
}

} // namespace devsurf::app
