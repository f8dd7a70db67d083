#include "devsurf_cli.h"
#include "pattern_commands.h"

#include <string>
#include <vector>

int main(int argc, char** argv) {
    const auto application = devsurf::app::makeCliApplication(argc, argv);
    return devsurf::app::runDevsurfCli(std::vector<std::string>(argv + 1, argv + argc));
}
