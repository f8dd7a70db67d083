#include "file_reactions.h"
#include "problem_text.h"

#include "../example_dialog.h"
#include "../output_problem_text.h"
#include "../workspace.h"
#include "io/file_error.h"
#include "io/interchange_json.h"
#include "model/document/document.h"
#include "model/model_error.h"

#include <QAction>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QMenu>
#include <QMessageBox>
#include <QPushButton>

namespace devsurf::app {

void NewFromExampleReaction::onTriggered() {
    ExampleDialog dialog(workspace()->window());
    if (dialog.exec() != QDialog::Accepted || !workspace()->maybeSave()) {
        return;
    }
    workspace()->newFromExample(dialog.exampleName(), dialog.exampleSize(), dialog.exampleSheet());
}

void OpenReaction::onTriggered() {
    if (!workspace()->maybeSave()) {
        return;
    }
    const QString path = QFileDialog::getOpenFileName(workspace()->window(), tr("Open Project"),
                                                      workspace()->fileDialogDirectory(),
                                                      tr("DevSurf projects (*.devsurf)"));
    if (!path.isEmpty()) {
        workspace()->open(path);
    }
}

OpenRecentReaction::OpenRecentReaction(QMenu* menu, Workspace* workspace)
    : QObject(menu), m_menu(menu), m_workspace(workspace) {
    connect(workspace, &Workspace::recentFilesChanged, this, &OpenRecentReaction::rebuild);
    rebuild();
}

void OpenRecentReaction::rebuild() {
    m_menu->clear();
    const QStringList files = m_workspace->recentFiles();
    int number = 1;
    for (const QString& path : files) {
        QAction* action = m_menu->addAction(
            QStringLiteral("&%1 %2").arg(number++).arg(QFileInfo(path).fileName()));
        action->setToolTip(path);
        action->setStatusTip(path);
        connect(action, &QAction::triggered, this, [this, path] {
            if (m_workspace->maybeSave()) {
                m_workspace->open(path);
            }
        });
    }
    if (files.isEmpty()) {
        QAction* none = m_menu->addAction(tr("No recent files"));
        none->setEnabled(false);
    } else {
        m_menu->addSeparator();
        connect(m_menu->addAction(tr("Clear Recent Files")), &QAction::triggered, m_workspace,
                &Workspace::clearRecentFiles);
    }
}

void SaveReaction::onTriggered() {
    workspace()->save();
}

void SaveAsReaction::onTriggered() {
    workspace()->saveAs();
}

QString ExportJsonReaction::jsonPathFor(const QString& chosen, QWidget* window) {
    if (chosen.isEmpty()) {
        return {};
    }
    const QFileInfo info(chosen);
    const QString suffix = info.suffix();
    if (suffix.compare(QStringLiteral("json"), Qt::CaseInsensitive) == 0) {
        return chosen;
    }
    if (suffix.isEmpty()) {
        return chosen + QStringLiteral(".json");
    }
    // Another format's extension: JSON written into "pattern.svg" would fool every program
    // that opens it, so the name is changed only with the user's consent.
    const QString renamed = info.dir().filePath(info.completeBaseName() + QStringLiteral(".json"));
    QMessageBox box(QMessageBox::Question, tr("Export Interchange JSON"),
                    tr("“%1” ends in .%2, but this command writes interchange JSON. Export to "
                       "“%3” instead?")
                        .arg(info.fileName(), suffix, QFileInfo(renamed).fileName()),
                    QMessageBox::Cancel, window);
    box.setObjectName(QStringLiteral("jsonExtensionBox"));
    QPushButton* rename = box.addButton(tr("Export as .json"), QMessageBox::AcceptRole);
    box.setDefaultButton(rename);
    box.exec();
    return box.clickedButton() == rename ? renamed : QString();
}

void ExportJsonReaction::onTriggered() {
    const document::Document* doc = workspace()->document();
    const QString base =
        doc->filePath().isEmpty() ? tr("untitled") : QFileInfo(doc->filePath()).completeBaseName();
    QString path = QFileDialog::getSaveFileName(
        workspace()->window(), tr("Export Interchange JSON"),
        QDir(workspace()->fileDialogDirectory()).filePath(base + QStringLiteral(".json")),
        tr("Interchange JSON (*.json)"));
    path = jsonPathFor(path, workspace()->window());
    if (path.isEmpty()) {
        return;
    }
    const io::OutputProblem problem = io::outputProblem(
        path, doc->filePath().isEmpty() ? QStringList{} : QStringList{doc->filePath()});
    if (problem != io::OutputProblem::None) {
        workspace()->showError(tr("Export failed"), outputProblemText(problem, path));
        return;
    }
    try {
        io::saveInterchangeJsonFile(doc->project(), path);
        emit workspace()->statusMessage(tr("Exported %1").arg(QFileInfo(path).fileName()));
    } catch (const io::FileError& error) {
        workspace()->showError(tr("Export failed"), QString::fromStdString(error.what()));
    } catch (const model::ModelError& error) {
        workspace()->showError(
            tr("Export failed"),
            tr("The design cannot be exported: %1").arg(ProblemText::of(error.problem())));
    }
}

} // namespace devsurf::app
