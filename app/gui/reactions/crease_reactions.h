#pragma once

#include "reaction.h"

#include "model/composite_surface.h"

class QMenu;
class QWidget;

namespace devsurf::app {

// Tools ▸ Crease ▸ Curved Fold / Geodesic / Straight When Unfolded / No Condition: the
// condition the solver imposes on the selected creases (edges of one surface). One undo step.
// Enabled while the selection holds a crease; checked when every selected edge is a crease
// with this condition. Where the edit does not apply (a ruling or boundary curve among the
// edges, the condition already set) the command's sentence goes to the status bar.
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

// Tools ▸ Crease ▸ Smooth / Sharp: marks the selected rulings between two patches smooth (the
// surface stays smooth across them) or sharp (it may fold there). One undo step. Enabled while
// the selection holds such a ruling; checked when every selected edge already has the flag.
// Refusals go to the status bar with the command's sentence.
class SmoothRulingsReaction : public Reaction {
    Q_OBJECT
public:
    SmoothRulingsReaction(QAction* action, Workspace* workspace, bool smooth);

protected:
    void onTriggered() override;
    void updateEnableState() override;

private:
    bool m_smooth;
};

// The Tools ▸ Crease submenu: the four crease conditions, then Smooth and Sharp, each with its
// reaction. Its actions are named actionCurvedFold, actionGeodesic, actionStraightWhenUnfolded,
// actionNoCondition, actionSmoothRulings and actionSharpRulings.
QMenu* createCreaseMenu(QWidget* parent, Workspace* workspace);

} // namespace devsurf::app
