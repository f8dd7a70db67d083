#pragma once

#include "model/composite_surface.h"

#include <string>
#include <vector>

namespace devsurf::bench {

// A row of the paper's Fig. 17 (Intel i5-3320M, after 10 iterations).
struct PaperRow {
    std::string figure;
    int controlPoints = 0;
    int strips = 0;
    int variables = 0;
    double flatnessMean = 0.0;
    double flatnessMax = 0.0;
    double secondsPerIteration = 0.0;
};

// A flat model matched to a Fig. 17 row by control points and strips.
struct BenchModel {
    std::string name;
    model::CompositeSurface surface;
    PaperRow paper;
};

// Two strips side by side between three S-edges of `intervals` cubic C² intervals each
// (Fig. 13: 36 control points for 9 intervals), straight and parallel; with `bow` (mm) the
// middle one bows towards +y by up to that much and carries the curved-fold condition (one
// curved crease in two strips, as in Fig. 13).
model::CompositeSurface makeTwoStripSheet(int intervals, double bow = 0.0);

// The benchmark's models: Fig. 8, Fig. 13, Fig. 12 and a model of about 40,000 variables
// (compared with Fig. 15a, the paper's row of that size). `names` selects (empty: all).
std::vector<BenchModel> benchModels(const std::vector<std::string>& names = {});

} // namespace devsurf::bench
