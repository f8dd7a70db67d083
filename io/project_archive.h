#pragma once

#include "model/project.h"

#include <string>

namespace devsurf::io {

// The payload of a project file: a Boost.Serialization text archive of the whole project.
// Saving is deterministic (entities in id order), so save → load → save gives the same bytes.
std::string writeProjectArchive(const model::Project& project);

// Throws FileError with a sentence when the archive is malformed, too new, or describes an
// invalid surface. Never allocates more than the archive's size justifies.
model::Project readProjectArchive(const std::string& payload);

} // namespace devsurf::io
