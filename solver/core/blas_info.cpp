#include "solver/core/blas_info.h"

#include <dlfcn.h>

#include <climits>
#include <cstdlib>

namespace devsurf::solver {

namespace {

bool contains(const std::string& haystack, const char* needle) {
    return haystack.find(needle) != std::string::npos;
}

} // namespace

std::string BlasInfo::describe() const {
    std::string text = vendor + (optimized ? " (optimised)" : " (not optimised)");
    text += ", " + (library.empty() ? std::string("library unknown") : library);
    if (!config.empty()) {
        text += ", " + config;
    }
    text += ", " + std::to_string(threads) + " thread(s)";
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
    using ConfigFunction = char* (*)();
    using ThreadsFunction = int (*)();
    if (void* config = dlsym(RTLD_DEFAULT, "openblas_get_config")) {
        const char* text = reinterpret_cast<ConfigFunction>(config)();
        info.config = text ? text : "";
        info.vendor = "OpenBLAS";
        if (void* threads = dlsym(RTLD_DEFAULT, "openblas_get_num_threads")) {
            info.threads = reinterpret_cast<ThreadsFunction>(threads)();
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

std::mutex& blasMutex() {
    static std::mutex mutex;
    return mutex;
}

} // namespace devsurf::solver
