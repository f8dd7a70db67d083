#include "output_file.h"

#include "file_error.h"

#include <QFile>
#include <QSaveFile>

#include <sys/stat.h>

#include <algorithm>

namespace devsurf::io {

namespace {

[[noreturn]] void cannotWrite(const QString& path, const std::string& reason) {
    throw FileError("Cannot write '" + path.toStdString() + "': " + withoutFinalPeriod(reason) +
                    ".");
}

// stat(2) following links; false when the path does not exist (or cannot be examined).
bool statOf(const QString& path, struct stat& info) {
    return ::stat(QFile::encodeName(path).constData(), &info) == 0;
}

void refuseNonRegular(const QString& path) {
    switch (outputProblem(path)) {
    case OutputProblem::Folder:
        cannotWrite(path, "it is a folder");
    case OutputProblem::NotRegularFile:
        cannotWrite(path, "it is a device, pipe or socket, not a regular file");
    case OutputProblem::None:
    case OutputProblem::SameAsInput:
        break;
    }
}

// The system's reason as Qt gives it.
std::string reasonOf(const QFileDevice& file) {
    const QString reason = file.errorString();
    return reason.isEmpty() ? std::string("the write failed") : reason.toStdString();
}

} // namespace

OutputProblem outputProblem(const QString& output, const QStringList& inputs) {
    struct stat target {};
    if (!statOf(output, target)) {
        return OutputProblem::None;
    }
    for (const QString& input : inputs) {
        struct stat source {};
        if (statOf(input, source) && source.st_dev == target.st_dev &&
            source.st_ino == target.st_ino) {
            return OutputProblem::SameAsInput;
        }
    }
    if (S_ISDIR(target.st_mode)) {
        return OutputProblem::Folder;
    }
    if (!S_ISREG(target.st_mode)) {
        return OutputProblem::NotRegularFile;
    }
    return OutputProblem::None;
}

void openOutputFile(QSaveFile& file, const QString& path, QIODevice::OpenMode mode) {
    refuseNonRegular(path);
    if (!file.open(mode)) {
        cannotWrite(path, reasonOf(file));
    }
}

void commitOutputFile(QSaveFile& file, const QString& path) {
    if (!file.commit()) {
        cannotWrite(path, reasonOf(file));
    }
}

void writeFileAtomically(const QString& path, const QByteArray& bytes) {
    QSaveFile file(path);
    // Unbuffered: a failing write(2) reports its errno (a buffered QSaveFile says "Unknown
    // error" when the disk is full).
    openOutputFile(file, path);
    qint64 done = 0;
    while (done < bytes.size()) {
        const qint64 written = file.write(bytes.constData() + done, bytes.size() - done);
        if (written <= 0) {
            const std::string reason = reasonOf(file);
            file.cancelWriting();
            cannotWrite(path, reason);
        }
        done += written;
    }
    commitOutputFile(file, path);
}

std::string readAtMost(QIODevice& device, std::uint64_t limit) {
    constexpr std::uint64_t kChunk = 1u << 20;
    std::string bytes;
    while (bytes.size() < limit) {
        const std::size_t old = bytes.size();
        const std::size_t want = static_cast<std::size_t>(std::min(kChunk, limit - old));
        bytes.resize(old + want);
        const qint64 got = device.read(bytes.data() + old, static_cast<qint64>(want));
        if (got < 0) {
            throw FileError(device.errorString().toStdString());
        }
        bytes.resize(old + static_cast<std::size_t>(got));
        if (got == 0) {
            break;
        }
    }
    return bytes;
}

} // namespace devsurf::io
