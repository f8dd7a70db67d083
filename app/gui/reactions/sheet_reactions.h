#pragma once

#include "reaction.h"

#include <optional>

namespace devsurf::app {

// Tools ▸ Hold the Sheet: the chosen surface keeps its development (§5). Every solve and drag
// then keeps it isometric to that sheet; a dragged vertex lags where the sheet cannot follow.
// Acts on the surface of the selection, or on the only surface; one undo step.
class HoldSheetReaction : public Reaction {
    Q_OBJECT
public:
    HoldSheetReaction(QAction* action, Workspace* workspace);

protected:
    void onTriggered() override;
    void updateEnableState() override;

private:
    std::optional<int> targetSurface() const;
};

} // namespace devsurf::app
