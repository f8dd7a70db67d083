#pragma once

#include <string>
#include <vector>

namespace devsurf::app {

// `devsurf-cli solve FILE [--iterations N] [--perturb SIGMA --seed S] [--fix IDS] -o OUT`.
// Arguments are already split into positionals and "--name value" options by the caller.
// Throws std::invalid_argument for bad usage (message without a final period) and io/model
// errors for bad input; returns the exit code.
int runSolveCommand(const std::vector<std::string>& positional,
                    const std::vector<std::pair<std::string, std::string>>& options);

} // namespace devsurf::app
