#pragma once

// How much sampling a cutting pattern at a given tolerance needs, and the bound beyond which
// building it would take many seconds. A design reaching far from the origin (up to 1 km, the
// validity limit) needs far more samples than its size in patches suggests; the command line
// and the application check the bound here before building, and word the answer themselves.

#include "model/composite_surface.h"
#include "model/project.h"

#include <optional>

namespace devsurf::model::pattern {

// Sampled points along all curves of one surface beyond which its pattern takes many seconds
// to build (the examples need at most 15,000).
inline constexpr long kMaxCurveSamples = 40000;

// Sampled points along all spline curves of a surface at this chord tolerance (mm).
long curveSampleCount(const CompositeSurface& surface, double tolerance);

// The first surface of a project whose curves need more than kMaxCurveSamples at a tolerance.
struct OversampledSurface {
    int surface = 0;      // index into Project::surfaces
    long samples = 0;     // at the tolerance asked for
    double reach = 0.0;   // mm: the control point furthest from the origin
    double coarser = 0.0; // mm: the finest of 0.1, 1 and 10 mm within the bound (0: none)
};
std::optional<OversampledSurface> oversampledSurface(const Project& project, double tolerance);

} // namespace devsurf::model::pattern
