#pragma once

namespace devsurf::solver {

// Runs CHOLMOD's OpenMP parallel regions on the calling thread, directly, while an instance
// lives on that thread (see serial_openmp.cpp).
//
// Debian's CHOLMOD is built with OpenMP: its supernodal factorisation and solve open parallel
// regions of a fixed four threads, several per supernode, whatever the machine has, and the
// BLAS it calls is single-threaded. Those threads spent more time waking each other than
// computing, and even inactive regions cost libgomp a team and a futex call each; run directly
// the factorisation is faster (docs/tuning.md).
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
