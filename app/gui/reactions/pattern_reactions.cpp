#include "pattern_reactions.h"
#include "problem_text.h"

#include "../bounded_pattern.h"
#include "../pattern_export_dialog.h"
#include "../workspace.h"
#include "io/pattern/page_plan.h"
#include "io/pattern/pattern_painter.h"
#include "model/document/document.h"
#include "model/pattern/cutting_pattern.h"

#include <QAction>
#include <QFileInfo>
#include <QMenu>
#include <QPrintDialog>
#include <QPrintPreviewDialog>
#include <QPrinter>
#include <QProgressDialog>

#include <optional>

namespace devsurf::app {

namespace {

bool hasSurfaces(const Workspace* workspace) {
    return !workspace->document()->project().surfaces.empty();
}

// The pattern printed: the options of the last export; nullopt (after telling the user) when
// nothing can be developed.
std::optional<model::CuttingPattern> patternToPrint(Workspace* workspace) {
    BoundedPattern built =
        buildBoundedPattern(workspace->document()->project(), PatternSettings::load().pattern);
    if (built.refused) {
        workspace->showError(QObject::tr("Nothing to print"), built.note);
        return std::nullopt;
    }
    if (!built.note.isEmpty()) {
        emit workspace->statusMessage(built.note); // printed at a coarser tolerance
    }
    model::CuttingPattern pattern = std::move(built.pattern);
    if (pattern.pieces.empty()) {
        workspace->showError(QObject::tr("Nothing to print"),
                             pattern.problems.empty()
                                 ? QObject::tr("The design has no surface to develop.")
                                 : ProblemText::of(pattern.problems.front(), pattern));
        return std::nullopt;
    }
    return pattern;
}

} // namespace

bool printCuttingPattern(QPrinter& printer, const model::CuttingPattern& pattern, QWidget* parent) {
    const QPageSize pageSize = printer.pageLayout().pageSize();
    const QSizeF paper = pageSize.size(QPageSize::Millimeter);
    const io::PagePlan plan = io::planPages(pattern, {std::min(paper.width(), paper.height()),
                                                      std::max(paper.width(), paper.height())});
    printer.setFullPage(true);
    io::preparePagedDevice(printer, pageSize, plan);
    QProgressDialog progress(QObject::tr("Printing the cutting pattern…"), QObject::tr("Cancel"), 0,
                             io::patternPageCount(pattern, plan), parent);
    progress.setWindowModality(Qt::WindowModal);
    progress.setMinimumDuration(400);
    return io::paintPatternPages(printer, pattern, plan, patternProblemTexts(pattern),
                                 [&progress](int done, int) {
                                     progress.setValue(done);
                                     return !progress.wasCanceled();
                                 });
}

ExportPatternReaction::ExportPatternReaction(QAction* action, Workspace* workspace)
    : Reaction(action, workspace) {
    followDocumentAndSelection();
}

void ExportPatternReaction::updateEnableState() {
    action()->setEnabled(hasSurfaces(workspace()));
}

void ExportPatternReaction::onTriggered() {
    const QString file = workspace()->document()->filePath();
    const QString base = file.isEmpty() ? tr("untitled") : QFileInfo(file).completeBaseName();
    PatternExportDialog dialog(workspace()->document()->project(), base,
                               workspace()->fileDialogDirectory(), workspace()->window());
    dialog.setProjectFile(file);
    if (dialog.exec() == QDialog::Accepted) {
        emit workspace()->statusMessage(tr("Exported the cutting pattern"));
    }
}

PrintPatternReaction::PrintPatternReaction(QAction* action, Workspace* workspace)
    : Reaction(action, workspace) {
    followDocumentAndSelection();
}

void PrintPatternReaction::updateEnableState() {
    action()->setEnabled(hasSurfaces(workspace()));
}

void PrintPatternReaction::onTriggered() {
    const std::optional<model::CuttingPattern> pattern = patternToPrint(workspace());
    if (!pattern) {
        return;
    }
    QPrinter printer(QPrinter::HighResolution);
    QPrintDialog dialog(&printer, workspace()->window());
    dialog.setWindowTitle(tr("Print Cutting Pattern"));
    if (dialog.exec() != QDialog::Accepted) {
        return;
    }
    if (!printCuttingPattern(printer, *pattern, workspace()->window())) {
        workspace()->showError(tr("Printing failed"),
                               tr("The pages could not be sent to the printer."));
    }
}

PrintPreviewReaction::PrintPreviewReaction(QAction* action, Workspace* workspace)
    : Reaction(action, workspace) {
    followDocumentAndSelection();
}

void PrintPreviewReaction::updateEnableState() {
    action()->setEnabled(hasSurfaces(workspace()));
}

void PrintPreviewReaction::onTriggered() {
    const std::optional<model::CuttingPattern> pattern = patternToPrint(workspace());
    if (!pattern) {
        return;
    }
    QPrinter printer(QPrinter::HighResolution);
    QPrintPreviewDialog preview(&printer, workspace()->window());
    preview.setWindowTitle(tr("Print Preview: Cutting Pattern"));
    connect(&preview, &QPrintPreviewDialog::paintRequested, this,
            [&pattern, &preview](QPrinter* target) {
                printCuttingPattern(*target, *pattern, &preview);
            });
    preview.exec();
}

void addCuttingPatternActions(QMenu* file, Workspace* workspace) {
    auto make = [file](const char* name, const QString& text, const QKeySequence& key) {
        auto* action = new QAction(text, file);
        action->setObjectName(QString::fromLatin1(name));
        action->setShortcut(key);
        file->addAction(action);
        return action;
    };
    new ExportPatternReaction(
        make("actionExportPattern", QObject::tr("Export &Cutting Pattern…"), QKeySequence()),
        workspace);
    new PrintPatternReaction(make("actionPrint", QObject::tr("&Print…"), QKeySequence::Print),
                             workspace);
    new PrintPreviewReaction(
        make("actionPrintPreview", QObject::tr("Print Pre&view…"), QKeySequence()), workspace);
}

} // namespace devsurf::app
