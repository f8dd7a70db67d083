#pragma once

#include "model/composite_surface.h"
#include "solver/formulation/surface_formulation.h"

#include <vector>

namespace devsurf::solver {

// A crease being dragged across its two strips (paper §4.1): its interior control points and
// its unpinned end vertices are pulled as handles by one displacement, so the crease slides
// within the strips and changes their sizes while the solver keeps the surface developable.
// The command line's `drag --crease` and the desktop application's Drag tool both use it.
class CreaseDrag {
public:
    // Throws std::invalid_argument with a sentence if `edge` is not a crease of `surface` (an
    // S-edge shared by two faces) or has nothing that may move (every point pinned).
    CreaseDrag(const model::CompositeSurface& surface, model::EdgeId edge);

    model::EdgeId edge() const { return m_edge; }
    // The unit normal of the surface along the crease: the mean of its two faces' normals
    // there (the bisector of a folded crease).
    const model::Vec3& normal() const { return m_normal; }

    // The handles for the crease moved by `delta` (model units). With `slide`, the component
    // of delta along normal() is removed first, so the crease moves within the surface; without
    // it (an axis the designer chose), delta is used as it is.
    std::vector<VertexHandle> vertexHandles(const model::Vec3& delta, bool slide) const;
    std::vector<ControlPointHandle> controlPointHandles(const model::Vec3& delta, bool slide) const;
    // The displacement the handles get for `delta`.
    model::Vec3 displacement(const model::Vec3& delta, bool slide) const;

    // The end vertices that move (unpinned), and the positions at the start.
    const std::vector<model::VertexId>& vertices() const { return m_vertices; }
    const std::vector<model::Vec3>& vertexStart() const { return m_vertexStart; }
    // The interior control points' positions at the start (indices 1 … n − 2).
    const std::vector<model::Vec3>& controlPointStart() const { return m_controlStart; }

private:
    model::EdgeId m_edge = model::kInvalidId;
    model::Vec3 m_normal;
    std::vector<model::VertexId> m_vertices;
    std::vector<model::Vec3> m_vertexStart;
    std::vector<model::Vec3> m_controlStart;
};

} // namespace devsurf::solver
