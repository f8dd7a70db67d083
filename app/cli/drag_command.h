#pragma once

#include "cli_arguments.h"

namespace devsurf::app {

// `devsurf-cli drag`: replays a drag as the desktop application runs it (N evenly spaced mouse
// positions with one solver iteration each, then K more iterations) through one SolveSession.
// Throws UsageError for bad usage and io/model errors for bad input; returns the exit code.
int runDragCommand(const DragArguments& args);

} // namespace devsurf::app
