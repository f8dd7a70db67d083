#include "solve_command.h"

#ifdef DEVSURF_HAVE_BENCH
#include "benchmark.h"
#endif

#include <iostream>

namespace devsurf::app {

int runBenchCommand(bool json) {
#ifdef DEVSURF_HAVE_BENCH
    bench::BenchmarkOptions options;
    options.json = json;
    options.log = [](const std::string& line) { std::cerr << line << "\n"; };
    return bench::runBenchmark(options, std::cout);
#else
    (void)json;
    std::cerr << "devsurf-cli: the benchmark is not part of this build (tests/bench is skipped "
                 "in the sanitizer build); use a normal build.\n";
    return 2;
#endif
}

} // namespace devsurf::app
