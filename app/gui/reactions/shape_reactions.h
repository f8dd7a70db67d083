#pragma once

#include "reaction.h"

namespace devsurf::app {

// File ▸ Export 3D Shape…: STEP, IGES or a mesh of the design (ShapeExportDialog).
class ExportShapeReaction : public Reaction {
    Q_OBJECT
public:
    ExportShapeReaction(QAction* action, Workspace* workspace);

protected:
    void onTriggered() override;
    void updateEnableState() override;
};

} // namespace devsurf::app
