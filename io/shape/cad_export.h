#pragma once

// STEP (AP214, AP242) and IGES of a design's exact surfaces through OpenCASCADE: one B-spline
// face per patch (a plane bounded by its polygon for a planar patch), each surface's faces sewn
// into one shell where the patches meet, units mm, faces named after their patches and creases
// named by their fold (mountain, valley) where the format keeps names of edges.

#include "model/ids.h"
#include "model/project.h"
#include "shape_export_error.h"

#include <QString>

#include <cstddef>
#include <functional>
#include <vector>

namespace devsurf::io {

enum class CadFormat { StepAP214, StepAP242, Iges };

// Returns false to cancel; given the fraction done (0 … 1).
using ExportProgress = std::function<bool(double fraction)>;

struct CadExportOptions {
    CadFormat format = CadFormat::StepAP242;
    // Patches closer than this (mm) along a shared edge are sewn; 0: 1e-6 of the diameter.
    double sewingTolerance = 0.0;
    ExportProgress progress; // may be empty
};

// A seam of the design (an edge shared by two patches) that sewing left open: the two faces
// stay apart there in the file. gap: the largest distance found between the two sides (mm).
struct UnsewnEdge {
    model::SurfaceId surface = 0;
    model::EdgeId edge = model::kInvalidId;
    double gap = 0.0;
};

struct CadExportSurface {
    model::SurfaceId surface = 0;
    std::size_t faces = 0;
    bool closedDesign = false; // every edge of the design is shared by two patches
    bool closedShell = false;  // what was written is one closed shell
    std::size_t shells = 0;    // shells written (1 where sewing joined every patch)
    std::vector<UnsewnEdge> unsewn;
    std::size_t namedCreases = 0; // mountain and valley edges named
};

struct CadExportResult {
    std::vector<CadExportSurface> surfaces;
    double sewingTolerance = 0.0;
    std::size_t faces() const;
    bool sewn() const; // no seam left open
};

// Writes the project's surfaces to `path` (atomically). Throws ModelError for an invalid
// surface, ShapeExportError, or FileError where the file cannot be written.
CadExportResult saveCadFile(const model::Project& project, const QString& path,
                            const CadExportOptions& options);

// "step", "step214", "step242", "stp", "iges", "igs" → the format (STEP alone is AP242).
bool cadFormatFromName(const std::string& name, CadFormat& format);

} // namespace devsurf::io
