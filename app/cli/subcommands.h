#pragma once

#include "command_line.h"

#include <string>
#include <vector>

namespace devsurf::app {

// Every subcommand of devsurf-cli with its options and help, in the order the help lists them.
const std::vector<SubcommandSpec>& subcommands();
// nullptr for an unknown name.
const SubcommandSpec* findSubcommand(const std::string& name);
// `devsurf-cli --help`: every subcommand's synopsis and description.
std::string overallHelp();

} // namespace devsurf::app
