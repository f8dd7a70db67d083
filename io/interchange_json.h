#pragma once

#include "model/project.h"

#include <QString>

#include <string>

namespace devsurf::io {

inline constexpr int kInterchangeVersion = 1;

// The interchange JSON, version 1 (docs/interchange-format.md): spline data of every strip,
// cone, planar face and crease, the sampled mesh and its development, written by QJsonDocument:
// every double in its shortest form that reads back bit for bit (−0 as 0). Throws
// model::ModelError if a surface is invalid.
std::string interchangeJson(const model::Project& project, int samplesPerInterval = 8);

// Writes the interchange JSON to a file atomically. Throws FileError with a sentence naming the
// file, or model::ModelError if a surface is invalid.
void saveInterchangeJsonFile(const model::Project& project, const QString& path,
                             int samplesPerInterval = 8);

} // namespace devsurf::io
