#include "project_file.h"

#include "crc32.h"
#include "file_error.h"
#include "output_file.h"
#include "project_archive.h"

#include <QFile>
#include <QFileInfo>
#include <QSaveFile>

#include <cstring>
#include <new>

namespace devsurf::io {

namespace {

constexpr char kMagic[8] = {'D', 'E', 'V', 'S', 'U', 'R', 'F', '\0'};

void putLittleEndian(std::string& out, std::uint64_t value, int bytes) {
    for (int i = 0; i < bytes; ++i) {
        out.push_back(static_cast<char>((value >> (8 * i)) & 0xFFu));
    }
}

std::uint64_t getLittleEndian(const std::string& in, std::size_t offset, int bytes) {
    std::uint64_t value = 0;
    for (int i = 0; i < bytes; ++i) {
        value |= static_cast<std::uint64_t>(static_cast<unsigned char>(in[offset + i])) << (8 * i);
    }
    return value;
}

std::string quoted(const QString& path) {
    return "'" + path.toStdString() + "'";
}

} // namespace

std::string encodeProject(const model::Project& project) {
    const std::string payload = writeProjectArchive(project);
    std::string bytes(kMagic, sizeof kMagic);
    putLittleEndian(bytes, kProjectFormatVersion, 4);
    putLittleEndian(bytes, payload.size(), 8);
    putLittleEndian(bytes, crc32(payload.data(), payload.size()), 4);
    bytes += payload;
    return bytes;
}

model::Project decodeProject(const std::string& bytes) {
    if (bytes.size() < kProjectHeaderSize ||
        std::memcmp(bytes.data(), kMagic, sizeof kMagic) != 0) {
        throw FileError("it is not a DevSurf project file");
    }
    const auto version = static_cast<std::uint32_t>(getLittleEndian(bytes, 8, 4));
    if (version > kProjectFormatVersion) {
        throw FileError("it was saved by a newer version of DevSurf (file format " +
                        std::to_string(version) + "; this version reads formats up to " +
                        std::to_string(kProjectFormatVersion) + ")");
    }
    if (version == 0) {
        throw FileError("it has an invalid file format version 0");
    }
    const std::uint64_t length = getLittleEndian(bytes, 12, 8);
    const std::uint64_t available = bytes.size() - kProjectHeaderSize;
    if (length != available) {
        throw FileError(length > available
                            ? "it is truncated (" + std::to_string(available) + " of " +
                                  std::to_string(length) + " bytes of content are present)"
                            : "it has " + std::to_string(available - length) +
                                  " unexpected bytes after its content");
    }
    const auto expected = static_cast<std::uint32_t>(getLittleEndian(bytes, 20, 4));
    const std::string payload = bytes.substr(kProjectHeaderSize);
    if (crc32(payload.data(), payload.size()) != expected) {
        throw FileError("it is damaged: its checksum does not match its contents");
    }
    return readProjectArchive(payload);
}

namespace {

// Replaces PATH.bak by a copy of PATH atomically: the previous backup stays until the new one is
// complete, so a kill at any moment leaves one of them.
void keepBackup(const QString& path) {
    const QString backup = path + QStringLiteral(".bak");
    QFile current(path);
    if (!current.open(QIODevice::ReadOnly)) {
        throw FileError("Cannot save " + quoted(path) + ": the backup copy " + quoted(backup) +
                        " could not be written (" +
                        withoutFinalPeriod(current.errorString().toStdString()) + ").");
    }
    QSaveFile copy(backup);
    try {
        openOutputFile(copy, backup);
        for (;;) {
            const std::string chunk = readAtMost(current, 1u << 20);
            if (chunk.empty()) {
                break;
            }
            if (copy.write(chunk.data(), static_cast<qint64>(chunk.size())) !=
                static_cast<qint64>(chunk.size())) {
                const std::string reason = copy.errorString().toStdString();
                copy.cancelWriting();
                throw FileError(reason);
            }
        }
        commitOutputFile(copy, backup);
    } catch (const FileError& error) {
        throw FileError("Cannot save " + quoted(path) + ": the backup copy " + quoted(backup) +
                        " could not be written (" + withoutFinalPeriod(error.what()) + ").");
    }
}

} // namespace

void saveProjectFile(const model::Project& project, const QString& path, Backup backup) {
    const std::string bytes = encodeProject(project);
    switch (outputProblem(path)) {
    case OutputProblem::Folder:
        throw FileError("Cannot save " + quoted(path) + ": it is a folder.");
    case OutputProblem::NotRegularFile:
        throw FileError("Cannot save " + quoted(path) +
                        ": it is a device, pipe or socket, not a regular file.");
    case OutputProblem::None:
    case OutputProblem::SameAsInput:
        break;
    }
    QSaveFile file(path);
    // Unbuffered: a failing write reports the system's reason (a full disk), not "Unknown error".
    if (!file.open(QIODevice::WriteOnly | QIODevice::Unbuffered)) {
        throw FileError("Cannot save " + quoted(path) + ": " +
                        withoutFinalPeriod(file.errorString().toStdString()) + ".");
    }
    qint64 done = 0;
    while (done < static_cast<qint64>(bytes.size())) {
        const qint64 written =
            file.write(bytes.data() + done, static_cast<qint64>(bytes.size()) - done);
        if (written <= 0) {
            const std::string reason = file.errorString().toStdString();
            file.cancelWriting();
            throw FileError("Cannot save " + quoted(path) + ": " + withoutFinalPeriod(reason) +
                            ".");
        }
        done += written;
    }
    // Keep the previous version: a failed or regretted save never loses the last good file.
    if (backup == Backup::Keep && QFileInfo::exists(path)) {
        try {
            keepBackup(path);
        } catch (const FileError&) {
            file.cancelWriting();
            throw;
        }
    }
    if (!file.commit()) {
        throw FileError("Cannot save " + quoted(path) + ": " +
                        withoutFinalPeriod(file.errorString().toStdString()) + ".");
    }
}

model::Project loadProjectFile(const QString& path) {
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) {
        throw FileError("Cannot open " + quoted(path) + ": " +
                        withoutFinalPeriod(file.errorString().toStdString()) + ".");
    }
    const std::string tooLarge =
        "Cannot open " + quoted(path) + ": it is larger than any DevSurf project file can be.";
    if (static_cast<std::uint64_t>(file.size()) > kMaxProjectFileSize) {
        throw FileError(tooLarge);
    }
    try {
        // The header first: a device or pipe that holds no project (/dev/zero) is refused after
        // 24 bytes, and no more than the bound plus one byte is ever read.
        std::string bytes = readAtMost(file, kProjectHeaderSize);
        std::uint64_t rest = 0;
        if (bytes.size() == kProjectHeaderSize &&
            std::memcmp(bytes.data(), kMagic, sizeof kMagic) == 0) {
            rest = kMaxProjectFileSize + 1 - kProjectHeaderSize;
            const std::uint64_t length = getLittleEndian(bytes, 12, 8);
            if (file.isSequential() && length < rest) {
                rest = length + 1; // one byte more shows content after the payload
            }
        }
        bytes += readAtMost(file, rest);
        if (bytes.size() > kMaxProjectFileSize) {
            throw FileError(tooLarge);
        }
        return decodeProject(bytes);
    } catch (const std::bad_alloc&) {
        throw FileError("Cannot open " + quoted(path) + ": there is not enough memory to read it.");
    } catch (const FileError& error) {
        if (error.what() == tooLarge) {
            throw;
        }
        throw FileError("Cannot open " + quoted(path) + ": " + withoutFinalPeriod(error.what()) +
                            ".",
                        error.problems());
    }
}

} // namespace devsurf::io
