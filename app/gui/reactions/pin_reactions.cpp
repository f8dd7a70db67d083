#include "pin_reactions.h"
#include "edit_refusal.h"

#include "../workspace.h"
#include "model/document/commands/command_or_error.h"
#include "model/document/commands/pin_vertices_command.h"
#include "model/document/document.h"
#include "model/document/selection.h"

#include <QAction>

#include <optional>
#include <set>

namespace devsurf::app {

namespace {

// The pin edit of the selected vertices; nullopt when no vertex is selected, or vertices of
// several surfaces are.
std::optional<document::CommandOrError> pinSelection(Workspace* workspace, bool pin) {
    std::optional<int> surface;
    std::set<model::VertexId> vertices;
    for (const document::Pick& pick : workspace->selection()->picks()) {
        if (pick.kind != document::Pick::Kind::Vertex) {
            continue;
        }
        if (surface && *surface != pick.surface) {
            return std::nullopt;
        }
        surface = pick.surface;
        vertices.insert(pick.id);
    }
    if (!surface) {
        return std::nullopt;
    }
    return document::PinVerticesCommand::create(*workspace->document(), *surface, vertices, pin);
}

} // namespace

PinVerticesReaction::PinVerticesReaction(QAction* action, Workspace* workspace, bool pin)
    : Reaction(action, workspace), m_pin(pin) {
    followDocumentAndSelection();
}

void PinVerticesReaction::updateEnableState() {
    const std::optional<document::CommandOrError> edit = pinSelection(workspace(), m_pin);
    QString tip;
    if (!edit) {
        tip = m_pin ? tr("Pin the selected vertices: the solver never moves them. Select "
                         "vertices of one surface first.")
                    : tr("Release the selected pinned vertices. Select vertices of one surface "
                         "first.");
    } else if (edit->isRefused()) {
        tip = refusalText(*edit);
    } else {
        tip = m_pin ? tr("Pin the selected vertices: the solver never moves them.")
                    : tr("Release the selected pinned vertices.");
    }
    action()->setEnabled(edit && !edit->isRefused());
    action()->setToolTip(tip);
    action()->setStatusTip(tip);
}

void PinVerticesReaction::onTriggered() {
    std::optional<document::CommandOrError> edit = pinSelection(workspace(), m_pin);
    if (edit) {
        workspace()->apply(std::move(*edit),
                           m_pin ? tr("Cannot pin the vertices") : tr("Cannot unpin the vertices"));
    }
}

} // namespace devsurf::app
