#pragma once

#include <string>
#include <utility>
#include <vector>

namespace devsurf::app {

// `devsurf-cli drag FILE --vertices IDS (--by DX,DY,DZ | --rotate PX,PY,PZ,AX,AY,AZ,DEGREES)
// [--steps N] [--pin IDS] [--after K] [--surface K] -o OUT`: replays a drag as the desktop
// application runs it (N evenly spaced mouse positions with one solver iteration each, then K
// more iterations) through one SolveSession. Options are split by the caller. Throws
// std::invalid_argument for bad usage (message without a final period) and io/model errors for
// bad input; returns the exit code.
int runDragCommand(const std::vector<std::string>& positional,
                   const std::vector<std::pair<std::string, std::string>>& options);

} // namespace devsurf::app
