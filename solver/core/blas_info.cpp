#include "solver/core/blas_info.h"

#include <dlfcn.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <climits>
#include <cstdlib>

namespace devsurf::solver {

namespace {

bool contains(const std::string& haystack, const char* needle) {
    return haystack.find(needle) != std::string::npos;
}

// Set together with OPENBLAS_CORETYPE by useBestBlasKernel(): tells the re-executed process
// (and detectBlas()) that DevSurf, not the user, chose the kernel.
constexpr const char* kChosenCoreType = "DEVSURF_OPENBLAS_CORETYPE";

std::string lowercase(std::string text) {
    std::transform(text.begin(), text.end(), text.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return text;
}

// The widest vector instructions an x86 OpenBLAS kernel (openblas_get_corename) uses:
// 0 SSE only, 1 AVX, 2 AVX2 with FMA, 3 AVX-512; -1 for a name not listed here.
int kernelLevel(const std::string& kernel) {
    const std::string name = lowercase(kernel);
    for (const char* k : {"skylakex", "cooperlake", "sapphirerapids"}) {
        if (name == k) {
            return 3;
        }
    }
    for (const char* k : {"haswell", "zen"}) {
        if (name == k) {
            return 2;
        }
    }
    for (const char* k : {"sandybridge", "bulldozer", "piledriver", "steamroller", "excavator"}) {
        if (name == k) {
            return 1;
        }
    }
    for (const char* k : {"katmai", "coppermine", "northwood", "prescott", "banias", "atom",
                          "core2", "penryn", "dunnington", "nehalem", "athlon", "opteron",
                          "opteron(sse3)", "opteron_sse3", "barcelona", "nano", "bobcat"}) {
        if (name == k) {
            return 0;
        }
    }
    return -1;
}

std::string openBlasString(const char* function) {
    using StringFunction = char* (*)();
    if (void* f = dlsym(RTLD_DEFAULT, function)) {
        const char* text = reinterpret_cast<StringFunction>(f)();
        return text ? text : "";
    }
    return {};
}

} // namespace

std::string BlasInfo::describe() const {
    std::string text = vendor + (optimized ? " (optimised)" : " (not optimised)");
    text += ", " + (library.empty() ? std::string("library unknown") : library);
    if (!config.empty()) {
        text += ", " + config;
    }
    text += ", " + std::to_string(threads) + " thread(s)";
    if (!kernel.empty()) {
        text += ", kernel " + kernel + " (chosen by " + kernelChosenBy;
        if (!kernelRequested.empty() && lowercase(kernelRequested) != lowercase(kernel)) {
            text += ", OPENBLAS_CORETYPE=" + kernelRequested;
        }
        text += ")";
    }
    return text;
}

BlasInfo detectBlas() {
    BlasInfo info;
    void* dgemm = dlsym(RTLD_DEFAULT, "dgemm_");
    Dl_info where{};
    if (dgemm && dladdr(dgemm, &where) != 0 && where.dli_fname) {
        char resolved[PATH_MAX];
        info.library = realpath(where.dli_fname, resolved) ? resolved : where.dli_fname;
    }
    using IntFunction = int (*)();
    if (dlsym(RTLD_DEFAULT, "openblas_get_config")) {
        info.config = openBlasString("openblas_get_config");
        info.vendor = "OpenBLAS";
        if (void* threads = dlsym(RTLD_DEFAULT, "openblas_get_num_threads")) {
            info.threads = reinterpret_cast<IntFunction>(threads)();
        }
        // 0 sequential, 1 pthreads, 2 OpenMP.
        if (void* parallel = dlsym(RTLD_DEFAULT, "openblas_get_parallel")) {
            info.threaded = reinterpret_cast<IntFunction>(parallel)() != 0;
        }
        info.kernel = openBlasString("openblas_get_corename");
        if (!info.kernel.empty()) {
            const char* requested = std::getenv("OPENBLAS_CORETYPE");
            const char* ours = std::getenv(kChosenCoreType);
            info.kernelRequested = requested ? requested : "";
            info.kernelChosenBy = !requested                               ? "OpenBLAS"
                                  : ours && std::string(ours) == requested ? "DevSurf"
                                                                           : "OPENBLAS_CORETYPE";
        }
    } else if (dlsym(RTLD_DEFAULT, "bli_info_get_version_str")) {
        info.vendor = "BLIS";
    } else if (dlsym(RTLD_DEFAULT, "MKL_Get_Max_Threads")) {
        info.vendor = "MKL";
    } else if (dlsym(RTLD_DEFAULT, "ATL_xerbla") || contains(info.library, "atlas")) {
        info.vendor = "ATLAS";
    } else if (contains(info.library, "/blas/") || contains(info.library, "libblas.so.3") ||
               contains(info.library, "refblas")) {
        info.vendor = "reference";
    } else {
        info.vendor = "unknown";
    }
    if (contains(info.library, "openblas")) {
        info.vendor = "OpenBLAS";
    }
    info.optimized = info.vendor != "reference" && info.vendor != "unknown";
    return info;
}

CpuFeatures detectCpuFeatures() {
    CpuFeatures cpu;
#if defined(__x86_64__) || defined(__i386__)
    __builtin_cpu_init();
    cpu.avx2 = __builtin_cpu_supports("avx2");
    cpu.fma = __builtin_cpu_supports("fma");
    cpu.avx512 = __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512cd") &&
                 __builtin_cpu_supports("avx512bw") && __builtin_cpu_supports("avx512dq") &&
                 __builtin_cpu_supports("avx512vl");
#endif
    return cpu;
}

std::string recommendedCoreType(const std::string& kernel, const CpuFeatures& cpu) {
    // An AVX2 kernel stays on an AVX-512 CPU: the factorisation gains nothing measurable from
    // SkylakeX over Haswell, and a restart costs the start-up once more (docs/tuning.md).
    const int level = kernelLevel(kernel);
    if (level < 0 || level >= 2) {
        return {};
    }
    if (cpu.avx512) {
        return "SkylakeX";
    }
    if (cpu.avx2 && cpu.fma) {
        return "Haswell";
    }
    return {};
}

void useBestBlasKernel(char** argv) {
    if (std::getenv("OPENBLAS_CORETYPE")) {
        return; // the user's choice, or ours after the re-exec
    }
    // OPENBLAS_CORETYPE only matters to a build that chooses its kernel at run time.
    if (!contains(openBlasString("openblas_get_config"), "DYNAMIC_ARCH")) {
        return;
    }
    const std::string coreType =
        recommendedCoreType(openBlasString("openblas_get_corename"), detectCpuFeatures());
    if (coreType.empty() || !argv || !argv[0]) {
        return;
    }
    setenv("OPENBLAS_CORETYPE", coreType.c_str(), 1);
    setenv(kChosenCoreType, coreType.c_str(), 1);
    execv("/proc/self/exe", argv);
    // Not re-executed (no /proc): carry on with the kernel already loaded.
    unsetenv("OPENBLAS_CORETYPE");
    unsetenv(kChosenCoreType);
}

std::mutex& blasMutex() {
    static std::mutex mutex;
    return mutex;
}

} // namespace devsurf::solver
