#pragma once

#include "reaction.h"

namespace devsurf::app {

// Tools ▸ Pin Vertices / Unpin Vertices: the solver never moves a pinned vertex, in solves and
// drags alike. One undo step for all selected vertices of one surface.
class PinVerticesReaction : public Reaction {
    Q_OBJECT
public:
    PinVerticesReaction(QAction* action, Workspace* workspace, bool pin);

protected:
    void onTriggered() override;
    void updateEnableState() override;

private:
    bool m_pin;
};

} // namespace devsurf::app
