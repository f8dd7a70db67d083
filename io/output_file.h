#pragma once

#include <QByteArray>
#include <QIODevice>
#include <QString>
#include <QStringList>

#include <cstdint>
#include <string>

class QSaveFile;

namespace devsurf::io {

// Why a path must not be written as an output. The front ends word it.
enum class OutputProblem {
    None,
    SameAsInput,   // it is one of the inputs (after links: the same device and inode)
    Folder,        // a directory
    NotRegularFile // a device, pipe or socket: a file renamed over it would replace it
};

// Whether `output` may be written when `inputs` are read (a path that does not exist yet is
// fine).
OutputProblem outputProblem(const QString& output, const QStringList& inputs = {});

// Writes `bytes` to `path` atomically: a temporary file next to it (unnamed where the file
// system allows) renamed over it at the end, so the old file stays if anything fails and a
// killed process leaves nothing. Refuses folders, devices, pipes and sockets. Throws FileError
// "Cannot write 'PATH': REASON." with the system's reason (e.g. no space left on device).
void writeFileAtomically(const QString& path, const QByteArray& bytes);

// The pieces of writeFileAtomically for writers that stream (PDF): refuses what
// writeFileAtomically refuses, then opens `file` (a QSaveFile on `path`) in `mode`.
void openOutputFile(QSaveFile& file, const QString& path,
                    QIODevice::OpenMode mode = QIODevice::WriteOnly | QIODevice::Unbuffered);
void commitOutputFile(QSaveFile& file, const QString& path);

// Reads at most `limit` bytes from `device`, in chunks, so that a device or pipe without an
// end (such as /dev/zero) costs no more memory than the bound. Throws FileError(reason) on a
// read error.
std::string readAtMost(QIODevice& device, std::uint64_t limit);

} // namespace devsurf::io
