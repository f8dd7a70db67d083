#pragma once

#include "reaction.h"

class QMenu;
class QPrinter;
class QWidget;

namespace devsurf::model {
struct CuttingPattern;
}

namespace devsurf::app {

// File ▸ Export Cutting Pattern…: the export dialog (format, options, fabrication report).
class ExportPatternReaction : public Reaction {
    Q_OBJECT
public:
    ExportPatternReaction(QAction* action, Workspace* workspace);

protected:
    void onTriggered() override;
    void updateEnableState() override;
};

// File ▸ Print…: the system print dialog, then the pattern at 1:1 on the chosen paper.
class PrintPatternReaction : public Reaction {
    Q_OBJECT
public:
    PrintPatternReaction(QAction* action, Workspace* workspace);

protected:
    void onTriggered() override;
    void updateEnableState() override;
};

// File ▸ Print Preview…: the same pages in QPrintPreviewDialog.
class PrintPreviewReaction : public Reaction {
    Q_OBJECT
public:
    PrintPreviewReaction(QAction* action, Workspace* workspace);

protected:
    void onTriggered() override;
    void updateEnableState() override;
};

// Adds the three actions (actionExportPattern, actionPrint with Ctrl+P, actionPrintPreview)
// and their reactions to the File menu.
void addCuttingPatternActions(QMenu* file, Workspace* workspace);

// Paints the pattern on the printer's paper (its page size, the orientation that needs fewer
// pages, the same pages as the PDF), with a progress dialog on `parent` for long jobs. Returns
// false if painting failed or was cancelled.
bool printCuttingPattern(QPrinter& printer, const model::CuttingPattern& pattern, QWidget* parent);

} // namespace devsurf::app
