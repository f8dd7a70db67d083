#pragma once

#include "reaction.h"

#include "model/composite_surface.h"

namespace devsurf::app {

// Tools ▸ Crease ▸ Curved Fold / Geodesic / No Condition: the condition the solver imposes on
// the selected creases (edges of one surface). One undo step; disabled with the reason when
// the selection holds no crease, or an edge that is a ruling or a boundary curve.
class CreaseConditionReaction : public Reaction {
    Q_OBJECT
public:
    CreaseConditionReaction(QAction* action, Workspace* workspace,
                            model::CreaseCondition condition);

protected:
    void onTriggered() override;
    void updateEnableState() override;

private:
    model::CreaseCondition m_condition;
};

} // namespace devsurf::app
