#pragma once

#include <string>

namespace devsurf::solver {

// Which BLAS the process actually uses (CHOLMOD links the generic libblas.so.3, whose
// provider is chosen by update-alternatives or LD_LIBRARY_PATH).
struct BlasInfo {
    std::string library; // resolved path of the shared object providing dgemm_
    std::string config;  // openblas_get_config() if available
    std::string vendor;  // "OpenBLAS", "BLIS", "MKL", "ATLAS", "reference" or "unknown"
    bool optimized = false;
    int threads = 1; // openblas_get_num_threads() if available

    std::string describe() const;
};

BlasInfo detectBlas();

} // namespace devsurf::solver
