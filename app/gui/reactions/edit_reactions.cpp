#include "edit_reactions.h"

#include <QAction>

namespace devsurf::app {

DeleteSelectionReaction::DeleteSelectionReaction(QAction* action, Workspace* workspace)
    : Reaction(action, workspace) {
    action->setEnabled(false);
    const QString why = tr("Deleting parts of a surface is not available yet: relabel an edge "
                           "(Ctrl+L) or undo (Ctrl+Z) instead.");
    action->setToolTip(why);
    action->setStatusTip(why);
}

} // namespace devsurf::app
