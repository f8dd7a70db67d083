#include "devsurf_cli.h"
#include "pattern_commands.h"

#include "solver/core/blas_info.h"

#include <string>
#include <vector>

int main(int argc, char** argv) {
    // Before anything else: it may re-execute the program with a better BLAS kernel.
    devsurf::solver::useBestBlasKernel(argv);
    const auto application = devsurf::app::makeCliApplication(argc, argv);
    return devsurf::app::runDevsurfCli(std::vector<std::string>(argv + 1, argv + argc));
}
