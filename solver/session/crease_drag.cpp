#include "solver/session/crease_drag.h"

#include <stdexcept>
#include <string>

namespace devsurf::solver {

using model::Vec3;

namespace {

Vec3 unit(const Vec3& v) {
    const double length = v.norm();
    return length > 0.0 ? v / length : Vec3{};
}

Vec3 faceCentroid(const model::CompositeSurface& surface, model::FaceId face) {
    Vec3 sum;
    const std::vector<model::VertexId>& loop = surface.faceLoop(face);
    for (model::VertexId v : loop) {
        sum += surface.position(v);
    }
    return loop.empty() ? sum : sum / static_cast<double>(loop.size());
}

} // namespace

CreaseDrag::CreaseDrag(const model::CompositeSurface& surface, model::EdgeId edge) : m_edge(edge) {
    const std::string name = "edge " + std::to_string(edge);
    if (!surface.hasEdge(edge)) {
        throw std::invalid_argument("there is no " + name + ".");
    }
    const model::EdgeRecord& record = surface.edge(edge);
    const std::vector<model::FaceId> faces = surface.facesOfEdge(edge);
    if (!record.isSpline() || faces.size() != 2) {
        throw std::invalid_argument(name + " is not a crease (a curve between two patches); only "
                                           "creases can be dragged.");
    }
    for (model::VertexId v : {record.from, record.to}) {
        if (!surface.isPinned(v)) {
            m_vertices.push_back(v);
            m_vertexStart.push_back(surface.position(v));
        }
    }
    for (std::size_t i = 1; i + 1 < record.controlPoints.size(); ++i) {
        m_controlStart.push_back(record.controlPoints[i]);
    }
    if (m_vertices.empty() && m_controlStart.empty()) {
        throw std::invalid_argument(name + " cannot move: both its ends are pinned and it has no "
                                           "other control point.");
    }
    // Each face's normal at the crease from the chord and the direction into the face; both
    // oriented alike (a fold turns them by less than half a turn).
    const Vec3 chord = unit(record.controlPoints.back() - record.controlPoints.front());
    const Vec3 middle = (record.controlPoints.back() + record.controlPoints.front()) * 0.5;
    const Vec3 first = unit(cross(chord, faceCentroid(surface, faces[0]) - middle));
    Vec3 second = unit(cross(chord, faceCentroid(surface, faces[1]) - middle));
    if (dot(first, second) < 0.0) {
        second = -second;
    }
    m_normal = unit(first + second);
    if (m_normal.norm() == 0.0) {
        m_normal = first;
    }
}

Vec3 CreaseDrag::displacement(const Vec3& delta, bool slide) const {
    return slide ? delta - m_normal * dot(delta, m_normal) : delta;
}

std::vector<VertexHandle> CreaseDrag::vertexHandles(const Vec3& delta, bool slide) const {
    const Vec3 d = displacement(delta, slide);
    std::vector<VertexHandle> handles;
    for (std::size_t i = 0; i < m_vertices.size(); ++i) {
        handles.push_back({m_vertices[i], false, m_vertexStart[i] + d});
    }
    return handles;
}

std::vector<ControlPointHandle> CreaseDrag::controlPointHandles(const Vec3& delta,
                                                                bool slide) const {
    const Vec3 d = displacement(delta, slide);
    std::vector<ControlPointHandle> handles;
    for (std::size_t i = 0; i < m_controlStart.size(); ++i) {
        handles.push_back({m_edge, static_cast<int>(i) + 1, m_controlStart[i] + d});
    }
    return handles;
}

} // namespace devsurf::solver
