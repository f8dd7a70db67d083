#pragma once

#include "cli_arguments.h"

namespace devsurf::app {

// `devsurf-cli solve`: N guided-projection iterations on every surface. Throws io/model errors
// for bad input; returns the exit code.
int runSolveCommand(const SolveArguments& args);

} // namespace devsurf::app
