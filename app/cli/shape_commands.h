#pragma once

#include "command_line.h"

#include <string>

namespace devsurf::app {

// Whether `name` (a --format value or an output's extension) is a 3D shape format: step,
// step214, step242, stp, iges, igs, obj, stl, ply.
bool isShapeFormat(const std::string& name);

// `devsurf-cli export FILE --format step|step214|iges|obj|stl|ply [--tolerance MM]
// [--thickness MM] -o OUT`: the 3D shape. `format` is the --format value or OUT's extension.
// Throws UsageError for bad usage and io/model errors for bad input; returns the exit code.
// Seams that could not be sewn are warnings on stderr.
int runExportShapeCommand(const SubcommandArguments& args, const std::string& format);

} // namespace devsurf::app
