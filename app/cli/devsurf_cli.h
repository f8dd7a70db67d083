#pragma once

#include <string>
#include <vector>

namespace devsurf::app {

// Runs devsurf-cli with its arguments (without the program's name): prints what the
// subcommand prints and one sentence per failure on stderr; returns the exit code (0 success,
// 1 bad usage, 2 invalid or unreadable input or an output that cannot be written). Needs a
// QCoreApplication (a QGuiApplication for PDF export, see makeCliApplication).
int runDevsurfCli(const std::vector<std::string>& args);

} // namespace devsurf::app
