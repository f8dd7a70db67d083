#pragma once

#include <optional>
#include <string>

namespace devsurf::io {

// OpenCASCADE's STEP reader numbers the entity instances of a file's DATA section before it
// reads them, and an instance number given twice (#70 = …; … #70 = …;) makes it loop forever.
// This scan refuses such files before OpenCASCADE sees them: the reason, or nullopt. Strings
// ('…', '' inside) and comments (/* … */) are skipped.
std::optional<std::string> unsafeStepContent(const std::string& bytes);

} // namespace devsurf::io
