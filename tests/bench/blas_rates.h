#pragma once

// The BLAS's own rates for devsurf-bench: DGEMM, its threads, and Amdahl's law to read a
// two-thread speed-up as a parallel fraction and predict more threads.

namespace devsurf::bench {

// The order of the square matrices measureDgemmGflops multiplies.
inline constexpr int kDgemmSize = 1000;

// Single-core DGEMM rate of the BLAS the process uses (the one CHOLMOD calls), in GFLOP/s:
// the best of three 1000×1000 products, the ceiling for a supernodal factorisation's flops.
// 0 if the process has no dgemm_.
double measureDgemmGflops();
// openblas_set_num_threads of the loaded BLAS; false if it has none.
bool setBlasThreads(int threads);
// Amdahl's law: the speed-up on `threads` of a run whose `fraction` is parallel.
double amdahl(double fraction, int threads);
// The parallel fraction that gives `speedup` on two threads (Amdahl's law solved for it).
double parallelFractionFromTwo(double speedup);

} // namespace devsurf::bench
