// devsurf_blas_time: an LD_PRELOAD library that measures how much of CHOLMOD's numeric
// factorisation and solve is spent inside the BLAS, the part a threaded BLAS can speed up.
// It wraps cholmod_factorize and cholmod_solve2 (called from our code) and the BLAS routines
// CHOLMOD calls (found by the dynamic linker in the preloaded library first), times the BLAS
// calls made inside either, and prints the totals on exit (stderr):
//   LD_PRELOAD=build/lib/libdevsurf_blas_time.so build/bin/devsurf-bench --blas
// Single-threaded by design: the bench runs one solver.
#include <dlfcn.h>

#include <chrono>
#include <cstdio>

namespace {

enum Phase { Factorize = 0, Solve = 1, Outside = 2 };

struct Totals {
    double seconds = 0.0;
    long calls = 0;
    double blasSeconds = 0.0;
    long blasCalls = 0;
};

Totals g_totals[2];
Phase g_phase = Outside;

double now() {
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch())
        .count();
}

template <typename Function> Function next(const char* name) {
    return reinterpret_cast<Function>(dlsym(RTLD_NEXT, name));
}

// Calls `real` with `args`, adding its time to the current phase's BLAS time.
template <typename Function, typename... Args> void timed(Function real, Args... args) {
    if (g_phase == Outside) {
        real(args...);
        return;
    }
    const double start = now();
    real(args...);
    g_totals[g_phase].blasSeconds += now() - start;
    ++g_totals[g_phase].blasCalls;
}

template <typename Result, typename Function, typename... Args>
Result inPhase(Phase phase, Function real, Args... args) {
    g_phase = phase;
    const double start = now();
    const Result result = real(args...);
    g_totals[phase].seconds += now() - start;
    ++g_totals[phase].calls;
    g_phase = Outside;
    return result;
}

struct Report {
    ~Report() {
        const char* names[2] = {"cholmod_factorize", "cholmod_solve2"};
        for (int p = 0; p < 2; ++p) {
            const Totals& t = g_totals[p];
            if (t.calls > 0) {
                std::fprintf(stderr,
                             "%s: %ld calls, %.1f ms; BLAS inside: %ld calls, %.1f ms, %.3f of "
                             "the time\n",
                             names[p], t.calls, 1e3 * t.seconds, t.blasCalls, 1e3 * t.blasSeconds,
                             t.seconds > 0.0 ? t.blasSeconds / t.seconds : 0.0);
            }
        }
    }
} g_report;

using P = void*; // the Fortran BLAS takes every argument by pointer

} // namespace

extern "C" {

void dgemm_(P a, P b, P c, P d, P e, P f, P g, P h, P i, P j, P k, P l, P m) {
    static const auto real = next<void (*)(P, P, P, P, P, P, P, P, P, P, P, P, P)>("dgemm_");
    timed(real, a, b, c, d, e, f, g, h, i, j, k, l, m);
}
void dsyrk_(P a, P b, P c, P d, P e, P f, P g, P h, P i, P j) {
    static const auto real = next<void (*)(P, P, P, P, P, P, P, P, P, P)>("dsyrk_");
    timed(real, a, b, c, d, e, f, g, h, i, j);
}
void dtrsm_(P a, P b, P c, P d, P e, P f, P g, P h, P i, P j, P k) {
    static const auto real = next<void (*)(P, P, P, P, P, P, P, P, P, P, P)>("dtrsm_");
    timed(real, a, b, c, d, e, f, g, h, i, j, k);
}
void dpotrf_(P a, P b, P c, P d, P e) {
    static const auto real = next<void (*)(P, P, P, P, P)>("dpotrf_");
    timed(real, a, b, c, d, e);
}
void dgemv_(P a, P b, P c, P d, P e, P f, P g, P h, P i, P j, P k) {
    static const auto real = next<void (*)(P, P, P, P, P, P, P, P, P, P, P)>("dgemv_");
    timed(real, a, b, c, d, e, f, g, h, i, j, k);
}
void dtrsv_(P a, P b, P c, P d, P e, P f, P g, P h) {
    static const auto real = next<void (*)(P, P, P, P, P, P, P, P)>("dtrsv_");
    timed(real, a, b, c, d, e, f, g, h);
}

int cholmod_factorize(P a, P l, P c) {
    static const auto real = next<int (*)(P, P, P)>("cholmod_factorize");
    return inPhase<int>(Factorize, real, a, l, c);
}
int cholmod_solve2(int s, P l, P b, P bs, P* x, P* xs, P* y, P* e, P c) {
    static const auto real = next<int (*)(int, P, P, P, P*, P*, P*, P*, P)>("cholmod_solve2");
    return inPhase<int>(Solve, real, s, l, b, bs, x, xs, y, e, c);
}

} // extern "C"
