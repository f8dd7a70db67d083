#pragma once

#include "reaction.h"

#include "model/ids.h"

#include <optional>
#include <set>

namespace devsurf::views {
class SceneView;
} // namespace devsurf::views

namespace devsurf::app {

class SolveController;

// The single surface all picks of one kind belong to, with their ids; nullopt when the
// selection has none of that kind or spans several surfaces.
struct SelectedIds {
    int surface = 0;
    std::set<std::uint32_t> ids;
};

// Tools ▸ Relabel Edge: turns every selected edge from R to S or from S to R in one step.
class RelabelEdgeReaction : public Reaction {
    Q_OBJECT
public:
    RelabelEdgeReaction(QAction* action, Workspace* workspace);

protected:
    void onTriggered() override;
    void updateEnableState() override;
};

// Tools ▸ Add Crease: a new crease across the selected strip (and its row), at a position
// across the strip in per cent, previewed in the given view while the dialog is open.
class SubdivideStripReaction : public Reaction {
    Q_OBJECT
public:
    SubdivideStripReaction(QAction* action, Workspace* workspace,
                           views::SceneView* preview = nullptr);

protected:
    void onTriggered() override;
    void updateEnableState() override;

private:
    views::SceneView* m_preview;
};

// Tools ▸ Add Ruling: a new ruling across the selected strip (and the strips sharing its
// curves), at a position along the strip in per cent, previewed like a crease.
class SplitAtRulingReaction : public Reaction {
    Q_OBJECT
public:
    SplitAtRulingReaction(QAction* action, Workspace* workspace,
                          views::SceneView* preview = nullptr);

protected:
    void onTriggered() override;
    void updateEnableState() override;

private:
    views::SceneView* m_preview;
};

// Tools ▸ Remove Ruling: the selected ruling between two strips removed, the strips merged into
// one (document::MergeStripsCommand); the status bar says how far the merged strip lies from
// the two it replaces, measured on dense samples of theirs.
class RemoveRulingReaction : public Reaction {
    Q_OBJECT
public:
    RemoveRulingReaction(QAction* action, Workspace* workspace);

protected:
    void onTriggered() override;
    void updateEnableState() override;
};

// Tools ▸ Refine Curves: doubles the intervals of the selected curve's spline class.
class RefineCurvesReaction : public Reaction {
    Q_OBJECT
public:
    RefineCurvesReaction(QAction* action, Workspace* workspace);

protected:
    void onTriggered() override;
    void updateEnableState() override;
};

// Tools ▸ Move or Rotate Vertices: exact translation or rotation of the selected vertices; with
// "Keep developable" (and a solver) the motion is followed by an Edit job (solver iterations
// with the moved vertices held), the two together one undo step.
class MoveVerticesReaction : public Reaction {
    Q_OBJECT
public:
    MoveVerticesReaction(QAction* action, Workspace* workspace, SolveController* solver = nullptr);

protected:
    void onTriggered() override;
    void updateEnableState() override;

private:
    SolveController* m_solver;
};

} // namespace devsurf::app
