#pragma once

// What a solve job measures on its results (SurfaceAssessment): how far the handles ended from
// their targets and, once settled, the geometry the verdict judges. Used by SolveJob only.

#include "model/composite_surface.h"
#include "solver/session/solve_job.h"

#include <optional>
#include <vector>

namespace devsurf::solver {

// How far each pulled vertex and control point ended from its target (model units).
void measureHandleGaps(SurfaceAssessment& assessment, const model::CompositeSurface& surface,
                       const std::vector<VertexHandle>& handles,
                       const std::vector<ControlPointHandle>& points);

// Where `vertex` lies in the surface's kept development (mm); nothing without one.
std::optional<model::Vec2> sheetPlace(const model::CompositeSurface& surface,
                                      model::VertexId vertex);

// How far each vertex dragged in the held sheet lies from its target there (mm).
void measureSheetGaps(SurfaceAssessment& assessment, const model::CompositeSurface& surface,
                      const std::vector<SheetHandle>& sheet);

// How far the sheet is from isometric to its development (SurfaceAssessment::isometryMm); a
// held sheet by no less than assessment.sheetStretchMm, measured before.
void measureIsometry(SurfaceAssessment& assessment, const model::CompositeSurface& result);

// The geometry of a settled result: fold-overs, overlaps, creases, vertex stars, worst faces.
// `press` is the drag's surface at the press (null for Solve and Edit); `knownOverlaps` those a
// judged drag found already.
void measureSettled(SurfaceAssessment& assessment, const model::CompositeSurface& result,
                    const model::CompositeSurface* press,
                    const std::optional<std::vector<model::FaceId>>& knownOverlaps);

// Whether a drag's release or an Edit must not end so: broken, or, on a surface that holds its
// sheet, not developable as the verdict judges it.
bool refusable(const SurfaceAssessment& a);

// A drag's press measured as a settled result, for the comparison with the release.
SurfaceAssessment assessPress(const model::CompositeSurface& press, const Summary& dragSummary);

} // namespace devsurf::solver
