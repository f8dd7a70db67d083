#pragma once

#include "drag_tool.h"

namespace devsurf::app {

// The Rotate tool (a checkable action, exclusive with the Drag tool): press on a vertex in the
// 3D view (selected or not) and move the mouse sideways; the selected vertices of its surface
// (two or more; pinned ones stay) rotate about an
// axis through their centroid by kDegreesPerPixel per pixel of horizontal motion (to the right:
// right-handed about the axis). The axis is the one chosen in the toolbar or held (X, Y, Z);
// with Free it is the vertical axis (Z), or the view axis when aboutViewAxis() is on. The
// surface follows as in a drag (one solver iteration per move, ten after the release, pins
// stay); one undo step; Esc returns to the state at press without an undo step.
class RotateTool : public DragTool {
    Q_OBJECT
public:
    RotateTool(QAction* action, Workspace* workspace, views::SurfaceView* view,
               SolveController* solver);

    static constexpr double kDegreesPerPixel = 0.5;
    bool aboutViewAxis() const { return m_aboutViewAxis; }
    void setAboutViewAxis(bool on) { m_aboutViewAxis = on; }
    // The current rotation: angle in degrees, the axis through the centroid of the rotated
    // vertices at press, and its unit direction.
    double angleDegrees() const { return m_angle; }
    model::Vec3 axisPoint() const { return m_centroid; }
    model::Vec3 axisDirection() const;

protected:
    bool begin() override;
    bool movesWholeSelection() const override { return true; }
    bool dragsCreases() const override { return false; }
    solver::JobKind jobKind() const override { return solver::JobKind::Rotate; }
    bool targetsAt(const QPoint& pos, std::vector<model::Vec3>& targets) override;
    QString hintText() const override;
    QString motionText() const override;
    void finish() override;
    QString undoText() const override;
    QString cancelledText() const override;
    QString stoppedText(const QString& reason) const override;
    QString changedText() const override;

private:
    // "about the vertical axis (Z) through their centroid" and the like.
    QString axisText() const;

    bool m_aboutViewAxis = false;
    double m_angle = 0.0;
    double m_axisLength = 1.0;
    model::Vec3 m_centroid;
};

} // namespace devsurf::app
