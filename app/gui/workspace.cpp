#include "workspace.h"
#include "edit_refusal.h"
#include "problem_text.h"

#include "autosaver.h"
#include "io/file_error.h"
#include "io/project_file.h"
#include "model/document/commands/command_or_error.h"
#include "model/document/document.h"
#include "model/document/selection.h"
#include "model/examples.h"
#include "model/model_error.h"
#include "output_problem_text.h"

#include <QDateTime>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QMessageBox>
#include <QSettings>
#include <QUndoStack>

#include <algorithm>
#include <new>

namespace devsurf::app {

namespace {
const char* const kRecentKey = "recentFiles";
const char* const kLastDirectoryKey = "lastDirectory";
} // namespace

Workspace::Workspace(QWidget* window)
    : QObject(window), m_window(window), m_document(new document::Document(this)),
      m_selection(new document::Selection(this)),
      m_autosaver(new Autosaver(m_document, Autosaver::defaultDirectory(), 60 * 1000, this)) {
    m_recentFiles = QSettings().value(kRecentKey).toStringList();
    connect(m_document, &document::Document::projectReset, m_selection,
            &document::Selection::clear);
    // After undo or a topological edit, picks of entities that no longer exist are dropped.
    connect(m_document, &document::Document::changed, m_selection, [this] {
        const auto& surfaces = m_document->project().surfaces;
        m_selection->prune([&surfaces](const document::Pick& pick) {
            if (pick.surface < 0 || pick.surface >= static_cast<int>(surfaces.size())) {
                return false;
            }
            const auto& surface = surfaces[static_cast<std::size_t>(pick.surface)];
            switch (pick.kind) {
            case document::Pick::Kind::Vertex:
                return surface.hasVertex(pick.id);
            case document::Pick::Kind::Edge:
                return surface.hasEdge(pick.id);
            case document::Pick::Kind::Face:
                return surface.hasFace(pick.id);
            }
            return false;
        });
    });
}

bool Workspace::apply(document::CommandOrError edit, const QString& failureTitle) {
    const QString refusal = pushOrExplain(*m_document, std::move(edit));
    if (!refusal.isEmpty()) {
        showError(failureTitle, refusal);
        return false;
    }
    return true;
}

Workspace::~Workspace() = default;

void Workspace::showError(const QString& title, const QString& sentence,
                          const QStringList& details) const {
    if (details.isEmpty()) {
        QMessageBox::warning(m_window, title, sentence);
        return;
    }
    // The first problems in the message itself, every one of them under "Show Details".
    constexpr int kShown = 8;
    QString text = sentence + QStringLiteral("\n");
    for (int i = 0; i < std::min<int>(kShown, static_cast<int>(details.size())); ++i) {
        text += QStringLiteral("\n• ") + details[i];
    }
    if (details.size() > kShown) {
        text += QStringLiteral("\n") +
                tr("… and %n more problem(s).", nullptr, static_cast<int>(details.size()) - kShown);
    }
    QMessageBox box(QMessageBox::Warning, title, text, QMessageBox::Ok, m_window);
    box.setObjectName(QStringLiteral("errorBox"));
    box.setDetailedText(details.join(QLatin1Char('\n')));
    box.exec();
}

QString Workspace::fileDialogDirectory() const {
    if (!m_document->filePath().isEmpty()) {
        return QFileInfo(m_document->filePath()).absolutePath();
    }
    return QSettings().value(kLastDirectoryKey, QDir::homePath()).toString();
}

bool Workspace::maybeSave() {
    if (!m_document->isModified()) {
        return true;
    }
    const QString name = m_document->filePath().isEmpty()
                             ? tr("Untitled")
                             : QFileInfo(m_document->filePath()).fileName();
    const auto answer = QMessageBox::warning(
        m_window, tr("Unsaved changes"),
        tr("%1 has unsaved changes. Do you want to save them?").arg(name),
        QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel, QMessageBox::Save);
    if (answer == QMessageBox::Save) {
        return save();
    }
    return answer == QMessageBox::Discard;
}

bool Workspace::open(const QString& path) {
    try {
        model::Project project = io::loadProjectFile(path);
        const QString absolute = QFileInfo(path).absoluteFilePath();
        m_document->resetProject(std::move(project), absolute);
        rememberFile(absolute);
        emit statusMessage(tr("Opened %1").arg(QFileInfo(absolute).fileName()));
        return true;
    } catch (const io::FileError& error) {
        QStringList details;
        for (const model::Problem& problem : error.problems()) {
            details << ProblemText::of(problem);
        }
        showError(tr("Cannot open file"), QString::fromStdString(error.what()), details);
        return false;
    } catch (const std::bad_alloc&) {
        showError(tr("Cannot open file"), notEnoughMemoryText(path));
        return false;
    }
}

bool Workspace::save() {
    if (m_document->filePath().isEmpty()) {
        return saveAs();
    }
    return saveTo(m_document->filePath());
}

bool Workspace::saveAs() {
    QString path = QFileDialog::getSaveFileName(
        m_window, tr("Save Project As"),
        QDir(fileDialogDirectory())
            .filePath(m_document->filePath().isEmpty()
                          ? tr("untitled.devsurf")
                          : QFileInfo(m_document->filePath()).fileName()),
        tr("DevSurf projects (*.devsurf)"));
    if (path.isEmpty()) {
        return false;
    }
    if (QFileInfo(path).suffix().isEmpty()) {
        path += QStringLiteral(".devsurf");
    }
    return saveTo(path);
}

bool Workspace::saveTo(const QString& path) {
    try {
        io::saveProjectFile(m_document->project(), path);
    } catch (const io::FileError& error) {
        showError(tr("Cannot save file"), QString::fromStdString(error.what()));
        return false;
    }
    const QString absolute = QFileInfo(path).absoluteFilePath();
    m_document->setFilePath(absolute);
    m_document->markSaved();
    rememberFile(absolute);
    emit statusMessage(tr("Saved %1").arg(QFileInfo(absolute).fileName()));
    return true;
}

void Workspace::newFromExample(const QString& name, int size, model::ExampleSheet sheet) {
    try {
        m_document->resetProject(model::makeExample(name.toStdString(), size, sheet));
        const bool holds = sheet == model::ExampleSheet::Held && m_document->surfaceCount() == 1 &&
                           m_document->surface(0).keepsDevelopment();
        emit statusMessage(holds ? tr("New design from the example “%1”, holding the sheet it "
                                      "starts as")
                                       .arg(name)
                                 : tr("New design from the example “%1”").arg(name));
    } catch (const model::ModelError& error) {
        showError(tr("Cannot create the example"), ProblemText::of(error.problem()));
    }
}

bool Workspace::recover(const QString& recoveryFile) {
    try {
        model::Project project = io::loadProjectFile(recoveryFile);
        m_document->resetProject(std::move(project), Autosaver::originalPath(recoveryFile));
        m_document->undoStack()->resetClean(); // recovered work is unsaved work
        Autosaver::removeRecoveryFile(recoveryFile);
        m_autosaver->saveNow();
        emit statusMessage(tr("Recovered unsaved work"));
        return true;
    } catch (const io::FileError& error) {
        showError(tr("Cannot recover"), QString::fromStdString(error.what()));
        return false;
    } catch (const std::bad_alloc&) {
        showError(tr("Cannot recover"), notEnoughMemoryText(recoveryFile));
        return false;
    }
}

void Workspace::offerRecovery() {
    const QStringList stale = Autosaver::staleRecoveryFiles(Autosaver::defaultDirectory());
    if (stale.isEmpty()) {
        return;
    }
    const QString newest = stale.front();
    const QString original = Autosaver::originalPath(newest);
    const QString name =
        original.isEmpty() ? tr("an untitled design") : QFileInfo(original).fileName();
    const auto answer = QMessageBox::question(
        m_window, tr("Recover unsaved work"),
        tr("DevSurf did not close properly last time. Recover the unsaved changes to %1 from "
           "%2?")
            .arg(name, QFileInfo(newest).lastModified().toString(Qt::TextDate)),
        QMessageBox::Yes | QMessageBox::Discard, QMessageBox::Yes);
    if (answer == QMessageBox::Yes) {
        recover(newest);
    }
    // Older leftovers would only ask again at every start.
    for (const QString& file : stale) {
        if (file != newest || answer != QMessageBox::Yes) {
            Autosaver::removeRecoveryFile(file);
        }
    }
}

void Workspace::rememberFile(const QString& absolutePath) {
    QSettings().setValue(kLastDirectoryKey, QFileInfo(absolutePath).absolutePath());
    m_recentFiles.removeAll(absolutePath);
    m_recentFiles.prepend(absolutePath);
    while (m_recentFiles.size() > kMaxRecentFiles) {
        m_recentFiles.removeLast();
    }
    QSettings().setValue(kRecentKey, m_recentFiles);
    emit recentFilesChanged();
}

void Workspace::clearRecentFiles() {
    m_recentFiles.clear();
    QSettings().setValue(kRecentKey, m_recentFiles);
    emit recentFilesChanged();
}

} // namespace devsurf::app
