#pragma once

// The cutting pattern as the application builds it: never with more samples than
// model::pattern::kMaxCurveSamples per surface. A design reaching far from the origin is sampled
// to a coarser tolerance, with a sentence saying so, or not built at all when even 10 mm would
// need too many samples; either way the answer comes at once, not after minutes.

#include "model/pattern/cutting_pattern.h"

#include <QString>

namespace devsurf::model {
struct Project;
}

namespace devsurf::app {

struct BoundedPattern {
    model::CuttingPattern pattern;
    double tolerance = 0.0; // mm: the tolerance the pattern was sampled to
    bool refused = false;   // no pattern: no tolerance up to 10 mm is within the bound
    QString note;           // empty, or why the tolerance was coarsened or nothing was built
};

BoundedPattern buildBoundedPattern(const model::Project& project,
                                   const model::PatternOptions& options);

} // namespace devsurf::app
