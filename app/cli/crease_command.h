#pragma once

#include "command_line.h"

namespace devsurf::app {

// `devsurf-cli crease FILE --edges IDS --condition curved-fold|geodesic|straight|none
// [--surface K] -o OUT`: sets the condition the solver imposes on creases. Throws UsageError for
// bad usage and io/model errors for bad input; returns the exit code.
int runCreaseCommand(const SubcommandArguments& args);

// `devsurf-cli smooth FILE --edges IDS [--off] [--surface K] -o OUT`: marks rulings between
// two patches smooth (the solver keeps the surface smooth across them) or, with --off, sharp.
int runSmoothCommand(const SubcommandArguments& args);

} // namespace devsurf::app
