#pragma once

#include "change_flags.h"
#include "model/project.h"

#include <QObject>
#include <QString>

#include <map>

class QUndoStack;

namespace devsurf::document {

// The open design. Owns the project and its undo stack; every change goes through a
// QUndoCommand pushed on undoStack(), and every change raises the revision and emits changed().
// Views and panels only read and listen.
class Document : public QObject {
    Q_OBJECT
public:
    explicit Document(QObject* parent = nullptr);
    ~Document() override;

    const model::Project& project() const { return m_project; }
    int surfaceCount() const { return static_cast<int>(m_project.surfaces.size()); }
    // index must be in [0, surfaceCount()).
    const model::CompositeSurface& surface(int index) const {
        return m_project.surfaces.at(static_cast<std::size_t>(index));
    }
    QUndoStack* undoStack() const { return m_undoStack; }
    // Increases with every change, undo and redo included; solver results carry the revision
    // they were computed from and are dropped when it no longer matches.
    quint64 revision() const { return m_revision; }
    // The revision at which the surface at index last changed (what the views' caches of
    // derived geometry are keyed by); index must be in [0, surfaceCount()).
    quint64 surfaceRevision(int index) const;
    // The surface the latest change was made to, or -1 if it may have touched every surface
    // (a new project, a change not about one surface). Valid while changed() is emitted.
    int changedSurface() const { return m_changedSurface; }

    QString filePath() const { return m_filePath; }
    void setFilePath(const QString& path);
    bool isModified() const;
    void markSaved(); // sets the undo stack's clean index

    // New or opened project: replaces everything and clears the undo history.
    void resetProject(model::Project project, const QString& filePath = QString());

    // A drag's live result, shown outside the undo history: the surface at index becomes
    // `surface` (valid: a solve job's outcome; its id kept) and changed() is emitted, but no undo
    // step is made and the modified flag stays. The drag pushes one command on release
    // (ApplySurfaceCommand:: createShown) or restores its press state the same way.
    void previewSurface(int index, const model::CompositeSurface& surface);

    // For commands only: the project to change, then notifyChanged() once the change is done.
    model::Project& mutableProject() { return m_project; }
    // surfaceIndex: the only surface changed, or -1 for any number of them.
    void notifyChanged(Changes changes, int surfaceIndex = -1);

signals:
    void changed(devsurf::document::Changes changes);
    void projectReset();
    void modifiedChanged(bool modified);
    void filePathChanged(const QString& path);

private:
    model::Project m_project;
    QUndoStack* m_undoStack = nullptr;
    quint64 m_revision = 0;
    // Revision of the last change to all surfaces, and of later changes to single surfaces.
    quint64 m_allSurfacesRevision = 0;
    std::map<model::SurfaceId, quint64> m_surfaceRevisions;
    int m_changedSurface = -1;
    QString m_filePath;
};

} // namespace devsurf::document
