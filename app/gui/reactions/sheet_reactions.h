#pragma once

#include "reaction.h"

#include "model/composite_surface.h"
#include "model/sheet_domain.h"

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

// Tools ▸ Sheet Shape…: the sheet the chosen surface is folded from — its development held as
// it is, or confined to a rectangle, disk or annulus (SheetShapeDialog). Holds the sheet if it
// is not held yet; one undo step.
class SheetShapeReaction : public Reaction {
    Q_OBJECT
public:
    SheetShapeReaction(QAction* action, Workspace* workspace);

    // Gives surface `index` the sheet `domain` (placed), holding its development; false and a
    // sentence in the status bar if it cannot hold one. Public for the tests.
    bool applyShape(int index, const model::SheetDomain& domain);
    // Why a surface held around a cylinder gets no flat sheet shape.
    static QString cylinderText(const model::CompositeSurface& surface);

protected:
    void onTriggered() override;
    void updateEnableState() override;
};

} // namespace devsurf::app
