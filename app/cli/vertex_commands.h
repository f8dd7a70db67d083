#pragma once

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

// Vertex ids such as "0,4,7" (option names the option in the error). Throws std::invalid_argument
// (message without a final period) on anything else.
std::vector<model::VertexId> parseVertexIds(const std::string& text, const std::string& option);
// The same for any kind of id; `what` names it in the message ("edge").
std::vector<std::uint32_t> parseIds(const std::string& text, const std::string& option,
                                    const std::string& what);

// The value of a required option; throws std::invalid_argument(missing) when it is absent or
// empty.
std::string requiredOption(const std::vector<std::pair<std::string, std::string>>& options,
                           const std::string& name, const std::string& missing);

// The 0-based surface index of option --surface K (1-based; 0 without the option). Throws
// std::invalid_argument if K is not a surface of the project or the project has none (`purpose`
// completes "the project has no surface to …").
std::size_t surfaceOption(const std::vector<std::pair<std::string, std::string>>& options,
                          const model::Project& project, const std::string& purpose);

// `devsurf-cli pin FILE --vertices IDS [--unpin] [--surface K] -o OUT`. Options are split by the
// caller ("--unpin" arrives as a flag). Throws std::invalid_argument for bad usage and io/model
// errors for bad input; returns the exit code.
int runPinCommand(const std::vector<std::string>& positional,
                  const std::vector<std::pair<std::string, std::string>>& options, bool unpin);

} // namespace devsurf::app
