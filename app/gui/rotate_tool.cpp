#include "rotate_tool.h"

#include "model/topology_edits.h"
#include "views/surface_view.h"

#include <algorithm>
#include <cmath>

namespace devsurf::app {

RotateTool::RotateTool(QAction* action, Workspace* workspace, views::SurfaceView* view,
                       SolveController* solver)
    : DragTool(action, workspace, view, solver) {}

model::Vec3 RotateTool::axisDirection() const {
    if (axis() != Axis::Free) {
        return unitVector(axis());
    }
    if (m_aboutViewAxis && m_normal.norm() > 0.0) {
        // Towards the viewer: a rotation to the right turns counter-clockwise on the screen,
        // as it does about Z seen from above.
        return m_normal * (-1.0 / m_normal.norm());
    }
    return unitVector(Axis::Z);
}

bool RotateTool::begin() {
    if (m_vertices.size() < 2) {
        emit statusMessage(tr("Rotate needs two or more vertices that are not pinned: select "
                              "them, then press on one of them and move the mouse sideways."));
        return false;
    }
    m_centroid = model::Vec3();
    for (const model::Vec3& p : m_start) {
        m_centroid += p;
    }
    m_centroid = m_centroid / static_cast<double>(m_start.size());
    // The axis is drawn across the whole surface.
    model::Vec3 lo(1e300, 1e300, 1e300);
    model::Vec3 hi(-1e300, -1e300, -1e300);
    for (const auto& [id, p] : pressSurface().vertices()) {
        for (int k = 0; k < 3; ++k) {
            lo[k] = std::min(lo[k], p[k]);
            hi[k] = std::max(hi[k], p[k]);
        }
    }
    m_axisLength = std::max(0.6 * (hi - lo).norm(), 1.0);
    m_angle = 0.0;
    emit statusMessage(tr("Rotate %n vertices %1: move the mouse sideways, %2° per pixel.", nullptr,
                          static_cast<int>(m_vertices.size()))
                           .arg(axisText())
                           .arg(kDegreesPerPixel));
    return true;
}

bool RotateTool::targetsAt(const QPoint& pos, std::vector<model::Vec3>& targets) {
    m_angle = kDegreesPerPixel * (pos.x() - m_pressPos.x());
    const model::Vec3 direction = axisDirection();
    const model::RigidMotion motion =
        model::RigidMotion::rotationAbout(m_centroid, direction, m_angle * M_PI / 180.0);
    targets.resize(m_start.size());
    for (std::size_t i = 0; i < m_start.size(); ++i) {
        targets[i] = motion.apply(m_start[i]);
    }
    view()->setPreviewLines(
        {{m_centroid - direction * m_axisLength, m_centroid + direction * m_axisLength}});
    return true;
}

void RotateTool::finish() {
    view()->setPreviewLines({});
}

QString RotateTool::axisText() const {
    switch (axis()) {
    case Axis::X:
        return tr("about the X axis through their centroid");
    case Axis::Y:
        return tr("about the Y axis through their centroid");
    case Axis::Z:
        return tr("about the Z axis through their centroid");
    case Axis::Free:
        break;
    }
    return m_aboutViewAxis ? tr("about the view axis through their centroid")
                           : tr("about the vertical axis (Z) through their centroid");
}

QString RotateTool::hintText() const {
    return tr("Rotate tool: select two or more vertices, press on one of them in the 3D view and "
              "move the mouse sideways (%1° per pixel). Esc cancels a rotation.")
        .arg(kDegreesPerPixel);
}

QString RotateTool::motionText() const {
    return tr("Rotating %n vertices by %1° %2. Release to finish, Esc cancels.", nullptr,
              static_cast<int>(m_vertices.size()))
        .arg(QString::number(m_angle, 'f', 1), axisText());
}

QString RotateTool::undoText() const {
    return tr("Rotate %n vertices", nullptr, static_cast<int>(m_vertices.size()));
}

QString RotateTool::cancelledText() const {
    return tr("Rotation cancelled; the design is as it was.");
}

QString RotateTool::stoppedText(const QString& reason) const {
    return tr("Rotation stopped: %1 The design is as it was.").arg(reason);
}

QString RotateTool::changedText() const {
    return tr("Rotation stopped: the design changed during the rotation.");
}

} // namespace devsurf::app
