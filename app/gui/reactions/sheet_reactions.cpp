#include "sheet_reactions.h"
#include "edit_refusal.h"

#include "../workspace.h"
#include "model/development.h"
#include "model/document/commands/apply_surface_command.h"
#include "model/document/document.h"
#include "model/document/selection.h"

#include <QAction>

namespace devsurf::app {

HoldSheetReaction::HoldSheetReaction(QAction* action, Workspace* workspace)
    : Reaction(action, workspace) {
    action->setCheckable(true);
    followDocumentAndSelection();
}

std::optional<int> HoldSheetReaction::targetSurface() const {
    std::optional<int> surface;
    for (const document::Pick& pick : workspace()->selection()->picks()) {
        if (surface && *surface != pick.surface) {
            return std::nullopt; // several surfaces selected
        }
        surface = pick.surface;
    }
    if (!surface && workspace()->document()->surfaceCount() == 1) {
        surface = 0;
    }
    return surface;
}

void HoldSheetReaction::updateEnableState() {
    const std::optional<int> surface = targetSurface();
    const document::Document* doc = workspace()->document();
    const bool holds =
        surface && *surface < doc->surfaceCount() && doc->surface(*surface).keepsDevelopment();
    action()->setEnabled(surface.has_value());
    action()->setChecked(holds);
    const QString tip =
        !surface ? tr("Hold the sheet of a surface: select something on one surface first.")
        : holds  ? tr("The surface is folded from its sheet: solves and drags keep it "
                       "isometric to its development, and a dragged vertex stays behind where "
                       "the sheet cannot follow. Uncheck to let the sheet stretch again.")
                 : tr("Fold the surface from its sheet: its development as it unfolds now is "
                       "kept by every solve and drag; a dragged vertex stays behind where the "
                       "sheet cannot follow, instead of the sheet stretching.");
    action()->setToolTip(tip);
    action()->setStatusTip(tip);
}

void HoldSheetReaction::onTriggered() {
    const std::optional<int> surface = targetSurface();
    document::Document* doc = workspace()->document();
    if (!surface || *surface >= doc->surfaceCount()) {
        updateEnableState();
        return;
    }
    model::CompositeSurface changed = doc->surface(*surface);
    const bool hold = !changed.keepsDevelopment();
    const QString title = hold ? tr("Hold the Sheet") : tr("Let the Sheet Stretch");
    if (hold) {
        if (const auto problem = model::keepDevelopment(changed)) {
            workspace()->apply(document::CommandOrError(tr("Cannot hold the sheet"), *problem),
                               tr("Cannot hold the sheet"));
            updateEnableState();
            return;
        }
    } else {
        changed.setKeepsDevelopment(false);
    }
    workspace()->apply(document::ApplySurfaceCommand::create(*doc, *surface, std::move(changed),
                                                             title, document::Change::Labels),
                       hold ? tr("Cannot hold the sheet") : tr("Cannot let the sheet stretch"));
    updateEnableState();
}

} // namespace devsurf::app
