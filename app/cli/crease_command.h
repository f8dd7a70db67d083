#pragma once

#include <string>
#include <utility>
#include <vector>

namespace devsurf::app {

// `devsurf-cli crease FILE --edges IDS --condition curved-fold|geodesic|straight|none
// [--surface K]
// -o OUT`: sets the condition the solver imposes on creases. Throws std::invalid_argument for
// bad usage and io/model errors for bad input; returns the exit code.
int runCreaseCommand(const std::vector<std::string>& positional,
                     const std::vector<std::pair<std::string, std::string>>& options);

// `devsurf-cli smooth FILE --edges IDS [--off] [--surface K] -o OUT`: marks rulings between
// two patches smooth (the solver keeps the surface smooth across them) or, with --off, sharp.
int runSmoothCommand(const std::vector<std::string>& positional,
                     const std::vector<std::pair<std::string, std::string>>& options, bool sharp);

} // namespace devsurf::app
