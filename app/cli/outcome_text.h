#pragma once

#include "model/held_by_pins.h"
#include "model/ids.h"
#include "solver/quality/quality_measures.h"
#include "solver/session/crease_drag.h"
#include "solver/session/solve_job.h"

#include <string>
#include <utility>
#include <vector>

// The command line's words for the solve job's outcome (a terminal's English; the desktop
// application words the same assessment with tr()).
namespace devsurf::app {

// "Folded over onto itself: face 3 (2 places), …" or "No face folds over onto itself."; the first
// kFoldOversNamed faces are named, the rest counted.
std::string describeFoldOvers(const std::vector<std::pair<model::FaceId, int>>& foldOvers);
// "The development overlaps itself at patches 1, 4 and cannot be cut from one sheet." or "The
// development does not overlap itself."
std::string describeSelfOverlap(const std::vector<model::FaceId>& patches);
// "Vertex 5 lies inside the triangle of the pinned vertices 0, 3 and 12, …"
std::string describeHeld(const model::HeldVertex& held);
// What went wrong at the end of a drag, continuing "the drag …": "did not converge (residual
// 1.4e-04), folded over in 2 places", or "ended without a problem".
std::string describeOutcome(const solver::DragOutcome& outcome);
// Why a drag's release was taken back (SurfaceAssessment::takenBack, the refused result's
// assessment): "did not reach the tolerance (residual 8.8e-02; patch 7 sampled 3.1e-02 from
// developable), folded over in 38 places and left a development overlapping itself at 18
// patches".
std::string describeTakenBack(const solver::SurfaceAssessment& refused);
// Why a crease cannot be dragged: "edge 3 is not a crease (…); only creases can be dragged."
std::string describeCreaseRefusal(const solver::CreaseDragRefused& refused);
// "flatness mean … max …, |K| mean … max …, det mean … max …"
std::string describeQuality(const solver::QualityMeasures& quality);
// Why a job failed: "surface 1 could not be solved: FactorizationFailed (…)".
std::string describeFailure(const solver::JobFailure& failure);
// What the iterate a solve refused would have broken: ", before the next iteration broke it:
// Patch 3 has zero area." or "" when nothing was refused.
std::string refusedText(const solver::SurfaceAssessment& assessment);

} // namespace devsurf::app
