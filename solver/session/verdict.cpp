#include "solver/session/verdict.h"

#include "solver/session/drag_lengths.h"

#include <algorithm>

namespace devsurf::solver {

namespace {

void addPatch(Verdict& verdict, int surface, model::FaceId face) {
    const std::pair<int, model::FaceId> place{surface, face};
    if (std::find(verdict.patches.begin(), verdict.patches.end(), place) == verdict.patches.end()) {
        verdict.patches.push_back(place);
    }
}

// Short of the tolerance, a patch's sampled developability residual exceeds
// kDragConvergedResidual. (A narrow strip's sampled mesh unfolds without stretching however
// little developable it is, so the unfolding alone can miss it: the torus's bands.)
bool worstFaceOff(const SurfaceAssessment& a) {
    return !a.summary.toleranceReached && !a.worstFaces.empty() &&
           a.worstFaces.front().second > kDragConvergedResidual;
}

// Far off: the sheet would stretch by more than kDragConvergedResidual (relative) to lie on its
// development, it could not be unfolded at all, a patch is far from developable, or Solve left
// the design as it was.
bool farOff(const SurfaceAssessment& a) {
    return (!a.summary.toleranceReached &&
            (a.edgeLengthError > kDragConvergedResidual || a.isometryMm < 0.0)) ||
           worstFaceOff(a) || a.keptAsItWas.has_value();
}

bool sheetStretched(const SurfaceAssessment& a) {
    return a.sheetStretchMm > kKeptSheetTolerance * std::max(a.sheetExtent, 1.0);
}

// Not developable for a reason other than a development that overlaps itself.
bool notDevelopableApartFromOverlap(const SurfaceAssessment& a) {
    return farOff(a) || sheetStretched(a) || !a.foldOvers.empty();
}

} // namespace

BrokenBy brokenBy(const SurfaceAssessment& a) {
    BrokenBy by;
    if (worstFaceOff(a)) {
        by.worstFace = a.worstFaces.front();
    }
    by.offSheet = sheetStretched(a);
    for (const auto& [face, places] : a.foldOvers) {
        (void)face;
        by.foldOverPlaces += places;
    }
    return by;
}

bool broken(const SurfaceAssessment& a) {
    return brokenBy(a).any();
}

bool notDevelopable(const SurfaceAssessment& a) {
    return notDevelopableApartFromOverlap(a) || !a.overlapping.empty();
}

Verdict verdictOf(const JobOutcome& outcome) {
    Verdict verdict;
    if (!outcome.ok || !outcome.settled) {
        return verdict;
    }
    bool anySolved = false;
    bool allReached = true;
    bool anyNotDevelopable = false;
    bool anyOtherThanOverlap = false;
    for (std::size_t s = 0; s < outcome.assessments.size(); ++s) {
        const SurfaceAssessment& a = outcome.assessments[s];
        if (!a.solved || !a.measured) {
            continue;
        }
        anySolved = true;
        const int surface = static_cast<int>(s);
        verdict.residual = std::max(verdict.residual, a.summary.finalMaxConstraintResidual);
        verdict.tolerance = std::max(verdict.tolerance, a.summary.tolerance);
        verdict.isometryMm = std::max(verdict.isometryMm, a.isometryMm);
        verdict.sheetExtent = std::max(verdict.sheetExtent, a.sheetExtent);
        verdict.edgeLengthError = std::max(verdict.edgeLengthError, a.edgeLengthError);
        allReached = allReached && a.summary.toleranceReached;
        verdict.sheetStretchMm = std::max(verdict.sheetStretchMm, a.sheetStretchMm);
        verdict.sheetStretched = verdict.sheetStretched || sheetStretched(a);
        // Folding over or overlapping cannot be cut, however small the residual.
        for (const auto& [face, places] : a.foldOvers) {
            (void)places;
            addPatch(verdict, surface, face);
            verdict.foldsOver = true;
        }
        for (model::FaceId face : a.overlapping) {
            addPatch(verdict, surface, face);
            verdict.foldsOver = true;
        }
        if (farOff(a)) {
            for (const auto& [face, residual] : a.worstFaces) {
                (void)residual;
                addPatch(verdict, surface, face);
            }
            verdict.solveMore = verdict.solveMore || (a.summary.status == Status::IterationLimit &&
                                                      !a.keptAsItWas.has_value());
            const model::CompositeSurface* shape =
                s < outcome.surfaces.size() ? &outcome.surfaces[s] : nullptr;
            verdict.releasePins =
                verdict.releasePins || (shape != nullptr && !shape->pinnedVertices().empty());
        }
        if (notDevelopable(a)) {
            anyNotDevelopable = true;
            anyOtherThanOverlap = anyOtherThanOverlap || notDevelopableApartFromOverlap(a);
            verdict.undoLastStep = verdict.undoLastStep || a.keptAsItWas.has_value() ||
                                   !a.foldOvers.empty() || !a.overlapping.empty();
        }
    }
    if (!anySolved) {
        return verdict;
    }
    verdict.overlapsOnly = anyNotDevelopable && !anyOtherThanOverlap;
    verdict.kind = anyNotDevelopable ? VerdictKind::NotDevelopable
                   : allReached      ? VerdictKind::ReadyToCut
                                     : VerdictKind::WithinIsometry;
    return verdict;
}

} // namespace devsurf::solver
