#pragma once

namespace devsurf::solver {

// Runs CHOLMOD's OpenMP parallel regions on the calling thread, directly, while an instance
// lives on that thread (see serial_openmp.cpp).
//
// Debian's CHOLMOD is built with OpenMP: its supernodal factorisation and solve open parallel
// regions of a fixed four threads (CHOLMOD_OMP_NUM_THREADS), several per supernode, whatever
// the machine has, and the BLAS it calls is single-threaded. Those threads spent more time
// waking each other than computing (the 40,200-variable annulus: 135 ms per factorisation,
// 50 ms on one thread). Keeping the regions inactive (OpenMP's max-active-levels 0) still
// left libgomp building a team of one for every region and waking its barrier with a futex
// system call at the end: 139 system calls per factorisation of fig8-sheet. Run directly,
// factorisation ms per iteration: fig8-sheet 0.132 → 0.094, fig12-annulus 0.70 → 0.55,
// large-annulus 32.5 → 27.3.
class SerialOpenMpRegions {
public:
    SerialOpenMpRegions();
    ~SerialOpenMpRegions();
    SerialOpenMpRegions(const SerialOpenMpRegions&) = delete;
    SerialOpenMpRegions& operator=(const SerialOpenMpRegions&) = delete;

private:
    bool m_outer; // the outermost instance on its thread (nested instances leave it on)
};

// Whether the calling thread is inside a SerialOpenMpRegions.
bool serialOpenMpRegionsActive();

} // namespace devsurf::solver
