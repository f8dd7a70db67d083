#pragma once

#include "command_line.h"

namespace devsurf::app {

// `devsurf-cli approximate TARGET [--from START.devsurf] [--strips K] [--intervals N]
// [--iterations N] [--rho R] -o OUT.devsurf`: developable strips pulled towards the mesh or
// point cloud TARGET (§4.2): the target thinned with radius R, the strips of START or K flat
// strips fitted by PCA to K clusters of the target, the approximation job, and the project
// written with the target stored in it; prints the residual and the distance report. Returns
// the exit code; throws UsageError, InputError and io::FileError.
int runApproximateCommand(const SubcommandArguments& args);

} // namespace devsurf::app
