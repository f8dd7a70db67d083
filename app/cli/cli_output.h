#pragma once

// Where devsurf-cli writes: the checks every subcommand makes before it reads or computes
// anything, and the writing of projects and of standard output ("-o -").

#include "model/project.h"

#include <QByteArray>

#include <string>
#include <vector>

namespace devsurf::app {

enum class OutputKind {
    Project, // a project file: writing it over its own input is an edit in place (FILE.bak kept)
    Other    // anything else: writing it over an input would destroy the input
};

// Refuses, before any work, an output that is a folder, a device, pipe or socket, or (for
// OutputKind::Other) one of the inputs, after resolving links: io::FileError (exit 2) with a
// sentence. "-" (standard output) is accepted for OutputKind::Other only (UsageError for a
// project). `what` names what is written ("the SVG pattern").
void checkOutput(const std::string& output, const std::vector<std::string>& inputs, OutputKind kind,
                 const std::string& what);

// An output whose extension is another format DevSurf writes (".pdf" for SVG, ".devsurf" for
// JSON) is a mistake: UsageError. Other extensions and none are accepted.
void checkExtension(const std::string& output, const std::string& extension,
                    const std::string& formatName);

// Writes a project file (keeping the previous version as OUTPUT.bak).
void writeProject(const model::Project& project, const std::string& output);

// Writes bytes to standard output; io::FileError if that fails.
void writeStandardOutput(const QByteArray& bytes);

} // namespace devsurf::app
