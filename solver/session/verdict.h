#pragma once

#include "model/ids.h"
#include "solver/session/solve_job.h"

#include <optional>
#include <utility>
#include <vector>

namespace devsurf::solver {

// What a designer can do with a settled outcome, decided here once for every front end (the
// Solver panel, the views' corner, `devsurf-cli solve`); app/ words it.
enum class VerdictKind {
    None,           // no verdict: the job failed, was cancelled, or did not settle
    ReadyToCut,     // every solved surface reached the solve's tolerance, nothing folds over
    WithinIsometry, // developable up to isometryMm over the sheet: the cut is off by that much
    NotDevelopable, // `patches` say where, the advice flags what to try
};

struct Verdict {
    VerdictKind kind = VerdictKind::None;
    // Measured on the sampled development of the solved surfaces (largest over them): the
    // sheet's extent (mm), the largest relative edge-length error, and their product or the
    // unfolding's closure gap, whichever is larger (mm): how far the cut pattern can be off.
    double isometryMm = 0.0;
    double sheetExtent = 0.0;
    double edgeLengthError = 0.0;
    // Surfaces that keep their development: the largest distance (mm) between the surface and
    // its kept sheet (SurfaceAssessment::sheetStretchMm), -1 when none keeps one; and whether
    // it exceeds kKeptSheetTolerance of the sheet's extent, which makes the result not
    // developable from that sheet.
    double sheetStretchMm = -1.0;
    bool sheetStretched = false;
    // The largest final constraint residual and the solve's tolerance on it.
    double residual = 0.0;
    double tolerance = 0.0;
    // NotDevelopable: the patches to look at (surface index, patch), worst first per surface.
    std::vector<std::pair<int, model::FaceId>> patches;
    bool foldsOver = false; // a patch folds over onto itself, or the development overlaps
    // NotDevelopable only because a development overlaps itself: every surface is developable
    // patch by patch (not far off, on its sheet, nothing folded over), but cut from one piece
    // its sheet would lie on itself (a lifted annulus's rings).
    bool overlapsOnly = false;
    // What to try: solve again (the iteration limit was reached), release pins (the surface
    // is pinned), undo the last step (the edit made it fold over or solving made it worse).
    bool solveMore = false;
    bool releasePins = false;
    bool undoLastStep = false;
};

// The kept development is held to this fraction of the sheet's extent (0.03 mm over a 300 mm
// sheet, below a laser's kerf): a mesh sampled from a developable spline matches a flat copy
// only up to its sampling, so the development cannot be held to the residual tolerance.
inline constexpr double kKeptSheetTolerance = 1e-4;

// Ready to cut when every solved surface reached the solve's tolerance (Summary::tolerance)
// and nothing folds over. Otherwise a surface whose development's relative edge-length error
// exceeds kDragConvergedResidual (the strain at which a drag counts as not converged), whose
// worst patch's sampled developability residual exceeds it, that cannot be unfolded, folds
// over or was left as it was is not developable; else isometryMm
// says how close it is. A surface that keeps its development is not developable from its sheet
// when it lies farther from it than kKeptSheetTolerance of the sheet's extent.
Verdict verdictOf(const JobOutcome& outcome);

// Whether one settled surface is not developable as verdictOf judges it: far off (its sheet
// would stretch by more than kDragConvergedResidual, a patch's sampled developability exceeds
// it, or it cannot be unfolded) without reaching
// the tolerance, left as it was by Solve, off its kept sheet, folded over, or its development
// overlapping itself.
bool notDevelopable(const SurfaceAssessment& a);

// Whether a settled surface is broken: folded over onto itself, off its kept sheet, or, short
// of the tolerance, a patch sampled farther than kDragConvergedResidual from developable. A
// surface that is developable patch by patch but does not unfold into one sheet (a lifted
// annulus whose development overlaps itself) is not broken, only not cut from one piece. A
// drag never ends broken from a press that was not: SolveJob takes it back.
bool broken(const SurfaceAssessment& a);

// What makes a settled surface broken (broken() holds when any does), for the front ends to
// word.
struct BrokenBy {
    // Short of the tolerance, the patch sampled farthest from developable beyond
    // kDragConvergedResidual, and its normalised residual.
    std::optional<std::pair<model::FaceId, double>> worstFace;
    bool offSheet = false; // farther from its kept sheet than kKeptSheetTolerance
    int foldOverPlaces = 0;
    bool any() const { return worstFace || offSheet || foldOverPlaces > 0; }
};
BrokenBy brokenBy(const SurfaceAssessment& a);

} // namespace devsurf::solver
