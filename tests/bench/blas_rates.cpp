#include "blas_rates.h"

#include <dlfcn.h>

#include <algorithm>
#include <chrono>
#include <vector>

namespace devsurf::bench {

// A threaded BLAS is held to one thread for it by the caller (runBenchmark).
double measureDgemmGflops() {
    using Dgemm = void (*)(const char*, const char*, const int*, const int*, const int*,
                           const double*, const double*, const int*, const double*, const int*,
                           const double*, double*, const int*);
    auto dgemm = reinterpret_cast<Dgemm>(dlsym(RTLD_DEFAULT, "dgemm_"));
    if (!dgemm) {
        return 0.0;
    }
    const int n = kDgemmSize;
    std::vector<double> a(static_cast<std::size_t>(n) * n, 0.5);
    std::vector<double> b(a.size(), 0.25);
    std::vector<double> c(a.size(), 0.0);
    const double one = 1.0;
    const double zero = 0.0;
    double best = 0.0;
    for (int repeat = 0; repeat < 3; ++repeat) {
        const auto start = std::chrono::steady_clock::now();
        dgemm("N", "N", &n, &n, &n, &one, a.data(), &n, b.data(), &n, &zero, c.data(), &n);
        const double seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        best = std::max(best, 2.0 * n * n * static_cast<double>(n) / seconds * 1e-9);
    }
    return best;
}

bool setBlasThreads(int threads) {
    using SetThreads = void (*)(int);
    auto set = reinterpret_cast<SetThreads>(dlsym(RTLD_DEFAULT, "openblas_set_num_threads"));
    if (!set) {
        return false;
    }
    set(threads);
    return true;
}

double amdahl(double fraction, int threads) {
    return 1.0 / ((1.0 - fraction) + fraction / threads);
}

double parallelFractionFromTwo(double speedup) {
    return speedup > 0.0 ? std::clamp(2.0 * (1.0 - 1.0 / speedup), 0.0, 1.0) : 0.0;
}

} // namespace devsurf::bench
