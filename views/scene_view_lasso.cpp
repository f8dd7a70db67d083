// The 3D view's lasso for marking reference points (app's MarkRegionTool): the camera as a
// projection the marking can use apart from VTK, the lasso drawn over the view and the
// marked points drawn in the scene.

#include "scene_view.h"
#include "scene_view_private.h"

#include <vtkCamera.h>
#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkMatrix4x4.h>
#include <vtkRenderer.h>

namespace devsurf::views {

model::reference::LassoCamera SceneView::lassoCamera() const {
    // VTK's composite matrix takes a scene point to normalised view coordinates (−1 … 1);
    // the renderer's viewport and the window's size to display pixels (y up); the device
    // pixel ratio and a flip of y to the widget (as projectToWidget).
    vtkCamera* camera = d->renderer->GetActiveCamera();
    const int* size = d->gl->renderWindow()->GetSize();
    const double width =
        size[0] > 0 ? size[0] : d->gl->width() * d->gl->effectiveDevicePixelRatio();
    const double height = d->deviceHeight();
    const double dpr = d->gl->effectiveDevicePixelRatio();
    const double* viewport = d->renderer->GetViewport();
    vtkMatrix4x4* m =
        camera->GetCompositeProjectionTransformMatrix(d->renderer->GetTiledAspectRatio(), -1, 1);
    const double halfWidth = 0.5 * width * (viewport[2] - viewport[0]);
    const double halfHeight = 0.5 * height * (viewport[3] - viewport[1]);
    const double ax = halfWidth / dpr;
    const double bx = (halfWidth + width * viewport[0]) / dpr;
    const double cy = -halfHeight / dpr;
    const double dy = (height - 1.0 - halfHeight - height * viewport[1]) / dpr;
    model::reference::LassoCamera lasso;
    for (int j = 0; j < 4; ++j) {
        const double w = m->GetElement(3, j);
        lasso.toScreen[static_cast<std::size_t>(j)] = ax * m->GetElement(0, j) + bx * w;
        lasso.toScreen[static_cast<std::size_t>(4 + j)] = cy * m->GetElement(1, j) + dy * w;
        lasso.toScreen[static_cast<std::size_t>(8 + j)] = m->GetElement(2, j);
        lasso.toScreen[static_cast<std::size_t>(12 + j)] = w;
    }
    lasso.parallel = camera->GetParallelProjection() != 0;
    double eye[3];
    camera->GetPosition(eye);
    lasso.eye = model::Vec3(eye[0], eye[1], eye[2]);
    lasso.direction = d->scene->viewDirection();
    return lasso;
}

void SceneView::setLasso(const std::vector<QPointF>& points) {
    d->overlay->setLasso(points);
}

std::vector<QPointF> SceneView::lasso() const {
    return d->overlay->lasso();
}

void SceneView::setMarkedPoints(const std::vector<model::Vec3>& points) {
    d->scene->setMarkedPoints(points);
    rerender();
}

int SceneView::markedPointsDrawn() const {
    return d->scene->markedPointCount();
}

} // namespace devsurf::views
