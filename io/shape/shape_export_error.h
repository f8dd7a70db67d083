#pragma once

#include "model/ids.h"

#include <stdexcept>

namespace devsurf::io {

// Why an export of the 3D shape stopped. The front ends word it.
class ShapeExportError : public std::runtime_error {
public:
    enum class Code {
        NoSurface,  // the project has no surface
        BadSurface, // OpenCASCADE refused a patch's surface (surface, face say which)
        Translate,  // the format's writer refused the shape
        Cancelled
    };
    explicit ShapeExportError(Code code, model::SurfaceId surface = 0,
                              model::FaceId face = model::kInvalidId)
        : std::runtime_error("shape export"), m_code(code), m_surface(surface), m_face(face) {}
    Code code() const { return m_code; }
    model::SurfaceId surface() const { return m_surface; }
    model::FaceId face() const { return m_face; }

private:
    Code m_code;
    model::SurfaceId m_surface;
    model::FaceId m_face;
};

} // namespace devsurf::io
