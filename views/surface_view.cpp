#include "surface_view.h"

#include "scene_geometry.h"

namespace devsurf::views {

SurfaceView::SurfaceView(document::Document* document, document::Selection* selection,
                         QWidget* parent)
    : SceneView(Kind::Spatial, document, selection, parent) {
    setShowControlPolygonsImpl(m_showControlPolygons);
    setShowVerticesImpl(m_showVertices);
}

SurfaceView::~SurfaceView() = default;

QColor SurfaceView::patchColor(model::FaceId face) {
    const std::array<double, 3> rgb = patchRgb(face);
    return QColor::fromRgbF(static_cast<float>(rgb[0]), static_cast<float>(rgb[1]),
                            static_cast<float>(rgb[2]));
}

void SurfaceView::setTargetPointCloud(std::vector<model::Vec3> points) {
    m_target = std::move(points);
    setTargetPointsImpl(m_target);
}

void SurfaceView::setShowControlPolygons(bool show) {
    m_showControlPolygons = show;
    setShowControlPolygonsImpl(show);
}

void SurfaceView::setShowVertices(bool show) {
    m_showVertices = show;
    setShowVerticesImpl(show);
}

} // namespace devsurf::views
