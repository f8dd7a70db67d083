#pragma once

#include "model/vec3.h"

#include <QObject>
#include <QPointF>
#include <QString>

#include <cstddef>
#include <vector>

class QAction;

namespace devsurf::views {
class SurfaceView;
}

namespace devsurf::app {

class Workspace;

// Tools ▸ Mark Region of Reference Shape (L) and Tools ▸ Add Strip Over Marked Region (issue
// 42): with the tool on, pressing the left button in the 3D view and dragging draws a closed
// lasso; on release the points of the shown reference shapes (a mesh's vertices) inside it
// that face the camera (model::reference::pointsInLasso) become the marked region, drawn
// magenta. Shift adds to the mark, a click without dragging clears it; Esc drops a lasso in
// progress, else leaves the tool (the mark stays); Enter adds the strip. The strip is the flat
// PCA trapezoid of the marked points (model::reference::initialStrip, with the spline space of
// the approximation's strips), added as one undo step and named "strip N"; the mark is then
// cleared. The mark is view state, never saved: a change of the reference shapes or another
// project clears it. While the tool is on the left button draws, not turns the camera (the
// middle button pans, the right one and the wheel zoom).
class MarkRegionTool : public QObject {
    Q_OBJECT
public:
    MarkRegionTool(QAction* mark, QAction* stripAction, Workspace* workspace,
                   views::SurfaceView* view);

    // The spline intervals of the strip (as Tools ▸ Approximate Reference Shape…'s default).
    static constexpr int kIntervals = 4;

    // The marked points: indices into each reference shape's points, ascending.
    const std::vector<std::vector<std::size_t>>& marked() const { return m_marked; }
    std::size_t markedCount() const;
    std::vector<model::Vec3> markedPositions() const;

    // Adds a strip over the marked region (Tools ▸ Add Strip Over Marked Region); false and a
    // sentence in the status bar when it cannot.
    bool addStrip();

signals:
    void statusMessage(const QString& text);
    // A strip was added over the marked region.
    void stripAdded();

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    void onToggled(bool on);
    // Whether Esc and Enter sent to `watched` are the tool's.
    bool takesKeysOf(QObject* watched) const;
    void updateActions();
    void finishLasso(bool add);
    void cancelLasso();
    void clearMark();
    void showMark();

    QAction* m_mark;
    QAction* m_addStrip;
    Workspace* m_workspace;
    views::SurfaceView* m_view;
    std::vector<std::vector<std::size_t>> m_marked; // per reference shape
    std::vector<QPointF> m_lasso;                   // widget coordinates, while drawing
    bool m_drawing = false;
    bool m_shiftAtPress = false;
};

} // namespace devsurf::app
