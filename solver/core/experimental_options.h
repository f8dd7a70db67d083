#pragma once

namespace devsurf::solver {

// Variants of the guided-projection iteration that the product does not use, kept so that the
// benchmark (tests/bench) and the tests can compare against them. Set on a GuidedProjection with
// setExperimentalOptions(); why each is off is recorded in docs/tuning.md.
struct ExperimentalOptions {
    // Once the ε₁ phase is over, a step that increases Σ w² φ² of the constraint rows is
    // rejected (the iterate stays, the iteration counts) and ε₂ is raised tenfold for the next
    // step; accepted steps lower that boost again.
    bool rejectWorseSteps = false;
    // Levenberg–Marquardt step control in every iteration (also during the ε₁ phase): a step
    // that increases Σ w² φ² of the constraint rows (guards included) is rejected and ε₂ is
    // multiplied by 10 for the next step, beyond Options::eps2; an accepted step divides that
    // boost by 10 again. Rejected steps count as iterations.
    bool levenbergMarquardt = false;
    // The benchmark's reference: rebuild the normal matrix from triplets and run a full symbolic
    // and numeric factorisation every iteration (same terms, no caching).
    bool baseline = false;
};

} // namespace devsurf::solver
