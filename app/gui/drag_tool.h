#pragma once

#include "model/composite_surface.h"
#include "model/document/selection.h"
#include "model/held_by_pins.h"
#include "model/pattern/pattern_sheet.h"
#include "panels/solver_panel.h"
#include "solver/session/crease_drag.h"
#include "solver/session/solve_job.h"
#include "solver/session/solve_session.h"

#include <QObject>
#include <QPoint>

#include <cstddef>
#include <map>
#include <memory>
#include <optional>
#include <vector>

class QAction;
class QTimer;

namespace devsurf::solver {
struct SolveResult;
} // namespace devsurf::solver

namespace devsurf::views {
class SceneView;
class SurfaceView;
} // namespace devsurf::views

namespace devsurf::app {

class SolveController;
class Workspace;

// The Drag tool (a checkable action): press on a vertex in the 3D view (or on one of several
// selected vertices of one surface) and move. The vertices move in the view plane through the
// pressed vertex (the axis chosen in the toolbar, or holding X, Y or Z, constrains the motion
// to that axis) and the surface follows: every move runs one solver iteration with the dragged
// vertices pulled to the mouse as handles (pinned vertices stay); the release runs ten more.
// Moves are shown outside the undo history; the release pushes one undo step whose undo
// returns the exact state at press; Esc returns to the state at press without touching the
// history. A press on a crease drags the crease
// instead (solver::CreaseDrag): it slides within its two strips, its control points and
// unpinned ends pulled by the mouse's motion (without its component along the surface normal,
// unless an axis is chosen). Presses away from vertices and creases still turn the camera. Other
// motions of the pressed vertices (RotateTool) override the hooks begin(), targetsAt(), undoText()
// and the sentences.
class DragTool : public QObject {
    Q_OBJECT
public:
    DragTool(QAction* action, Workspace* workspace, views::SurfaceView* view,
             SolveController* solver);
    ~DragTool() override;

    enum class Axis { Free, X, Y, Z };
    bool isDragging() const { return m_state != State::Idle; }
    // Pins that hold a dragged vertex where the sheet cannot bend, as found at the press of a
    // vertex drag keeping lengths (said in the status bar while the mouse moves).
    const std::optional<model::HeldVertex>& heldAtPress() const { return m_held; }
    // Why the last press on an edge did not drag it (said in the status bar); none if it did.
    const std::optional<solver::CreaseDragRefusal>& creaseRefusal() const { return m_refusal; }
    // The axis in effect: the one of a held X, Y or Z key, else the chosen one.
    Axis axis() const { return m_heldAxis != Axis::Free ? m_heldAxis : m_chosenAxis; }
    Axis chosenAxis() const { return m_chosenAxis; }
    // The axis chosen in the toolbar (Free: the tool's own default).
    void setChosenAxis(Axis axis) { m_chosenAxis = axis; }
    // The unit vector of an axis other than Free.
    static model::Vec3 unitVector(Axis axis);
    // Tools ▸ Snap to Reference Curves: a dragged vertex (no axis chosen) goes to the nearest
    // point of a reference curve drawn within 10 pixels of the mouse.
    void setSnapToCurves(bool snap) { m_snapToCurves = snap; }
    bool snapsToCurves() const { return m_snapToCurves; }
    // The reference curve the last move snapped to, or -1.
    int snappedCurve() const { return m_snappedCurve; }
    // Two-way editing: with the tool on, a press on a vertex of a surface that holds its sheet
    // in this view (the development view) drags the vertex's place in the sheet, and the
    // surface follows its sheet (solver::JobRequest::pulledSheet); one undo step.
    void setSheetView(views::SceneView* view) { m_sheetView = view; }
    // The drag moves a place in the sheet (pressed in the sheet view).
    bool draggingSheet() const { return m_inSheet && m_state != State::Idle; }

signals:
    // The drag ended: applied (one undo step), or not (cancelled, failed, or nothing moved).
    void dragFinished(bool applied);
    void statusMessage(const QString& text);
    void reportReady(const devsurf::app::SolveReport& report);

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

    // Called at press with the vertices to move (m_vertices, m_start) and the pressed vertex
    // (m_anchor); returns false (after saying why) to refuse the press.
    virtual bool begin() { return true; }
    // The targets of m_vertices for the mouse at pos; false: no motion for this position.
    virtual bool targetsAt(const QPoint& pos, std::vector<model::Vec3>& targets);
    // True: a press on any vertex moves the selected vertices of its surface (two or more),
    // whether the pressed one is selected or not; false: only a press on a selected vertex.
    virtual bool movesWholeSelection() const { return false; }
    // True: a press on a crease drags the crease.
    virtual bool dragsCreases() const { return true; }
    // The status bar sentence when the tool is turned on.
    virtual QString hintText() const;
    // The status bar sentence while the vertices follow the mouse.
    virtual QString motionText() const;
    // What the solve job is told this drag is.
    virtual solver::JobKind jobKind() const;
    // Called when the motion ends (applied or not).
    virtual void finish() {}
    virtual QString undoText() const;
    virtual QString cancelledText() const;
    // The status bar sentence while the iterations after the release run.
    QString settlingText(int iteration, int iterations) const;
    // "… stopped: reason The design is as it was."
    virtual QString stoppedText(const QString& reason) const;
    // The motion stopped because the design changed by another edit meanwhile.
    virtual QString changedText() const;

    views::SurfaceView* view() const { return m_view; }
    const model::CompositeSurface& pressSurface() const {
        return m_pressSurfaces.at(static_cast<std::size_t>(m_surface));
    }

    std::vector<model::VertexId> m_vertices;
    std::vector<model::Vec3> m_start;
    model::Vec3 m_anchor;
    model::Vec3 m_normal; // the view direction at press
    QPoint m_pressPos;

private:
    enum class State { Idle, Dragging, Finishing };
    bool press(const QPoint& pos);
    // A press in the sheet view; false: not on a vertex (the view handles it as usual).
    bool pressSheet(const QPoint& pos);
    // The target in the kept development for the mouse at pos in the sheet view.
    bool sheetTargetAt(const QPoint& pos);
    // A press on edge `pick` (which may or may not be a crease).
    bool pressCrease(const QPoint& pos, const document::Pick& pick);
    // The rest of a press once m_surface, m_vertices and m_start are set: the motion's plane
    // passes through `anchor`.
    bool start(const QPoint& pos, const model::Vec3& anchor);
    void move(const QPoint& pos);
    void release(const QPoint& pos, Qt::KeyboardModifiers modifiers);
    // Returns to the state at press (no undo step); says why in the status bar.
    void abort(const QString& sentence);
    // Shows the press state again if a move was shown.
    void restorePress();
    // settle: the release (the iterations after it).
    void submit(bool settle = false);
    // "Pins 0, 3 and 12 hold vertex 5 …", before the motion's sentence, while pins hold a
    // dragged vertex where the sheet cannot bend (m_held); empty otherwise.
    QString heldText() const;
    // The texts of a drag in the development view (drag_tool_sheet.cpp).
    QString sheetUndoText() const;
    QString sheetMotionText() const;
    void onResult(const solver::SolveResult& result);
    void end(bool applied, const QString& sentence);
    bool handleKey(QEvent* event);
    // The vertices a press on vertex `pressed` of `surface` drags (the selected ones of its
    // surface, or it alone), without changing the selection.
    std::vector<model::VertexId> verticesPressedAt(const document::Pick& pressed,
                                                   const model::CompositeSurface& surface) const;
    // The same for a press in the development view (drag_tool_sheet.cpp): pinned vertices
    // included (their places in the sheet may move), only those with a place in the kept
    // development (`indexOf`: developmentIndices).
    std::vector<model::VertexId>
    sheetVerticesPressedAt(const document::Pick& pressed, const model::CompositeSurface& surface,
                           const std::map<model::VertexId, std::size_t>& indexOf) const;
    // Each vertex's index in the kept development, which lists the coarse vertices first, in
    // id order.
    static std::map<model::VertexId, std::size_t>
    developmentIndices(const model::CompositeSurface& surface);
    // The lengths mode of the Solver settings as the solve job takes it.
    static solver::DragLengths dragLengths();

    // A drag prepared while the pointer rests on a vertex (drag_tool_prepare.cpp): the worker
    // builds the drag's session and its solver analysis before the press
    // (solver::JobRequest::prepare), and a press on the same vertices of the same design,
    // dragged the same way, continues it instead of starting cold.
    struct Prepared {
        quint64 key = 0;
        quint64 revision = 0;
        int surface = -1;
        std::vector<model::VertexId> vertices;
        solver::JobKind kind = solver::JobKind::VertexDrag;
        solver::DragLengths lengths = solver::DragLengths::Automatic;
        bool inSheet = false; // their places in the sheet, pressed in the development view
        model::EdgeId crease = model::kInvalidId; // the crease a crease drag drags
        // The same drag of the same design (the keys aside).
        bool sameDragAs(const Prepared& other) const {
            return revision == other.revision && surface == other.surface &&
                   vertices == other.vertices && kind == other.kind && lengths == other.lengths &&
                   inSheet == other.inSheet && crease == other.crease;
        }
    };
    // The pointer moved over the 3D view (or, `inSheetView`, the development view) with the
    // tool on and idle.
    void hovered(const QPoint& pos, bool inSheetView);
    // It has rested at m_restPos for kRestMs: prepares a drag of the vertex (or crease) under
    // it.
    void rested();
    // The preparation of a drag pressed in the development view at m_restPos, if a press there
    // would drag places in a held sheet (drag_tool_sheet.cpp).
    std::optional<Prepared> sheetDragRestedOn(solver::JobRequest& job) const;
    // The same for a press on the crease `pick` in the 3D view, if it can be dragged.
    std::optional<Prepared> creaseDragRestedOn(const document::Pick& pick,
                                               const model::CompositeSurface& surface,
                                               solver::JobRequest& job) const;
    // Drags get session keys of their own, so that no drag continues another one's solver
    // state (a prepared drag's is its press's).
    static quint64 nextSessionKey();
    // The session key of the drag pressed now: the prepared one if it is this drag's.
    quint64 sessionKeyAtPress();
    std::optional<Prepared> m_prepared;
    QTimer* m_rest = nullptr;
    QPoint m_restPos;
    bool m_restInSheet = false; // m_restPos is in the development view

    bool m_snapToCurves = false;
    int m_snappedCurve = -1;

    views::SceneView* m_sheetView = nullptr;
    bool m_inSheet = false;           // this drag was pressed in the sheet view
    model::PlaneMotion m_sheetMotion; // kept development → the view's layout
    // The dragged vertices (m_vertices) in the kept development, and where the drag puts them.
    std::vector<model::Vec2> m_sheetStarts;
    std::vector<model::Vec2> m_sheetTargets;
    std::size_t m_sheetPressed = 0; // the pressed one among them

    QAction* m_action;
    Workspace* m_workspace;
    views::SurfaceView* m_view;
    SolveController* m_solver;

    State m_state = State::Idle;
    Axis m_heldAxis = Axis::Free;
    Axis m_chosenAxis = Axis::Free;
    int m_surface = 0;
    solver::SharedSurfaces m_pressSurfaces; // sent with every move without a copy
    std::vector<model::Vec3> m_targets;
    bool m_moved = false;
    quint64 m_sessionKey = 0;
    quint64 m_pressRevision = 0;
    quint64 m_ownRevision = 0;
    bool m_previewed = false; // a move's result is shown (Document::previewSurface)
    // The crease being dragged (null for vertices) and its displacement for the mouse now.
    std::unique_ptr<solver::CreaseDrag> m_crease;
    model::Vec3 m_creaseShift;  // the motion the crease follows (status bar)
    model::Vec3 m_creaseDelta;  // the mouse's motion, on the axis if one is held
    bool m_creaseSlides = true; // no axis held: the crease slides within the surface
    // Pins that hold a dragged vertex where the sheet cannot bend (model::findVertexHeldByPins),
    // found at the press of a vertex drag keeping lengths on a surface of at most
    // kHeldCheckVertices vertices and kHeldCheckPins pins (larger ones hear it from the worker
    // after the release). Measured: 0.2 ms on fig8, 43 ms on a sheet of 676 vertices with its
    // 100 boundary vertices pinned.
    std::optional<model::HeldVertex> m_held;
    std::optional<solver::CreaseDragRefusal> m_refusal;
    static constexpr std::size_t kHeldCheckVertices = 2000;
    static constexpr std::size_t kHeldCheckPins = 100;
};

} // namespace devsurf::app
