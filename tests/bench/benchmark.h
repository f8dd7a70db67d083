#pragma once

#include <functional>
#include <ostream>
#include <string>
#include <vector>

namespace devsurf::bench {

struct BenchmarkOptions {
    bool json = false;
    std::vector<std::string> models; // empty: all
    int iterations = 10;
    double noise = 0.01; // σ as a fraction of the model's diameter
    // A second, quality-only run from this smaller σ (0 skips it): where the 1 % start is
    // rougher than the model's features (the annuli), it shows what the iteration reaches.
    double smallNoise = 0.001;
    unsigned seed = 20150801u; // fixed: every run starts from the same perturbed models
    double eps2 = 1e-3;
    double ceresCapSeconds = 60.0;
    bool runCeres = true;
    bool runBaseline = true;
    // The factorisation and the iteration on 1 and 2 BLAS threads (only with a threaded BLAS).
    bool measureThreads = true;
    bool compareAuxiliary = true; // also time the auxiliary-variable formulation
    // Quality over seeds (quality_study.h): 10 iterations (20 on the ~40,000-variable model)
    // from σ = 10 % of the mean control-polygon edge length and from σ = 1 % of the diameter,
    // `studySeeds` seeds each, worst and median, with the paper's configuration and with what
    // Tools ▸ Solve runs (StudySolver); 0 skips it.
    int studySeeds = 10;
    // Progress lines (to stderr in the command-line tools).
    std::function<void(const std::string&)> log;
};

// The solver benchmark (tests/bench): for each model, 10 iterations from the perturbed flat
// model with three boundary vertices fixed; timing split, flops, the BLAS kernel, DGEMM rate
// and bound, the speed-up on two BLAS threads, quality, the rebuild baseline and Ceres on the
// same start. Writes JSON or a table to `out`. Returns 0 on
// success.
int runBenchmark(const BenchmarkOptions& options, std::ostream& out);

// True if the Ceres peer was compiled in.
bool ceresAvailable();

} // namespace devsurf::bench
