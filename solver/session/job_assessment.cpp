#include "solver/session/job_assessment.h"

#include "model/derived_geometry.h"
#include "model/development.h"
#include "model/pattern/cutting_pattern.h"
#include "solver/quality/quality_measures.h"
#include "solver/quality/shape_change.h"
#include "solver/quality/vertex_stars.h"
#include "solver/session/verdict.h"

#include <algorithm>
#include <exception>
#include <iterator>
#include <limits>

namespace devsurf::solver {

void measureHandleGaps(SurfaceAssessment& assessment, const model::CompositeSurface& surface,
                       const std::vector<VertexHandle>& handles,
                       const std::vector<ControlPointHandle>& points) {
    for (const VertexHandle& handle : handles) {
        if (!surface.hasVertex(handle.vertex) || surface.isPinned(handle.vertex)) {
            continue;
        }
        assessment.handleGaps.push_back({handle.vertex, model::kInvalidId, -1,
                                         (surface.position(handle.vertex) - handle.target).norm()});
    }
    for (const ControlPointHandle& point : points) {
        if (!surface.hasEdge(point.edge)) {
            continue;
        }
        const auto& controlPoints = surface.edge(point.edge).controlPoints;
        if (point.index < 0 || static_cast<std::size_t>(point.index) >= controlPoints.size()) {
            continue;
        }
        assessment.handleGaps.push_back(
            {model::kInvalidId, point.edge, point.index,
             (controlPoints[static_cast<std::size_t>(point.index)] - point.target).norm()});
    }
    for (const HandleGap& gap : assessment.handleGaps) {
        assessment.largestHandleGap = std::max(assessment.largestHandleGap, gap.distance);
    }
}

std::optional<model::Vec2> sheetPlace(const model::CompositeSurface& surface,
                                      model::VertexId vertex) {
    // The sampled mesh, and so the development, lists the coarse vertices first in id order.
    const std::vector<model::Vec2>& flat = surface.development();
    const auto& vertices = surface.vertices();
    const auto it = vertices.find(vertex);
    const auto index = static_cast<std::size_t>(std::distance(vertices.begin(), it));
    if (it == vertices.end() || index >= flat.size()) {
        return std::nullopt;
    }
    return flat[index];
}

void measureSheetGaps(SurfaceAssessment& assessment, const model::CompositeSurface& surface,
                      const std::vector<SheetHandle>& sheet) {
    for (const SheetHandle& handle : sheet) {
        const std::optional<model::Vec2> place = sheetPlace(surface, handle.vertex);
        if (!place) {
            continue;
        }
        const double gap = (*place - handle.target).norm();
        assessment.handleGaps.push_back({handle.vertex, model::kInvalidId, -1, gap});
        assessment.largestHandleGap = std::max(assessment.largestHandleGap, gap);
    }
}

void measureIsometry(SurfaceAssessment& assessment, const model::CompositeSurface& result) {
    const auto derived = model::DerivedGeometry::of(result, kVerdictSamples);
    const model::Development& development = derived->development();
    double minX = std::numeric_limits<double>::infinity();
    double minY = minX;
    double maxX = -minX;
    double maxY = -minX;
    for (const model::Vec2& p : development.vertices) {
        minX = std::min(minX, p.x);
        minY = std::min(minY, p.y);
        maxX = std::max(maxX, p.x);
        maxY = std::max(maxY, p.y);
    }
    if (development.vertices.empty()) {
        return;
    }
    assessment.sheetExtent = std::max(maxX - minX, maxY - minY);
    assessment.edgeLengthError = development.maxEdgeLengthError;
    assessment.isometryMm =
        std::max(development.maxEdgeLengthError * assessment.sheetExtent, development.closureError);
    // A closed surface that unfolds into no one sheet (a torus) is measured on the pieces of its
    // cutting pattern instead: how far each piece is from isometric, relative to the largest.
    // So is a held sheet around a hole whose curves, sampled this finely, close up less well
    // than at the sampling the sheet is kept at (a folded annulus: its pattern is cut from the
    // kept sheet, model::pattern::layOntoKeptSheet).
    const auto& edges = result.edges();
    const bool closed = std::all_of(edges.begin(), edges.end(), [&result](const auto& edge) {
        return result.facesOfEdge(edge.first).size() == 2;
    });
    const bool heldFlat =
        result.keepsDevelopment() && result.sheetDomain().shape != model::SheetShape::Cylinder;
    if (development.closureError > model::kOneSheetClosure && !development.period &&
        (closed || heldFlat)) {
        model::PatternOptions options;
        options.layout = false;
        options.samplesPerInterval = kVerdictSamples;
        int names = 0;
        double extent = 0.0;
        double isometry = 0.0;
        for (const model::PatternPiece& piece :
             model::developSurfacePieces(result, 0, options, names)) {
            isometry = std::max(isometry, piece.maxIsometryError);
            double low[2] = {std::numeric_limits<double>::infinity(),
                             std::numeric_limits<double>::infinity()};
            double high[2] = {-low[0], -low[1]};
            for (const model::Vec2& p : piece.mesh.vertices) {
                low[0] = std::min(low[0], p.x);
                low[1] = std::min(low[1], p.y);
                high[0] = std::max(high[0], p.x);
                high[1] = std::max(high[1], p.y);
            }
            extent = std::max({extent, high[0] - low[0], high[1] - low[1]});
        }
        if (heldFlat) {
            // The pattern is laid onto the kept sheet: off by as much as the surface is.
            isometry = std::max(isometry, assessment.sheetStretchMm);
        }
        if (extent > 0.0) {
            assessment.sheetExtent = extent;
            assessment.isometryMm = isometry;
            assessment.edgeLengthError = isometry / extent;
        }
    }
}

void measureSettled(SurfaceAssessment& assessment, const model::CompositeSurface& result,
                    const model::CompositeSurface* press,
                    const std::optional<std::vector<model::FaceId>>& knownOverlaps) {
    assessment.measured = true;
    try {
        if (press) {
            const ShapeChange change = measureShapeChange(*press, result);
            assessment.foldOvers = change.foldOvers;
            assessment.shortestRuling = change.shortestRuling;
            assessment.slowestSpeed = change.slowestSpeed;
        } else {
            assessment.foldOvers = foldOvers(result);
        }
    } catch (const std::exception&) {
        // Too degenerate to sample: the worst faces below say where.
    }
    if (knownOverlaps) {
        assessment.overlapping = *knownOverlaps;
    } else if (!assessment.summary.iterations.empty()) {
        assessment.overlapping = model::selfOverlappingPatches(result);
    }
    try {
        assessment.creases = measureCreaseQuality(result);
    } catch (const std::exception&) {
    }
    try {
        const auto defects = vertexAngleDefects(result);
        assessment.vertexStars = static_cast<int>(defects.size());
        for (const VertexAngleDefect& d : defects) {
            assessment.largestVertexDefect = std::max(assessment.largestVertexDefect, d.defect);
        }
    } catch (const std::exception&) {
    }
    try {
        assessment.sheetStretchMm = model::keptSheetStretch(result); // measureIsometry's too
        measureIsometry(assessment, result);
    } catch (const std::exception&) {
        // Too degenerate to sample: left unmeasured.
    }
    if (!assessment.summary.toleranceReached) {
        auto faces = developabilityByFace(result);
        if (faces.size() > kWorstFaces) {
            faces.resize(kWorstFaces);
        }
        assessment.worstFaces = std::move(faces);
    }
}

// Whether a drag's release or an Edit must not end so: broken, or, on a surface that holds its
// sheet, not developable as the verdict judges it (the sheet is a constraint: a result that
// does not unfold onto it within kDragConvergedResidual cannot be cut from it).
bool refusable(const SurfaceAssessment& a) {
    return broken(a) || (a.sheetHeld && notDevelopable(a));
}

// A drag's press measured as a settled result, for the comparison with the release. Its
// "residual" is its largest sampled developability residual (normalised, worstDevelopability):
// the drag's session does not evaluate the press's constraints without its handles.
SurfaceAssessment assessPress(const model::CompositeSurface& press, const Summary& dragSummary) {
    const double residual = worstDevelopability(press);
    SurfaceAssessment assessment;
    assessment.solved = true;
    assessment.sheetHeld = press.keepsDevelopment();
    Summary& summary = assessment.summary;
    summary.tolerance = dragSummary.tolerance;
    summary.initialMaxConstraintResidual = residual;
    summary.finalMaxConstraintResidual = residual;
    summary.toleranceReached = residual <= dragSummary.tolerance;
    summary.variables = dragSummary.variables;
    summary.rows = dragSummary.rows;
    std::vector<model::FaceId> overlapping;
    try {
        overlapping = model::selfOverlappingPatches(press);
    } catch (const std::exception&) {
    }
    measureSettled(assessment, press, nullptr, overlapping);
    return assessment;
}

} // namespace devsurf::solver
