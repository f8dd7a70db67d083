#pragma once

// `devsurf-bench --paper`: the paper's Fig. 17 rows like for like. Each row is a built-in
// example that keeps its development (model::keepDevelopment), confined to a sheet of the
// example's shape so that the development is variables of the solve, at the size whose
// variable count (Problem::variableCount, the development included) is nearest the paper's.

#include "bench_models.h"

#include "model/composite_surface.h"
#include "solver/quality/quality_measures.h"

#include <functional>
#include <ostream>
#include <string>
#include <vector>

namespace devsurf::bench {

struct PaperBenchOptions {
    int iterations = 10;
    int runs = 3; // timing: the median of these runs, each from the same start
    // The start: Gaussian noise on the control points, three boundary vertices fixed (the solver
    // benchmark's start): σ = noise × the mean control-polygon edge length (the quality study's
    // scale, which follows the model's resolution as its size grows) or × the diameter.
    bool noiseOfDiameter = false;
    double noise = 0.01;
    std::vector<std::string>
        models; // rows by name (fig8, fig13, fig12, fig15a, fig12-folded); empty: all
    unsigned seed = 20150801u;
    double eps2 = 1e-3;
    // Largest example size tried (0: the example's own maximum); a small cap makes a fast run.
    int sizeCap = 0;
    bool runBaseline = true;
    std::function<void(const std::string&)> log;
};

struct PaperTiming {
    double assembly = 0.0;
    double factorize = 0.0;
    double solve = 0.0;
    double total = 0.0;
};

// The drag of devsurf-bench --drag on the Fig. 12 model with its development (filled by the
// executable, which has the worker).
struct PaperDrag {
    bool measured = false;
    std::string model;
    std::string development; // how the dragged surface keeps its development, in words
    int variables = 0;
    double medianMs = 0.0;
    double p95Ms = 0.0;
    double residualAfter = 0.0;
    std::string error;
};

struct PaperRowResult {
    std::string name;
    PaperRow paper;
    std::string example;
    int size = 0;
    std::string sheet; // the sheet's shape and size
    int variables = 0;
    int developmentVariables = 0;
    bool withinTenPercent = false;
    std::string note; // why the row differs from the paper's figure, if it does
    std::string status;
    double residual = 0.0;
    PaperTiming ours;           // per iteration, medians
    PaperTiming baseline;       // the rebuild baseline (ExperimentalOptions::baseline)
    double paperRatio = 0.0;    // ours / the paper's s/iter
    double baselineRatio = 0.0; // baseline / ours
    solver::QualityMeasures quality;
    double developmentEdgeError = -1.0; // largest relative pair error vs the kept development
    double sheetStretchMm = -1.0;       // model::keptSheetStretch
    // The surface with its development as the row starts (for the drag).
    model::CompositeSurface surface;
};

struct PaperReport {
    std::vector<PaperRowResult> rows;
    PaperDrag drag;
    // The same drag with a free sheet (the development fixed) and without the development, to
    // show what the sheet's shape and the development cost.
    std::vector<PaperDrag> dragReferences;
    std::string start;       // the start the rows were solved from, in words
    int iterations = 0;      // per run
    int runs = 0;            // timing runs per row (medians)
    double loadAverage = -1; // the machine's 1-minute load average at the end (-1: unknown)
};

PaperReport runPaperBench(const PaperBenchOptions& options);
void printPaperBench(const PaperReport& report, bool json, std::ostream& out);

} // namespace devsurf::bench
