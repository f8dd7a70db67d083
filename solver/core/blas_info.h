#pragma once

#include <mutex>
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

// The BLAS that setup.sh selects (Debian's single-threaded OpenBLAS) is built without locking:
// two threads inside it at once corrupt each other's buffers (two solver workers on the same
// structure failed with "matrix not positive definite" about once in 300 runs, and every time
// once the normal equations' row groups called it). Every call that may reach the BLAS (the
// supernodal factorisation and solve, the row groups' fill) holds this lock; one solver in
// the process never waits on it.
std::mutex& blasMutex();

} // namespace devsurf::solver
