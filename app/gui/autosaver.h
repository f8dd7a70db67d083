#pragma once

#include <QObject>
#include <QString>
#include <QStringList>

#include <memory>

class QLockFile;
class QTimer;

namespace devsurf::document {
class Document;
}

namespace devsurf::app {

// Keeps a recovery copy of unsaved work so that a crash loses at most one interval of edits.
// Each running DevSurf writes its own recovery file, guarded by a lock file; a recovery file
// whose lock is stale belongs to a session that ended without closing cleanly.
class Autosaver : public QObject {
    Q_OBJECT
public:
    Autosaver(document::Document* document, const QString& directory, int intervalMs,
              QObject* parent = nullptr);
    ~Autosaver() override;

    // Writes the recovery file now if the document changed since the last one; removes it when
    // there is nothing unsaved.
    void saveNow();
    QString recoveryFile() const { return m_file; }
    // The session ends cleanly: nothing to recover.
    void discard();

    // Recovery files left by sessions that did not end cleanly, newest first. Removes the locks
    // of ended sessions that left no recovery file.
    static QStringList staleRecoveryFiles(const QString& directory);
    // The file the recovered work had been saved to, if any (empty for untitled work).
    static QString originalPath(const QString& recoveryFile);
    static void removeRecoveryFile(const QString& recoveryFile);
    static QString defaultDirectory();

private:
    document::Document* m_document;
    QString m_file;
    std::unique_ptr<QLockFile> m_lock;
    QTimer* m_timer;
    quint64 m_savedRevision = 0;
};

} // namespace devsurf::app
