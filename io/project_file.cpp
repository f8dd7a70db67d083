#include "project_file.h"

#include "crc32.h"
#include "file_error.h"
#include "project_archive.h"

#include <QFile>
#include <QFileInfo>
#include <QSaveFile>

#include <cstring>

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

std::string withoutFinalPeriod(std::string text) {
    while (!text.empty() && (text.back() == '.' || text.back() == ' ')) {
        text.pop_back();
    }
    return text;
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

void saveProjectFile(const model::Project& project, const QString& path, Backup backup) {
    const std::string bytes = encodeProject(project);
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly)) {
        throw FileError("Cannot save " + quoted(path) + ": " +
                        withoutFinalPeriod(file.errorString().toStdString()) + ".");
    }
    if (file.write(bytes.data(), static_cast<qint64>(bytes.size())) !=
        static_cast<qint64>(bytes.size())) {
        const std::string reason = file.errorString().toStdString();
        file.cancelWriting();
        throw FileError("Cannot save " + quoted(path) + ": " + withoutFinalPeriod(reason) + ".");
    }
    // Keep the previous version: a failed or regretted save never loses the last good file.
    if (backup == Backup::Keep && QFileInfo::exists(path)) {
        const QString backup = path + QStringLiteral(".bak");
        QFile::remove(backup);
        if (!QFile::copy(path, backup)) {
            file.cancelWriting();
            throw FileError("Cannot save " + quoted(path) + ": the backup copy " + quoted(backup) +
                            " could not be written.");
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
    if (static_cast<std::uint64_t>(file.size()) > kMaxProjectFileSize) {
        throw FileError("Cannot open " + quoted(path) +
                        ": it is larger than any DevSurf project file can be.");
    }
    const QByteArray data = file.readAll();
    if (file.error() != QFileDevice::NoError) {
        throw FileError("Cannot open " + quoted(path) + ": " +
                        withoutFinalPeriod(file.errorString().toStdString()) + ".");
    }
    try {
        return decodeProject(std::string(data.constData(), static_cast<std::size_t>(data.size())));
    } catch (const FileError& error) {
        throw FileError("Cannot open " + quoted(path) + ": " + withoutFinalPeriod(error.what()) +
                            ".",
                        error.details());
    }
}

} // namespace devsurf::io
