#pragma once

#include "model/composite_surface.h"
#include "panels/solver_panel.h"

#include <QObject>
#include <QPoint>

#include <vector>

class QAction;

namespace devsurf::solver {
struct SolveResult;
} // namespace devsurf::solver

namespace devsurf::views {
class SurfaceView;
} // namespace devsurf::views

namespace devsurf::app {

class SolveController;
class Workspace;

// The Drag tool (a checkable action): press on a vertex in the 3D view (or on one of several
// selected vertices of one surface) and move. The vertices move in the view plane through the
// pressed vertex (holding X, Y or Z constrains the motion to that axis) and the surface
// follows: every move runs one solver iteration with the dragged vertices pulled to the
// mouse as handles (pinned vertices stay); the release runs ten more. The whole drag is one
// undo step whose undo returns the exact state at press; Esc during the drag returns to the
// state at press without an undo step. Presses away from vertices still turn the camera.
class DragTool : public QObject {
    Q_OBJECT
public:
    DragTool(QAction* action, Workspace* workspace, views::SurfaceView* view,
             SolveController* solver);
    ~DragTool() override;

    enum class Axis { Free, X, Y, Z };
    bool isDragging() const { return m_state != State::Idle; }
    Axis axis() const { return m_axis; }
    // Iterations run after the release.
    static constexpr int kFinalIterations = 10;

signals:
    // The drag ended: applied (one undo step), or not (cancelled, failed, or nothing moved).
    void dragFinished(bool applied);
    void statusMessage(const QString& text);
    void reportReady(const devsurf::app::SolveReport& report);

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    enum class State { Idle, Dragging, Finishing };
    bool press(const QPoint& pos);
    void move(const QPoint& pos);
    void release(const QPoint& pos, Qt::KeyboardModifiers modifiers);
    // Returns to the state at press (no undo step); says why in the status bar.
    void abort(const QString& sentence);
    void submit(int iterations);
    void onResult(const solver::SolveResult& result);
    void end(bool applied, const QString& sentence);
    bool handleKey(QEvent* event);
    QString undoText() const;

    QAction* m_action;
    Workspace* m_workspace;
    views::SurfaceView* m_view;
    SolveController* m_solver;

    State m_state = State::Idle;
    Axis m_axis = Axis::Free;
    int m_surface = 0;
    std::vector<model::VertexId> m_vertices;
    std::vector<model::Vec3> m_start;
    std::vector<model::CompositeSurface> m_pressSurfaces;
    model::Vec3 m_anchor;
    model::Vec3 m_normal;
    model::Vec3 m_delta;
    QPoint m_pressPos;
    bool m_moved = false;
    quint64 m_sessionKey = 0;
    int m_mergeKey = 0;
    quint64 m_pressRevision = 0;
    quint64 m_ownRevision = 0;
    int m_stackCountAtPress = 0;
    bool m_applied = false;
};

} // namespace devsurf::app
