// GOMP_parallel, the entry of libgomp (GCC's OpenMP runtime) that starts a parallel region:
// every `#pragma omp parallel` compiled by GCC calls it with the region's body as a function.
// CHOLMOD imports it (with omp_get_num_threads and omp_get_thread_num, nothing else), and
// this definition, in the executable, comes first in the dynamic linker's lookup and takes
// its calls. On a thread inside a SerialOpenMpRegions it runs the body directly, as the one
// thread of the region: outside any team, omp_get_num_threads() is 1 and
// omp_get_thread_num() 0, so a body that divides its loop among the team's threads (all of
// CHOLMOD's: static schedules) does all of it, as in a team of one, without the team. Every
// other call goes on to libgomp's GOMP_parallel unchanged.
#include "solver/core/serial_openmp.h"

#include <dlfcn.h>
#include <omp.h>

namespace devsurf::solver {

namespace {

thread_local bool t_serialRegions = false;

} // namespace

SerialOpenMpRegions::SerialOpenMpRegions() : m_outer(!t_serialRegions) {
    t_serialRegions = true;
    // Also for any region that does not pass through GOMP_parallel (none in CHOLMOD today):
    // inactive, so it runs on this thread alone.
    if (omp_get_max_active_levels() != 0) {
        omp_set_max_active_levels(0);
    }
}

SerialOpenMpRegions::~SerialOpenMpRegions() {
    if (m_outer) {
        t_serialRegions = false;
    }
}

bool serialOpenMpRegionsActive() {
    return t_serialRegions;
}

} // namespace devsurf::solver

extern "C" void GOMP_parallel(void (*body)(void*), void* data, unsigned threads, unsigned flags) {
    using Entry = void (*)(void (*)(void*), void*, unsigned, unsigned);
    static const Entry libgomp = reinterpret_cast<Entry>(dlsym(RTLD_NEXT, "GOMP_parallel"));
    if (devsurf::solver::serialOpenMpRegionsActive() || !libgomp) {
        body(data);
        return;
    }
    libgomp(body, data, threads, flags);
}
