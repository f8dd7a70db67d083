// The picking side of a SceneRenderer: which vertex, edge or patch lies under a display point,
// and where the ray through it meets the surface.

#include "scene_renderer.h"

#include <vtkCamera.h>
#include <vtkCellPicker.h>
#include <vtkRenderer.h>
#include <vtkStaticCellLocator.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace devsurf::views {

using document::Pick;
using model::Vec3;

namespace {

double distanceToSegment(double px, double py, const Vec3& a, const Vec3& b, double* t) {
    const double ux = b.x - a.x;
    const double uy = b.y - a.y;
    const double len2 = ux * ux + uy * uy;
    double s = len2 > 0.0 ? ((px - a.x) * ux + (py - a.y) * uy) / len2 : 0.0;
    s = std::clamp(s, 0.0, 1.0);
    *t = s;
    return std::hypot(a.x + s * ux - px, a.y + s * uy - py);
}

} // namespace

const Vec3* SceneRenderer::vertexPosition(int surface, model::VertexId vertex) const {
    for (const SurfaceScene& scene : m_set->scenes) {
        if (scene.surface == surface) {
            auto it = scene.vertices.find(vertex);
            return it == scene.vertices.end() ? nullptr : &it->second;
        }
    }
    return nullptr;
}

std::optional<Vec3> SceneRenderer::surfaceHit(double displayX, double displayY,
                                              std::optional<Pick>* face) const {
    if (m_cellFace.empty()) {
        return std::nullopt;
    }
    if (m_locatorStale) {
        m_locator->Modified();
        m_locator->BuildLocator();
        m_locatorStale = false;
    }
    if (m_picker->Pick(displayX, displayY, 0.0, m_renderer) == 0) {
        return std::nullopt;
    }
    const vtkIdType cell = m_picker->GetCellId();
    if (cell < 0 || cell >= static_cast<vtkIdType>(m_cellFace.size())) {
        return std::nullopt;
    }
    const auto& [surface, id] = m_cellFace[static_cast<std::size_t>(cell)];
    *face = Pick{Pick::Kind::Face, surface, id};
    const double* p = m_picker->GetPickPosition();
    return Vec3(p[0], p[1], p[2]);
}

std::optional<Pick> SceneRenderer::faceAt(double displayX, double displayY) const {
    std::optional<Pick> face;
    surfaceHit(displayX, displayY, &face);
    return face;
}

std::optional<Pick> SceneRenderer::pick(double displayX, double displayY, double radius) const {
    std::optional<Pick> face;
    const std::optional<Vec3> hit = surfaceHit(displayX, displayY, &face);

    // In 3D, something farther from the eye than the surface under the cursor is hidden.
    const bool spatial = m_mode == Mode::Spatial;
    double eye[3];
    m_renderer->GetActiveCamera()->GetPosition(eye);
    const Vec3 eyePoint(eye[0], eye[1], eye[2]);
    const double hitDistance =
        hit ? distance(eyePoint, *hit) : std::numeric_limits<double>::infinity();
    const double slack = 0.01 * m_sceneSize;
    auto hidden = [&](const Vec3& p) {
        return spatial && hit && distance(eyePoint, p) > hitDistance + slack;
    };

    std::optional<Pick> best;
    double bestDistance = radius;
    for (const SurfaceScene& scene : m_set->scenes) {
        for (const auto& [id, position] : scene.vertices) {
            const Vec3 d = toDisplay(position);
            const double dist = std::hypot(d.x - displayX, d.y - displayY);
            if (dist <= bestDistance && !hidden(position)) {
                bestDistance = dist;
                best = Pick{Pick::Kind::Vertex, scene.surface, id};
            }
        }
    }
    if (best) {
        return best;
    }

    bestDistance = 0.6 * radius;
    for (const SurfaceScene& scene : m_set->scenes) {
        for (const EdgeCurve& edge : scene.edges) {
            std::vector<Vec3> display;
            display.reserve(edge.points.size());
            for (const Vec3& p : edge.points) {
                display.push_back(toDisplay(p));
            }
            for (std::size_t i = 0; i + 1 < display.size(); ++i) {
                double t = 0.0;
                const double dist =
                    distanceToSegment(displayX, displayY, display[i], display[i + 1], &t);
                if (dist <= bestDistance) {
                    const Vec3 world = edge.points[i] * (1.0 - t) + edge.points[i + 1] * t;
                    if (!hidden(world)) {
                        bestDistance = dist;
                        best = Pick{Pick::Kind::Edge, scene.surface, edge.id};
                    }
                }
            }
        }
    }
    if (best) {
        return best;
    }
    return face;
}

} // namespace devsurf::views
