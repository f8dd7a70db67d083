#pragma once

#include "model/project.h"

#include <QString>

#include <cstdint>
#include <string>

namespace devsurf::io {

// The .devsurf project file: a 24-byte envelope (magic "DEVSURF\0", format version,
// payload length, CRC-32 of the payload; little endian) around the project archive.
// 1: the first release. 2: pinned vertices. 3: smooth rulings, surface ids. 4: the kept
// development of every surface (older files open without one, as they were). 5: the sheet
// shape each kept development is confined to, the project's reference curves (older files
// open with a free sheet and without curves). 6: the project's reference shapes, meshes and
// point clouds (older files open without them). 7: crease curves drawn in the sheet (older
// files open without them).
inline constexpr std::uint32_t kProjectFormatVersion = 7;
inline constexpr std::size_t kProjectHeaderSize = 24;
inline constexpr std::uint64_t kMaxProjectFileSize = 512ull * 1024 * 1024;

std::string encodeProject(const model::Project& project);
// Throws FileError; the message does not name a file.
model::Project decodeProject(const std::string& bytes);

enum class Backup { Keep, None };

// Writes atomically (QSaveFile) and, with Backup::Keep, keeps the previous file as PATH.bak.
// Throws FileError with a sentence that names the file.
void saveProjectFile(const model::Project& project, const QString& path,
                     Backup backup = Backup::Keep);
// Throws FileError with a sentence that names the file; never returns a half-loaded project.
model::Project loadProjectFile(const QString& path);

} // namespace devsurf::io
