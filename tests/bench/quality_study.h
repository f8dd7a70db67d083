#pragma once

#include "model/composite_surface.h"
#include "solver/core/experimental_options.h"
#include "solver/core/options.h"
#include "solver/core/summary.h"
#include "solver/formulation/surface_formulation.h"
#include "solver/quality/shape_change.h"

#include <string>
#include <vector>

namespace devsurf::bench {

// The scale of a start's Gaussian noise: a fraction of the mean control-polygon edge length or
// of the model's diameter.
enum class NoiseScale { EdgeLength, Diameter };

struct StudyStart {
    NoiseScale scale = NoiseScale::Diameter;
    double fraction = 0.01;
};

// What solves a start: GuidedProjection with StudyOptions' formulation and solver options, or
// what Tools ▸ Solve and `devsurf-cli solve` run (a solver::SolveSession with its defaults: for
// a rough start, the pull towards the start, vertex developability kept where it holds, the
// step limit on guarded lengths, and a stop at the last valid iterate), the fixed vertices
// pinned.
enum class StudySolver { Options, Session };

struct StudyOptions {
    StudySolver solverKind = StudySolver::Options;
    int iterations = 10;
    int seeds = 10;
    unsigned firstSeed = 20150801u;
    int fixedVertices = 3; // boundary vertices fixed (spread over the boundary)
    solver::FormulationOptions formulation;
    solver::Options solver;
    // Variants of the iteration the product does not use (StudySolver::Options only).
    solver::ExperimentalOptions experimental;
    // Also run Ceres' Levenberg–Marquardt (ceres_peer.h) from each start on the same constraint
    // rows (StudySolver::Options only) for up to 1,000 iterations or 60 s, towards 1e-10.
    bool ceres = false;
};

// One solve from one seed, measured on the geometry.
struct StudyRun {
    unsigned seed = 0;
    std::string status;
    double residual = 0.0; // the solver's largest constraint residual at the end
    double detMax = 0.0;   // normalised developability residual, max
    double flatnessMean = 0.0;
    solver::ShapeChange change;
    // Patches at which the result's development overlaps itself (model::selfOverlappingPatches).
    std::vector<model::FaceId> overlapping;
    double msPerIteration = 0.0;
    std::vector<solver::IterationStats> iterations; // the solver's per-iteration statistics
    // With StudyOptions::ceres: Ceres' largest constraint residual at its end, its iterations.
    double ceresResidual = -1.0;
    int ceresIterations = 0;
};

// Worst and median over the seeds ("worst" is the largest residual, the shortest ruling, …).
struct StudySummary {
    double detWorst = 0.0, detMedian = 0.0;
    double flatnessWorst = 0.0, flatnessMedian = 0.0;
    double rulingWorst = 0.0, rulingMedian = 0.0;
    double speedWorst = 0.0, speedMedian = 0.0;
    double foldWorst = 0.0, foldMedian = 0.0; // radians
    double startAngleMedian = 0.0;            // radians
    double foldOverStartWorst = 0.0, foldOverStartMedian = 0.0;
    // Seeds whose result folds over onto itself somewhere, and the most places in one result.
    int foldedOverSeeds = 0;
    int foldOverPlacesWorst = 0;
    // Seeds whose result's development overlaps itself (it cannot be cut from one sheet).
    int overlappingSeeds = 0;
};

// Noise σ in model units for a start on `surface`.
double noiseSigma(const model::CompositeSurface& surface, const StudyStart& start);

std::vector<StudyRun> runStudy(const model::CompositeSurface& surface, const StudyStart& start,
                               const StudyOptions& options);
StudySummary summarize(const std::vector<StudyRun>& runs);

} // namespace devsurf::bench
