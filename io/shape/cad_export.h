#pragma once

// STEP (AP214, AP242) and IGES of a design's exact surfaces through OpenCASCADE: one B-spline
// face per patch (a plane bounded by its polygon for a planar patch), each surface's faces sewn
// into one shell where the patches meet, units mm, faces named after their patches and creases
// named by their fold (mountain, valley) where the format keeps names of edges.

#include "model/ids.h"
#include "model/project.h"

#include <QString>

#include <cstddef>
#include <functional>
#include <stdexcept>
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

// Why an export stopped. The front ends word it.
class CadExportError : public std::runtime_error {
public:
    enum class Code {
        NoSurface,  // the project has no surface
        BadSurface, // OpenCASCADE refused a patch's surface (surface, face say which)
        Translate,  // the writer refused the shape
        Cancelled
    };
    CadExportError(Code code, model::SurfaceId surface = 0, model::FaceId face = model::kInvalidId)
        : std::runtime_error("cad export"), m_code(code), m_surface(surface), m_face(face) {}
    Code code() const { return m_code; }
    model::SurfaceId surface() const { return m_surface; }
    model::FaceId face() const { return m_face; }

private:
    Code m_code;
    model::SurfaceId m_surface;
    model::FaceId m_face;
};

// Writes the project's surfaces to `path` (atomically). Throws ModelError for an invalid
// surface, CadExportError, or FileError where the file cannot be written.
CadExportResult saveCadFile(const model::Project& project, const QString& path,
                            const CadExportOptions& options);

// "step", "step214", "step242", "stp", "iges", "igs" → the format (STEP alone is AP242).
bool cadFormatFromName(const std::string& name, CadFormat& format);

} // namespace devsurf::io
