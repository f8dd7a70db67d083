#pragma once

#include "scene_view.h"

#include <QColor>

#include <vector>

namespace devsurf::views {

// The 3D view: every strip tessellated and shaded in its patch colour, S-edges as sampled
// curves, R-edges as lines, creases (S-edges between two faces) thicker and darker, and
// optionally the control polygons (blue) and the vertices.
class SurfaceView : public SceneView {
    Q_OBJECT
public:
    SurfaceView(document::Document* document, document::Selection* selection,
                QWidget* parent = nullptr);
    ~SurfaceView() override;

    // The fixed colour of a patch, for legends and panels.
    static QColor patchColor(model::FaceId face);

    bool showControlPolygons() const { return m_showControlPolygons; }
    bool showVertices() const { return m_showVertices; }

    // A measured point cloud the design should follow (drawn as green points; none yet).
    void setTargetPointCloud(std::vector<model::Vec3> points);
    const std::vector<model::Vec3>& targetPointCloud() const { return m_target; }

public slots:
    void setShowControlPolygons(bool show);
    void setShowVertices(bool show);

private:
    bool m_showControlPolygons = false;
    bool m_showVertices = true;
    std::vector<model::Vec3> m_target;
};

} // namespace devsurf::views
