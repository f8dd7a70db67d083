#include "shape_reactions.h"

#include "../shape_export_dialog.h"
#include "../workspace.h"
#include "model/document/document.h"

#include <QAction>
#include <QFileInfo>

namespace devsurf::app {

ExportShapeReaction::ExportShapeReaction(QAction* action, Workspace* workspace)
    : Reaction(action, workspace) {
    followDocumentAndSelection();
}

void ExportShapeReaction::updateEnableState() {
    action()->setEnabled(!workspace()->document()->project().surfaces.empty());
}

void ExportShapeReaction::onTriggered() {
    const QString file = workspace()->document()->filePath();
    const QString base = file.isEmpty() ? tr("untitled") : QFileInfo(file).completeBaseName();
    ShapeExportDialog dialog(workspace()->document()->project(), base,
                             workspace()->fileDialogDirectory(), workspace()->window());
    dialog.setProjectFile(file);
    if (dialog.exec() == QDialog::Accepted) {
        emit workspace()->statusMessage(tr("Exported the 3D shape (%1)").arg(dialog.summary()));
    }
}

} // namespace devsurf::app
