#include "autosaver.h"

#include "io/file_error.h"
#include "io/project_file.h"
#include "model/document/document.h"

#include <QCoreApplication>
#include <QDateTime>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QLockFile>
#include <QSaveFile>
#include <QStandardPaths>
#include <QTimer>

#include <algorithm>

namespace devsurf::app {

namespace {

QString sidecar(const QString& recoveryFile) {
    return recoveryFile + QStringLiteral(".origin");
}
QString lockName(const QString& recoveryFile) {
    return recoveryFile + QStringLiteral(".lock");
}

} // namespace

QString Autosaver::defaultDirectory() {
    return QDir(QStandardPaths::writableLocation(QStandardPaths::AppDataLocation))
        .filePath(QStringLiteral("recovery"));
}

Autosaver::Autosaver(document::Document* document, const QString& directory, int intervalMs,
                     QObject* parent)
    : QObject(parent), m_document(document), m_timer(new QTimer(this)) {
    QDir().mkpath(directory);
    m_file = QDir(directory).filePath(QStringLiteral("session-%1-%2.devsurf")
                                          .arg(QCoreApplication::applicationPid())
                                          .arg(QDateTime::currentMSecsSinceEpoch()));
    m_lock = std::make_unique<QLockFile>(lockName(m_file));
    m_lock->setStaleLockTime(0); // a lock is stale only when its process is gone
    m_lock->tryLock(0);
    m_timer->setInterval(intervalMs);
    connect(m_timer, &QTimer::timeout, this, &Autosaver::saveNow);
    // Once the work is saved (or undone back to the saved state) the recovery copy is older
    // than the file on disk: remove it at once, not at the next interval, so that a crash in
    // between does not offer to "recover" a state the designer has already replaced.
    connect(m_document, &document::Document::modifiedChanged, this, [this](bool modified) {
        if (!modified) {
            saveNow();
        }
    });
    m_timer->start();
}

Autosaver::~Autosaver() {
    discard();
}

void Autosaver::saveNow() {
    if (!m_document->isModified()) {
        QFile::remove(m_file);
        QFile::remove(sidecar(m_file));
        m_savedRevision = m_document->revision();
        return;
    }
    if (m_document->revision() == m_savedRevision && QFileInfo::exists(m_file)) {
        return;
    }
    try {
        io::saveProjectFile(m_document->project(), m_file, io::Backup::None);
        QSaveFile origin(sidecar(m_file));
        if (origin.open(QIODevice::WriteOnly)) {
            origin.write(m_document->filePath().toUtf8());
            origin.commit();
        }
        m_savedRevision = m_document->revision();
    } catch (const io::FileError&) {
        // A full disk must not interrupt the designer; the next interval tries again.
    }
}

void Autosaver::discard() {
    m_timer->stop();
    QFile::remove(m_file);
    QFile::remove(sidecar(m_file));
    if (m_lock && m_lock->isLocked()) {
        m_lock->unlock();
    }
}

QStringList Autosaver::staleRecoveryFiles(const QString& directory) {
    // A session killed before it wrote a recovery file leaves only its lock: remove those of
    // ended sessions, so they do not pile up (a running session's lock is not stale).
    const QFileInfoList locks = QDir(directory).entryInfoList(
        {QStringLiteral("session-*.devsurf.lock")}, QDir::Files | QDir::Hidden);
    for (const QFileInfo& info : locks) {
        const QString recovery = info.absoluteFilePath().chopped(int(qstrlen(".lock")));
        if (QFileInfo::exists(recovery)) {
            continue;
        }
        QLockFile lock(info.absoluteFilePath());
        lock.setStaleLockTime(0);
        if (lock.tryLock(0)) {
            lock.unlock(); // removes the lock file
            QFile::remove(sidecar(recovery));
        }
    }
    QStringList stale;
    const QFileInfoList files = QDir(directory).entryInfoList({QStringLiteral("session-*.devsurf")},
                                                              QDir::Files, QDir::Time);
    for (const QFileInfo& info : files) {
        QLockFile lock(lockName(info.absoluteFilePath()));
        lock.setStaleLockTime(0);
        if (lock.tryLock(0)) { // nobody holds it: its session is over
            lock.unlock();
            stale << info.absoluteFilePath();
        }
    }
    return stale;
}

QString Autosaver::originalPath(const QString& recoveryFile) {
    QFile origin(sidecar(recoveryFile));
    if (!origin.open(QIODevice::ReadOnly)) {
        return {};
    }
    return QString::fromUtf8(origin.readAll());
}

void Autosaver::removeRecoveryFile(const QString& recoveryFile) {
    QFile::remove(recoveryFile);
    QFile::remove(sidecar(recoveryFile));
    QFile::remove(lockName(recoveryFile));
}

} // namespace devsurf::app
