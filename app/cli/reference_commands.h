#pragma once

#include "command_line.h"
#include "io/reference/reference_import.h"
#include "model/reference/distance_report.h"

#include <string>

namespace devsurf::app {

// The terminal's sentence for a mesh or point cloud that cannot be read.
std::string referenceImportSentence(const io::ReferenceImportError& error, const std::string& path);

// Refuses, with the sentence the terminal prints, a TARGET of no mesh or point cloud format and,
// where `output` is given, an output file that is TARGET itself (the shape read would be lost).
void checkReferenceTarget(const std::string& target, const std::string& output = {});

// `devsurf-cli import-reference FILE TARGET [--name N] -o OUT`: the project with the mesh or
// point cloud TARGET added as a reference shape. Nothing is written when it cannot be read.
// Returns the exit code; throws UsageError and io::FileError.
int runImportReferenceCommand(const SubcommandArguments& args);

// `devsurf-cli distance FILE TARGET [--json] [--tolerance MM]`: how far the project's surfaces
// are from the mesh or point cloud TARGET (model::reference::measureDistance), both ways, and
// how much of the target lies within the tolerance. Returns the exit code.
int runDistanceCommand(const SubcommandArguments& args);

// The distance report's lines for a terminal (as `distance` prints them).
void printDistanceReport(const model::reference::DistanceReport& report, std::size_t targetPoints);

} // namespace devsurf::app
