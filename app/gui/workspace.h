#pragma once

#include "model/examples.h"

#include <QObject>
#include <QString>
#include <QStringList>

class QWidget;

namespace devsurf::document {
class CommandOrError;
class Document;
class Selection;
} // namespace devsurf::document

namespace devsurf::app {

class Autosaver;

// What the main window's handlers share: the open document, the selection, the window to
// parent dialogs on, and the file operations several actions need (open, save, prompting for
// unsaved changes, recent files).
class Workspace : public QObject {
    Q_OBJECT
public:
    explicit Workspace(QWidget* window);
    ~Workspace() override;

    document::Document* document() const { return m_document; }
    document::Selection* selection() const { return m_selection; }
    QWidget* window() const { return m_window; }

    // Asks whether to save unsaved changes. Returns false when the user cancels or saving
    // failed, i.e. when the caller must not discard the document.
    bool maybeSave();
    bool open(const QString& path); // shows an error dialog and returns false on failure
    bool save();                    // Save As when the document has no file yet
    bool saveAs();
    bool saveTo(const QString& path); // shows an error dialog and returns false on failure
    // A new design from a built-in example (size 0: its default); `sheet` says whether an
    // example that starts flat holds the sheet it starts as.
    void newFromExample(const QString& name, int size,
                        model::ExampleSheet sheet = model::ExampleSheet::AsBuilt);
    // A message box with the sentence; details (e.g. every problem of a refused file) are
    // listed below it.
    void showError(const QString& title, const QString& sentence,
                   const QStringList& details = {}) const;
    // Pushes an edit, or tells the user in a dialog why it was refused. Returns whether it was
    // applied.
    bool apply(document::CommandOrError edit, const QString& failureTitle);

    // Opens the work kept in a recovery file as unsaved changes to its original file.
    bool recover(const QString& recoveryFile);
    // Asks whether to recover work left by a session that ended without closing cleanly.
    void offerRecovery();
    Autosaver* autosaver() const { return m_autosaver; }

    QStringList recentFiles() const { return m_recentFiles; }
    void clearRecentFiles();
    static constexpr int kMaxRecentFiles = 8;

    QString fileDialogDirectory() const;

signals:
    void recentFilesChanged();
    void statusMessage(const QString& text);

private:
    // An opened or saved file: first in the recent files, its folder the next dialogs' start.
    void rememberFile(const QString& absolutePath);

    QWidget* m_window;
    document::Document* m_document;
    document::Selection* m_selection;
    QStringList m_recentFiles;
    Autosaver* m_autosaver;
};

} // namespace devsurf::app
