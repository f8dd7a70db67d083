#include "solver/session/crease_drag.h"

#include "model/model_error.h"
#include "model/strip.h"

#include <algorithm>
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

// The ruling of `strip` nearest p (the line through a(u) and b(u) closest to p), pointing from
// the strip's other side towards the crease (its side a if creaseIsA), as a vector.
Vec3 rulingThrough(const model::Strip& strip, bool creaseIsA, const Vec3& p) {
    auto distance = [&](double u) {
        const Vec3 a = strip.aPoint(u);
        const Vec3 r = strip.bPoint(u) - a;
        const double length2 = dot(r, r);
        const double t = length2 > 0.0 ? dot(p - a, r) / length2 : 0.0;
        return (a + r * t - p).norm();
    };
    // Coarse samples, then a ternary search around the nearest.
    constexpr int kSamples = 256;
    const double begin = strip.a.domainBegin();
    const double end = strip.a.domainEnd();
    const double h = (end - begin) / kSamples;
    double best = begin;
    double bestDistance = distance(begin);
    for (int i = 1; i <= kSamples; ++i) {
        const double u = begin + h * i;
        const double d = distance(u);
        if (d < bestDistance) {
            best = u;
            bestDistance = d;
        }
    }
    double low = std::max(begin, best - h);
    double high = std::min(end, best + h);
    for (int i = 0; i < 60; ++i) {
        const double m1 = low + (high - low) / 3.0;
        const double m2 = high - (high - low) / 3.0;
        if (distance(m1) < distance(m2)) {
            high = m2;
        } else {
            low = m1;
        }
    }
    const double u = 0.5 * (low + high);
    const Vec3 r = strip.bPoint(u) - strip.aPoint(u); // from a towards b
    return creaseIsA ? -r : r;
}

} // namespace

CreaseDragRefused::CreaseDragRefused(CreaseDragRefusal reason, model::EdgeId edge)
    : std::invalid_argument("crease drag refused for edge " + std::to_string(edge)),
      m_reason(reason), m_edge(edge) {}

CreaseDrag::CreaseDrag(const model::CompositeSurface& surface, model::EdgeId edge) : m_edge(edge) {
    if (!surface.hasEdge(edge)) {
        throw CreaseDragRefused(CreaseDragRefusal::NoSuchEdge, edge);
    }
    const model::EdgeRecord& record = surface.edge(edge);
    const std::vector<model::FaceId> faces = surface.facesOfEdge(edge);
    if (!record.isSpline() || faces.size() != 2) {
        throw CreaseDragRefused(CreaseDragRefusal::NotACrease, edge);
    }
    for (model::VertexId v : {record.from, record.to}) {
        if (!surface.isPinned(v)) {
            m_vertices.push_back(v);
            m_vertexStart.push_back(surface.position(v));
            m_vertexIndex.push_back(v == record.from ? 0 : record.controlPoints.size() - 1);
        }
    }
    for (std::size_t i = 1; i + 1 < record.controlPoints.size(); ++i) {
        m_controlStart.push_back(record.controlPoints[i]);
    }
    if (m_vertices.empty() && m_controlStart.empty()) {
        throw CreaseDragRefused(CreaseDragRefusal::Immovable, edge);
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
    for (std::size_t k = 0; k < 2; ++k) {
        try {
            const model::Strip strip = model::stripOfFace(surface, faces[k]);
            const bool creaseIsA = strip.aSide.edge == edge;
            for (const Vec3& p : record.controlPoints) {
                const Vec3 ruling = rulingThrough(strip, creaseIsA, p);
                m_rulings[k].push_back(unit(ruling));
                m_rulingLengths[k].push_back(ruling.norm());
            }
        } catch (const model::ModelError&) {
            m_rulings[k].clear(); // a planar face: no rulings
            m_rulingLengths[k].clear();
        }
    }
}

Vec3 CreaseDrag::displacement(const Vec3& delta, bool slide) const {
    return slide ? delta - m_normal * dot(delta, m_normal) : delta;
}

std::size_t CreaseDrag::leftFace(const Vec3& d) const {
    // The face whose rulings point most along d.
    double sum[2] = {0.0, 0.0};
    for (std::size_t k = 0; k < 2; ++k) {
        for (const Vec3& r : m_rulings[k]) {
            sum[k] += dot(r, d);
        }
    }
    return sum[1] > sum[0] ? 1 : 0;
}

double CreaseDrag::along(std::size_t face, std::size_t i, const Vec3& d) const {
    // A point whose ruling leans back against the motion stays (the crease does not move into
    // the face it leaves).
    return std::max(0.0, dot(m_rulings[face][i], d));
}

double CreaseDrag::reach(const Vec3& delta, bool slide) const {
    const Vec3 d = displacement(delta, slide);
    if (!slide || m_rulings[0].empty() || m_rulings[1].empty()) {
        return 1.0;
    }
    const std::size_t left = leftFace(d);
    const std::size_t into = 1 - left;
    double reach = 1.0;
    for (std::size_t i = 0; i < m_rulings[left].size(); ++i) {
        // How far the point moves across the strip it moves into, along that strip's ruling.
        const double across = along(left, i, d) * -dot(m_rulings[left][i], m_rulings[into][i]);
        const double room = (1.0 - kCreaseSlideRoom) * m_rulingLengths[into][i];
        if (across > room) {
            reach = std::min(reach, room / across);
        }
    }
    return reach;
}

std::vector<Vec3> CreaseDrag::pointDisplacements(const Vec3& delta, bool slide) const {
    const Vec3 d = displacement(delta, slide);
    const std::size_t count = m_controlStart.size() + 2;
    if (!slide || m_rulings[0].empty() || m_rulings[1].empty()) {
        return std::vector<Vec3>(count, d);
    }
    const std::size_t left = leftFace(d);
    const double scale = reach(delta, slide);
    std::vector<Vec3> displacements;
    for (std::size_t i = 0; i < count; ++i) {
        displacements.push_back(m_rulings[left][i] * (along(left, i, d) * scale));
    }
    return displacements;
}

std::vector<VertexHandle> CreaseDrag::vertexHandles(const Vec3& delta, bool slide) const {
    const std::vector<Vec3> displacements = pointDisplacements(delta, slide);
    std::vector<VertexHandle> handles;
    for (std::size_t i = 0; i < m_vertices.size(); ++i) {
        handles.push_back(
            {m_vertices[i], false, m_vertexStart[i] + displacements[m_vertexIndex[i]]});
    }
    return handles;
}

std::vector<ControlPointHandle> CreaseDrag::controlPointHandles(const Vec3& delta,
                                                                bool slide) const {
    const std::vector<Vec3> displacements = pointDisplacements(delta, slide);
    std::vector<ControlPointHandle> handles;
    for (std::size_t i = 0; i < m_controlStart.size(); ++i) {
        handles.push_back(
            {m_edge, static_cast<int>(i) + 1, m_controlStart[i] + displacements[i + 1]});
    }
    return handles;
}

} // namespace devsurf::solver
