#pragma once

// A spline edge laid onto a reference curve (a curve imported from another program, e.g. the
// planned line of a crease or the rim of a part): the designer's way to start a crease or a
// strip's boundary on a given curve, before a Solve makes the surface developable again.

#include "composite_surface.h"
#include "reference_curve.h"

#include <cstddef>
#include <optional>
#include <vector>

namespace devsurf::model {

struct EdgeFit {
    enum class Refusal {
        NotSpline,   // the edge is a ruling (or does not exist)
        EndsMeet,    // both ends are nearest to the same point of the curve
        TooFewPoints // the curve has fewer than two distinct points
    };
    std::optional<Refusal> refused;
    double largestDistance = 0.0; // mm: the fitted edge from the curve piece, sampled densely
    double moved = 0.0;           // mm: the largest move of a control point
};

// Moves `edge`'s spline onto `curve`: each unpinned end vertex to the curve point nearest it,
// the inner control points by least squares onto the piece of the curve between those points,
// sampled by arc length (of a closed curve, the piece whose length is nearest the edge's).
// The rest of the surface follows only through the moved end vertices. Changes nothing when
// refused.
EdgeFit fitEdgeToCurve(CompositeSurface& surface, EdgeId edge, const ReferenceCurve& curve);

// The mean distance (mm) of an S-edge's spline from a curve, sampled: which curve is meant.
double edgeCurveDistance(const CompositeSurface& surface, EdgeId edge, const ReferenceCurve& curve);
// The index of the curve nearest the S-edge by that distance (0 for no curves).
std::size_t nearestCurve(const CompositeSurface& surface, EdgeId edge,
                         const std::vector<ReferenceCurve>& curves);

} // namespace devsurf::model
