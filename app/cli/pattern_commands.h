#pragma once

#include "command_line.h"

#include <QCoreApplication>

#include <memory>
#include <string>
#include <vector>

namespace devsurf::app {

// `devsurf-cli export FILE --format dxf|svg|pdf|fold [--sheet W,H | --paper A4|A3|Letter]
// [--tolerance MM] [--splines] [--r12] [--seam MM] [--rulings] -o OUT`: the cutting pattern.
// Throws UsageError for bad usage and io/model errors for bad input; returns the exit code.
// Problems of the pattern (overlaps, pieces larger than the sheet) are warnings on stderr.
int runExportPatternCommand(const SubcommandArguments& args);

// `devsurf-cli report FILE [--json]` (and the pattern options of export): the fabrication
// report.
int runReportCommand(const SubcommandArguments& args);

// The application object of the tool: exporting a PDF paints text and reading SVG curves
// renders the drawing, which need a QGuiApplication (on the offscreen platform unless one is
// chosen); everything else a QCoreApplication.
std::unique_ptr<QCoreApplication> makeCliApplication(int& argc, char** argv);

} // namespace devsurf::app
