#pragma once

// The readers behind readReferenceShape, one per kind of file, and what they share.

#include "reference_import.h"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace devsurf::io::reference {

ReferenceImportResult failure(ReferenceImportError::Code code, std::string detail = {});

// The error a file check found, as the checks return it (none: the file is sound so far).
inline std::optional<ReferenceImportError> importProblem(ReferenceImportError::Code code,
                                                         std::string detail = {}) {
    return ReferenceImportError{code, std::move(detail)};
}

// A coordinate DevSurf can draw and measure: finite and within kMaxReferenceCoordinate.
bool isSane(const model::Vec3& p);

// Calls the progress callback at most about a hundred times per file; false once it said stop.
class ProgressTicker {
public:
    ProgressTicker(const ReferenceProgress& progress, double from, double to)
        : m_progress(progress), m_from(from), m_to(to) {}
    // fraction of this stage, 0 … 1
    bool at(double fraction);
    bool cancelled() const { return m_cancelled; }

private:
    const ReferenceProgress& m_progress;
    double m_from;
    double m_to;
    double m_last = -1.0;
    bool m_cancelled = false;
};

// XYZ and PTS, parsed here.
ReferenceImportResult readPointCloud(const std::string& path, ReferenceFormat format,
                                     std::uint64_t size, ProgressTicker& progress);

// OFF, parsed here.
ReferenceImportResult readOffFile(const std::string& path, std::uint64_t size,
                                  ProgressTicker& progress);

// OBJ, PLY and STL: checked here for what OpenMesh's readers trust (counts, indices, lengths,
// a header they can parse), then read by OpenMesh.
struct MeshCheck {
    std::optional<ReferenceImportError> error;
    std::uint64_t points = 0;         // as many as OpenMesh must read; 0 where it merges them (STL)
    std::vector<model::Vec3> normals; // OBJ: one per point where the faces name one for each
};
MeshCheck checkMeshFile(const std::string& path, ReferenceFormat format, std::uint64_t size,
                        ProgressTicker& progress);
// The PLY part of checkMeshFile (ply_check.cpp); pointCount: the vertices OpenMesh must read.
std::optional<ReferenceImportError> checkPly(const std::string& path, std::uint64_t size,
                                             ProgressTicker& progress, std::uint64_t& pointCount);
// pointNormals: whether OpenMesh's normals per point are the file's (PLY's are; STL gives one
// per facet, OBJ's come from the check).
ReferenceImportResult readMeshFile(const std::string& path, std::uint64_t expectedPoints,
                                   bool pointNormals);

} // namespace devsurf::io::reference
