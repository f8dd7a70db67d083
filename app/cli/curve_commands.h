#pragma once

#include "command_line.h"
#include "io/curves/curve_import.h"

#include <string>

namespace devsurf::app {

// The terminal's sentence for a curve file that cannot be read.
std::string curveImportSentence(const io::CurveImportError& error, const std::string& path);

// `devsurf-cli import-curves FILE CURVES [--tolerance MM] -o OUT`: the project with the curves
// of a DXF, SVG, STEP or IGES file added as reference curves. Nothing is written when the curves
// cannot be read. Returns the exit code; throws UsageError and io::FileError.
int runImportCurvesCommand(const SubcommandArguments& args);

// `devsurf-cli fit-edge FILE --edge E [--curve K] [--surface K] -o OUT`: the spline edge laid
// onto reference curve K (1-based; default the nearest), as Tools ▸ Fit Edge to Reference Curve.
int runFitEdgeCommand(const SubcommandArguments& args);

} // namespace devsurf::app
