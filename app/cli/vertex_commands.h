#pragma once

#include "command_line.h"
#include "model/project.h"

#include <cstdint>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

namespace devsurf::app {

// What `devsurf-cli info FILE --vertices --edges [--json]` lists besides the summary.
struct EntityListing {
    bool vertices = false;
    bool edges = false;
    bool json = false;
};

// Every coarse vertex (id, x y z, pinned, on the boundary) and/or every edge (id, R or S, its two
// vertices, crease or boundary, crease condition) of every surface, as text or as one JSON
// document.
void printEntities(const model::Project& project, const EntityListing& listing, std::ostream& out);

// `devsurf-cli pin FILE --vertices IDS [--unpin] [--surface K] -o OUT`. Throws UsageError for
// bad usage and io/model errors for bad input; returns the exit code.
int runPinCommand(const SubcommandArguments& args);

// `devsurf-cli sheet FILE (--free | --off) [--surface K] -o OUT`: the surface keeps its
// development as it unfolds now (every solve and drag holds that sheet), or no longer.
int runSheetCommand(const SubcommandArguments& args);

} // namespace devsurf::app
