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
    int threads = 1;       // openblas_get_num_threads() if available
    bool threaded = false; // a BLAS that can run more than one thread (openblas_get_parallel)
    std::string kernel;    // openblas_get_corename() if available, e.g. "Haswell"
    // Who chose the kernel: "OpenBLAS" (its own detection), "DevSurf" (useBestBlasKernel) or
    // "OPENBLAS_CORETYPE" (set by the user); empty if the BLAS has no kernel name.
    std::string kernelChosenBy;
    std::string kernelRequested; // OPENBLAS_CORETYPE (OpenBLAS ignores a name it does not know)

    std::string describe() const;
};

BlasInfo detectBlas();

// The x86 instruction sets that decide which OpenBLAS kernel a CPU can run (usable: the
// operating system saves the registers too).
struct CpuFeatures {
    bool avx2 = false;
    bool fma = false;
    bool avx512 = false; // AVX-512 F, CD, BW, DQ and VL (what OpenBLAS's SkylakeX kernel uses)
};

CpuFeatures detectCpuFeatures();

// The OPENBLAS_CORETYPE to ask for when OpenBLAS chose `kernel` (openblas_get_corename) on a
// CPU with `cpu`: when the kernel is older than AVX2 (a DYNAMIC_ARCH build that does not know
// a new CPU falls back to one, "Prescott" at worst) while the CPU has AVX-512, "SkylakeX", or
// AVX2 with FMA, "Haswell". Empty if the kernel uses AVX2 already, the CPU has nothing better
// or the kernel's name is not known.
std::string recommendedCoreType(const std::string& kernel, const CpuFeatures& cpu);

// Called first thing in main() with main's argv: if OPENBLAS_CORETYPE is unset, the loaded
// OpenBLAS picks its kernel at run time and recommendedCoreType() names a better one, sets
// OPENBLAS_CORETYPE and re-executes the program once (OpenBLAS reads it only when it loads).
// Never when the user set OPENBLAS_CORETYPE; after the re-exec the variable is set, so there
// is no second one, whatever kernel OpenBLAS then takes. Returns if it does not re-execute.
void useBestBlasKernel(char** argv);

// The BLAS that setup.sh selects (Debian's single-threaded OpenBLAS) is built without locking:
// two threads inside it at once corrupt each other's buffers (two solver workers on the same
// structure failed with "matrix not positive definite" about once in 300 runs, and every time
// once the normal equations' row groups called it). Every call that may reach the BLAS (the
// supernodal factorisation and solve, the row groups' fill) holds this lock; one solver in
// the process never waits on it.
std::mutex& blasMutex();

} // namespace devsurf::solver
