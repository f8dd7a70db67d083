#include "scene_renderer.h"

#include <vtkCamera.h>
#include <vtkRenderer.h>

#include <algorithm>
#include <cmath>
#include <limits>

// The camera side of a SceneRenderer: projections between the scene and the display, standard
// directions, fitting, and whether the surface hides a point.

namespace devsurf::views {

using model::Vec3;

std::optional<Vec3> SceneRenderer::displayToPlane(double displayX, double displayY,
                                                  const Vec3& planePoint,
                                                  const Vec3& planeNormal) const {
    // The ray through the display point, from the near to the far clipping plane.
    Vec3 ends[2];
    for (int k = 0; k < 2; ++k) {
        m_renderer->SetDisplayPoint(displayX, displayY, k == 0 ? 0.0 : 1.0);
        m_renderer->DisplayToWorld();
        const double* w = m_renderer->GetWorldPoint();
        if (w[3] == 0.0) {
            return std::nullopt;
        }
        ends[k] = Vec3(w[0] / w[3], w[1] / w[3], w[2] / w[3]);
    }
    const Vec3 direction = ends[1] - ends[0];
    const double denominator = dot(direction, planeNormal);
    if (std::abs(denominator) < 1e-12 * direction.norm() * planeNormal.norm()) {
        return std::nullopt;
    }
    const double t = dot(planePoint - ends[0], planeNormal) / denominator;
    return ends[0] + direction * t;
}

Vec3 SceneRenderer::viewDirection() const {
    double direction[3];
    m_renderer->GetActiveCamera()->GetDirectionOfProjection(direction);
    return {direction[0], direction[1], direction[2]};
}

Vec3 SceneRenderer::toDisplay(const Vec3& point) const {
    m_renderer->SetWorldPoint(point.x, point.y, point.z, 1.0);
    m_renderer->WorldToDisplay();
    const double* d = m_renderer->GetDisplayPoint();
    return {d[0], d[1], d[2]};
}

Vec3 SceneRenderer::defaultDirection() {
    const Vec3 eye(1.0, -1.6, 1.2);
    return -eye / eye.norm();
}

void SceneRenderer::lookAlong(const Vec3& direction, const Vec3& up) {
    if (m_mode != Mode::Spatial || direction.norm() == 0.0) {
        return;
    }
    vtkCamera* camera = m_renderer->GetActiveCamera();
    const Vec3 d = direction / direction.norm();
    camera->SetFocalPoint(0.0, 0.0, 0.0);
    camera->SetPosition(-d.x, -d.y, -d.z);
    camera->SetViewUp(up.x, up.y, up.z);
    camera->OrthogonalizeViewUp();
    m_renderer->ResetCamera();
    fitBoundsToViewport();
}

double SceneRenderer::pixelsPerUnit() const {
    vtkCamera* camera = m_renderer->GetActiveCamera();
    const int* size = m_renderer->GetSize();
    if (size[1] <= 0) {
        return 0.0;
    }
    // The height of the scene seen at the focal point, in scene units.
    double visible = 0.0;
    if (camera->GetParallelProjection() != 0) {
        visible = 2.0 * camera->GetParallelScale();
    } else {
        constexpr double kDegree = 3.14159265358979323846 / 180.0;
        visible = 2.0 * camera->GetDistance() * std::tan(0.5 * camera->GetViewAngle() * kDegree);
    }
    return visible > 0.0 && std::isfinite(visible) ? size[1] / visible : 0.0;
}

void SceneRenderer::resetCamera() {
    if (m_mode == Mode::Development) {
        vtkCamera* camera = m_renderer->GetActiveCamera();
        camera->SetPosition(0.0, 0.0, 1.0);
        camera->SetFocalPoint(0.0, 0.0, 0.0);
        camera->SetViewUp(0.0, 1.0, 0.0);
    }
    m_renderer->ResetCamera();
    fitBoundsToViewport();
}

void SceneRenderer::fitBoundsToViewport() {
    // ResetCamera fits the bounding sphere tangent to the view: a corner of the bounding box
    // (a pinned corner of a flat sheet) can touch the edge, and nothing keeps a legend free.
    // The drawn points are fitted instead, tightly, with a margin for the markers.
    double bounds[6];
    m_renderer->ComputeVisiblePropBounds(bounds);
    const int* size = m_renderer->GetSize();
    if (!(bounds[0] <= bounds[1]) || size[0] <= 0 || size[1] <= 0) {
        return;
    }
    // At least the markers' margin, and a little air around the design in a large view.
    const double margin = std::max(kFitMargin, kFitAir * std::min(size[0], size[1]));
    const double left = margin;
    // The legends keep the right of the viewport from their left edge on: the quality legend,
    // and the distance legend left of it (ViewOverlay::distanceLegendRect).
    double legendLeft = size[0];
    const bool quality = m_quality && m_quality->mode() != ColourBy::Patch;
    const bool distance = drawsDistanceColours();
    if (quality || distance) {
        const QualityColouring::Box box = QualityColouring::legendBox(size[0], size[1]);
        legendLeft = box.left - (quality && distance ? box.right - box.left + 8.0 : 0.0);
    }
    const double right = std::max(left + 1.0, std::min(size[0] - margin, legendLeft - kFitMargin));
    const double bottom = margin;
    const double top = std::max(bottom + 1.0, size[1] - margin);
    vtkCamera* camera = m_renderer->GetActiveCamera();
    // The drawn points, or the corners of everything's bounds when there are none.
    std::vector<Vec3> points = fitPoints();
    if (points.empty()) {
        for (int corner = 0; corner < 8; ++corner) {
            points.push_back({bounds[(corner & 1) != 0 ? 1 : 0], bounds[(corner & 2) != 0 ? 3 : 2],
                              bounds[(corner & 4) != 0 ? 5 : 4]});
        }
    }
    // Perspective projection is not linear in the dolly: a few passes converge.
    for (int pass = 0; pass < 4; ++pass) {
        double minX = std::numeric_limits<double>::infinity();
        double minY = minX;
        double maxX = -minX;
        double maxY = -minX;
        for (const Vec3& point : points) {
            const Vec3 d = toDisplay(point);
            minX = std::min(minX, d.x);
            maxX = std::max(maxX, d.x);
            minY = std::min(minY, d.y);
            maxY = std::max(maxY, d.y);
        }
        const double width = maxX - minX;
        const double height = maxY - minY;
        if (!std::isfinite(width) || !std::isfinite(height) || (width <= 0.0 && height <= 0.0)) {
            return;
        }
        double scale = std::numeric_limits<double>::infinity();
        if (width > 0.0) {
            scale = std::min(scale, (right - left) / width);
        }
        if (height > 0.0) {
            scale = std::min(scale, (top - bottom) / height);
        }
        // Pan the box's centre to the free area's centre, at the focal point's depth.
        double focal[3];
        camera->GetFocalPoint(focal);
        const double depth = toDisplay({focal[0], focal[1], focal[2]}).z;
        auto toWorld = [this, depth](double x, double y) {
            m_renderer->SetDisplayPoint(x, y, depth);
            m_renderer->DisplayToWorld();
            const double* w = m_renderer->GetWorldPoint();
            return Vec3(w[0] / w[3], w[1] / w[3], w[2] / w[3]);
        };
        const Vec3 shift = toWorld(0.5 * (minX + maxX), 0.5 * (minY + maxY)) -
                           toWorld(0.5 * (left + right), 0.5 * (bottom + top));
        double position[3];
        camera->GetPosition(position);
        camera->SetFocalPoint(focal[0] + shift.x, focal[1] + shift.y, focal[2] + shift.z);
        camera->SetPosition(position[0] + shift.x, position[1] + shift.y, position[2] + shift.z);
        if (camera->GetParallelProjection() != 0) {
            camera->SetParallelScale(camera->GetParallelScale() / scale);
        } else {
            camera->Dolly(scale);
        }
        m_renderer->ResetCameraClippingRange(bounds);
        if (std::abs(scale - 1.0) < 1e-3) {
            break;
        }
    }
}

std::vector<Vec3> SceneRenderer::fitPoints() const {
    std::size_t total = 0;
    for (const SurfaceScene& scene : m_set->scenes) {
        total += scene.points.size();
    }
    const std::size_t stride = std::max<std::size_t>(1, total / kFitPoints);
    std::vector<Vec3> points;
    points.reserve(total / stride + 8);
    const bool controls = m_controlPointsShown;
    for (const SurfaceScene& scene : m_set->scenes) {
        for (std::size_t i = 0; i < scene.points.size(); i += stride) {
            points.push_back(scene.points[i]);
        }
        // The outermost sampled points may be skipped by the stride: the vertices never are.
        for (const auto& [id, position] : scene.vertices) {
            (void)id;
            points.push_back(position);
        }
        if (controls) {
            points.insert(points.end(), scene.controlPoints.begin(), scene.controlPoints.end());
        }
    }
    points.insert(points.end(), m_referenceCorners.begin(), m_referenceCorners.end());
    if (m_showReferenceShapes) {
        points.insert(points.end(), m_shapeCorners.begin(), m_shapeCorners.end());
    }
    return points;
}

bool SceneRenderer::isHidden(const Vec3& point) const {
    if (m_mode != Mode::Spatial) {
        return false;
    }
    const Vec3 display = toDisplay(point);
    std::optional<document::Pick> face;
    const std::optional<Vec3> hit = surfaceHit(display.x, display.y, &face);
    if (!hit) {
        return false;
    }
    double eye[3];
    m_renderer->GetActiveCamera()->GetPosition(eye);
    const Vec3 eyePoint(eye[0], eye[1], eye[2]);
    return distance(eyePoint, point) > distance(eyePoint, *hit) + 0.01 * m_sceneSize;
}

} // namespace devsurf::views
