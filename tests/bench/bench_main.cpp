// devsurf-bench: the solver benchmark (the same code as `devsurf-cli bench`).
#include "benchmark.h"

#include <iostream>
#include <string>

int main(int argc, char** argv) {
    devsurf::bench::BenchmarkOptions options;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        if (arg == "--json") {
            options.json = true;
        } else if (arg == "--model" && i + 1 < argc) {
            options.models.push_back(argv[++i]);
        } else if (arg == "--no-ceres") {
            options.runCeres = false;
        } else {
            std::cerr << "usage: devsurf-bench [--json] [--model NAME]... [--no-ceres]\n";
            return 1;
        }
    }
    options.log = [](const std::string& line) { std::cerr << line << "\n"; };
    const int code = devsurf::bench::runBenchmark(options, std::cout);
    if (code != 0) {
        std::cerr << "devsurf-bench: no such model.\n";
    }
    return code;
}
