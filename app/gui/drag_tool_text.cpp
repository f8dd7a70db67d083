// The Drag tool's sentences: the status bar's hint, the motion while dragging, the settling
// after the release, the undo step's name and the endings (cancelled, stopped, held by pins).
#include "drag_tool.h"

#include "model/bspline_curve.h"

namespace devsurf::app {

QString DragTool::undoText() const {
    if (m_inSheet && !m_vertices.empty()) {
        return sheetUndoText();
    }
    if (m_crease) {
        return tr("Drag crease %1").arg(m_crease->edge());
    }
    return tr("Drag %n vertices", nullptr, static_cast<int>(m_vertices.size()));
}

QString DragTool::cancelledText() const {
    return tr("Drag cancelled; the design is as it was.");
}

QString DragTool::settlingText(int iteration, int iterations) const {
    return tr("%1: settling, iteration %2 of %3 (Esc cancels).")
        .arg(undoText())
        .arg(iteration)
        .arg(iterations);
}

QString DragTool::stoppedText(const QString& reason) const {
    return tr("Drag stopped: %1 The design is as it was.").arg(reason);
}

QString DragTool::hintText() const {
    return tr("Drag tool: press on a vertex in the 3D view and move the mouse; the selected "
              "vertices of its surface follow. Press on a crease to slide it within its patches. "
              "Esc cancels a drag.");
}

QString DragTool::changedText() const {
    return tr("Drag stopped: the design changed during the drag.");
}

QString DragTool::motionText() const {
    if (m_inSheet && !m_sheetStarts.empty()) {
        return sheetMotionText();
    }
    if (m_crease) {
        const QString shift = QString::number(m_creaseShift.norm(), 'f', 2);
        if (axis() == Axis::Free && m_crease->reach(m_creaseDelta, true) < 1.0) {
            return tr("Sliding crease %1 by %2 mm within the surface, as far as it goes: the "
                      "patch it moves into keeps %3 % of its width. Release to finish, Esc "
                      "cancels.")
                .arg(m_crease->edge())
                .arg(shift)
                .arg(qRound(100.0 * solver::kCreaseSlideRoom));
        }
        return axis() == Axis::Free
                   ? tr("Sliding crease %1 by %2 mm within the surface. Release to finish, Esc "
                        "cancels; hold X, Y or Z to move along that axis.")
                         .arg(m_crease->edge())
                         .arg(shift)
                   : tr("Moving crease %1 by %2 mm along the axis. Release to finish, Esc "
                        "cancels.")
                         .arg(m_crease->edge())
                         .arg(shift);
    }
    const double distance = m_targets.empty() ? 0.0 : (m_targets.front() - m_start.front()).norm();
    const QString length = QString::number(distance, 'f', 2);
    const int n = static_cast<int>(m_vertices.size());
    switch (axis()) {
    case Axis::X:
        return tr("Dragging %n vertices %1 mm along X. Release to finish, Esc cancels.", nullptr, n)
            .arg(length);
    case Axis::Y:
        return tr("Dragging %n vertices %1 mm along Y. Release to finish, Esc cancels.", nullptr, n)
            .arg(length);
    case Axis::Z:
        return tr("Dragging %n vertices %1 mm along Z. Release to finish, Esc cancels.", nullptr, n)
            .arg(length);
    case Axis::Free:
        break;
    }
    return tr("Dragging %n vertices %1 mm in the view plane. Release to finish, Esc cancels; "
              "hold X, Y or Z to move along that axis.",
              nullptr, n)
        .arg(length);
}

QString DragTool::heldText() const {
    if (!m_held || m_crease) {
        return {};
    }
    const model::HeldVertex& held = *m_held;
    if (held.pins.size() == 2) {
        return tr("Pins %1 and %2 hold vertex %3 on the straight line between them (they are as "
                  "far apart as in the flat sheet): it moves only by stretching the sheet. ")
            .arg(held.pins[0])
            .arg(held.pins[1])
            .arg(held.vertex);
    }
    return tr("Pins %1, %2 and %3 hold vertex %4 in the triangle between them (they are as far "
              "apart as in the flat sheet): it moves only by stretching the sheet. ")
        .arg(held.pins[0])
        .arg(held.pins[1])
        .arg(held.pins[2])
        .arg(held.vertex);
}

} // namespace devsurf::app
