#pragma once

#include "model/project.h"

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

// Vertex ids such as "0,4,7" (option names the option in the error). Throws std::invalid_argument
// (message without a final period) on anything else.
std::vector<model::VertexId> parseVertexIds(const std::string& text, const std::string& option);

// `devsurf-cli pin FILE --vertices IDS [--unpin] [--surface K] -o OUT`. Options are split by the
// caller ("--unpin" arrives as a flag). Throws std::invalid_argument for bad usage and io/model
// errors for bad input; returns the exit code.
int runPinCommand(const std::vector<std::string>& positional,
                  const std::vector<std::pair<std::string, std::string>>& options, bool unpin);

} // namespace devsurf::app
