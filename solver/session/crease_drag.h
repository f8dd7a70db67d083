#pragma once

#include "model/composite_surface.h"
#include "solver/formulation/surface_formulation.h"

#include <stdexcept>
#include <vector>

namespace devsurf::solver {

// Why a crease cannot be dragged (CreaseDrag's constructor throws CreaseDragRefused).
enum class CreaseDragRefusal {
    NoSuchEdge,
    NotACrease, // a ruling or a boundary curve: only curves between two patches slide
    Immovable,  // both ends pinned and no interior control point
};

class CreaseDragRefused : public std::invalid_argument {
public:
    CreaseDragRefused(CreaseDragRefusal reason, model::EdgeId edge);
    CreaseDragRefusal reason() const { return m_reason; }
    model::EdgeId edge() const { return m_edge; }

private:
    CreaseDragRefusal m_reason;
    model::EdgeId m_edge;
};

// A crease being dragged across its two strips (paper §4.1): its interior control points and
// its unpinned end vertices are pulled as handles, so the crease slides within the strips and
// changes their sizes while the solver keeps the surface developable. The command line's
// `drag --crease` and the desktop application's Drag tool both use it, with
// creaseDragSessionOptions.
//
// Sliding, every point moves along the ruling through it of the strip the crease moves away
// from, by the motion's component along that ruling: that strip grows along its own rulings, so
// it stays what it was, and the crease stays on its extension. (Moving every point by the same
// vector asked for a crease its strips could not follow: measured with creaseDragSessionOptions
// on fig6 folded 15°, its crease slid 15 mm, residual 6.0e-8 with the fold relaxed to 13.4°,
// against 1.2e-12 and 15.3° along the rulings; on the lifted fig8, five slides, 3.0e-8 … 4.8e-7
// against 2.4e-8 … 2.2e-7.) Where a side of the crease is not a strip or a cone (a planar face),
// every point moves by the motion.
//
// Sliding stops before the strip the crease moves into is narrower than 0.3 of its width
// anywhere (kCreaseSlideRoom): further, the crease crossed that strip's far curve and turned it
// inside out (fig6's crease slid 120 mm across its 100 mm strip: folded 180° onto itself).
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
    // of delta along normal() is removed first and the points move along the rulings (see
    // above) as far as the strip they move into allows (reach()), so the crease moves within
    // the surface; without it (an axis the designer chose), every point moves by delta.
    std::vector<VertexHandle> vertexHandles(const model::Vec3& delta, bool slide) const;
    std::vector<ControlPointHandle> controlPointHandles(const model::Vec3& delta, bool slide) const;
    // The motion the crease follows for `delta`: delta without its component along normal()
    // when sliding, else delta.
    model::Vec3 displacement(const model::Vec3& delta, bool slide) const;
    // The displacements of the control points 0 … n − 1 (the ends included) for `delta`.
    std::vector<model::Vec3> pointDisplacements(const model::Vec3& delta, bool slide) const;
    // The fraction of the slide for `delta` that the points make: 1, or less where the strip
    // the crease moves into would become narrower than kCreaseSlideRoom of its width.
    double reach(const model::Vec3& delta, bool slide) const;

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
    std::vector<std::size_t> m_vertexIndex; // per moving end: its control point index
    // Per face of the crease (facesOfEdge order) and control point: the unit direction of the
    // face's ruling through the point, from the face towards the crease (empty if the face is
    // not a strip or a cone).
    std::vector<model::Vec3> m_rulings[2];
    std::vector<double> m_rulingLengths[2]; // the lengths of those rulings

    // The face the crease moves away from for the slide d (0 or 1), and the unclamped
    // displacement of point i along its ruling.
    std::size_t leftFace(const model::Vec3& d) const;
    double along(std::size_t face, std::size_t i, const model::Vec3& d) const;
};

// The narrowest the strip a sliding crease moves into may become, as a fraction of its width
// at the press (CreaseDrag::reach).
constexpr double kCreaseSlideRoom = 0.3;

} // namespace devsurf::solver
