#include "crease_reactions.h"

#include "../workspace.h"
#include "model/document/commands/command_or_error.h"
#include "model/document/commands/crease_condition_command.h"
#include "model/document/document.h"
#include "model/document/selection.h"

#include <QAction>

#include <optional>
#include <set>

namespace devsurf::app {

namespace {

// The condition edit of the selected edges; nullopt when no edge is selected, or edges of
// several surfaces are.
std::optional<document::CommandOrError> conditionOfSelection(Workspace* workspace,
                                                             model::CreaseCondition condition) {
    std::optional<int> surface;
    std::set<model::EdgeId> edges;
    for (const document::Pick& pick : workspace->selection()->picks()) {
        if (pick.kind != document::Pick::Kind::Edge) {
            continue;
        }
        if (surface && *surface != pick.surface) {
            return std::nullopt;
        }
        surface = pick.surface;
        edges.insert(pick.id);
    }
    if (!surface) {
        return std::nullopt;
    }
    return document::CreaseConditionCommand::create(*workspace->document(), *surface, edges,
                                                    condition);
}

QString purpose(model::CreaseCondition condition) {
    switch (condition) {
    case model::CreaseCondition::CurvedFold:
        return CreaseConditionReaction::tr(
            "Curved fold: the solver keeps the crease's osculating plane halfway between the two "
            "patches, so that the design folds from one flat sheet.");
    case model::CreaseCondition::Geodesic:
        return CreaseConditionReaction::tr(
            "Geodesic: the solver keeps the crease a geodesic of both patches.");
    case model::CreaseCondition::Straight:
    case model::CreaseCondition::None:
        break;
    }
    return CreaseConditionReaction::tr("No condition: the solver treats the crease freely.");
}

} // namespace

CreaseConditionReaction::CreaseConditionReaction(QAction* action, Workspace* workspace,
                                                 model::CreaseCondition condition)
    : Reaction(action, workspace), m_condition(condition) {
    followDocumentAndSelection();
}

void CreaseConditionReaction::updateEnableState() {
    const std::optional<document::CommandOrError> edit =
        conditionOfSelection(workspace(), m_condition);
    QString tip = purpose(m_condition);
    if (!edit) {
        tip += QLatin1Char(' ') + tr("Select creases (curves between two patches) of one "
                                     "surface first.");
    } else if (edit->isRefused()) {
        tip = edit->error();
    }
    action()->setEnabled(edit && !edit->isRefused());
    action()->setToolTip(tip);
    action()->setStatusTip(tip);
}

void CreaseConditionReaction::onTriggered() {
    std::optional<document::CommandOrError> edit = conditionOfSelection(workspace(), m_condition);
    if (edit) {
        workspace()->apply(std::move(*edit), tr("Cannot set the crease condition"));
    }
}

} // namespace devsurf::app
