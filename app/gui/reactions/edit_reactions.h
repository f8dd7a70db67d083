#pragma once

#include "reaction.h"

namespace devsurf::app {

// Edit ▸ Delete. No edit of the composite surface removes entities yet (merging strips across a
// ruling is still to come), so the action stays disabled and says why.
class DeleteSelectionReaction : public Reaction {
    Q_OBJECT
public:
    DeleteSelectionReaction(QAction* action, Workspace* workspace);

protected:
    void onTriggered() override {}
};

} // namespace devsurf::app
