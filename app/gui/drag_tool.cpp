#include "drag_tool.h"
#include "curve_snap.h"
#include "edit_refusal.h"
#include "problem_text.h"

#include "model/bspline_curve.h"
#include "model/document/commands/apply_surface_command.h"
#include "model/document/document.h"
#include "model/document/selection.h"
#include "solve_controller.h"
#include "solver/worker/solver_worker.h"
#include "views/scene_view.h"
#include "views/surface_view.h"
#include "views/vtk_opengl_widget.h"
#include "workspace.h"

#include <QAction>
#include <QApplication>
#include <QKeyEvent>
#include <QMouseEvent>
#include <QUndoStack>

#include <algorithm>
#include <limits>
#include <stdexcept>

namespace devsurf::app {

using document::Pick;

namespace {

// Pointer travel (logical pixels) below which a press and release on a vertex is a click.
constexpr int kClickSlop = 3;
// Logical pixels within which Snap to Reference Curves pulls a dragged vertex onto a curve.
constexpr double kSnapPixels = 10.0;

} // namespace

quint64 DragTool::nextSessionKey() {
    static quint64 key = 0x44524147'00000000ULL; // never 0 (0 is Solve)
    return ++key;
}

DragTool::DragTool(QAction* action, Workspace* workspace, views::SurfaceView* view,
                   SolveController* solver)
    : QObject(action), m_action(action), m_workspace(workspace), m_view(view), m_solver(solver) {
    m_action->setCheckable(true);
    connect(solver->worker(), &solver::SolverWorker::finished, this, &DragTool::onResult);
    // The release of a large model settles for seconds (and longer where the whole drag would
    // end broken and the job looks for how far it can follow): its progress, and Esc cancels.
    connect(solver->worker(), &solver::SolverWorker::progress, this,
            [this](quint64 revision, int iteration, int iterations, double) {
                if (m_state == State::Finishing && revision == m_pressRevision) {
                    emit statusMessage(settlingText(iteration, iterations));
                }
            });
    // While the tool is on, an application event filter sees the view's mouse events before
    // the view does, and the axis keys wherever the keyboard focus is.
    connect(m_action, &QAction::toggled, this, [this](bool on) {
        if (on) {
            qApp->installEventFilter(this);
            emit statusMessage(hintText());
        } else {
            if (m_state == State::Dragging) {
                abort(cancelledText());
            }
            qApp->removeEventFilter(this);
            m_heldAxis = Axis::Free;
        }
    });
    connect(workspace->document(), &document::Document::projectReset, this, [this] {
        m_prepared.reset();
        if (m_state != State::Idle) {
            m_solver->worker()->cancel();
            m_state = State::Idle;
            finish();
            emit dragFinished(false);
        }
    });
}

DragTool::~DragTool() {
    qApp->removeEventFilter(this);
}

model::Vec3 DragTool::unitVector(Axis axis) {
    model::Vec3 unit;
    unit[axis == Axis::X ? 0 : (axis == Axis::Y ? 1 : 2)] = 1.0;
    return unit;
}

bool DragTool::handleKey(QEvent* event) {
    auto* key = static_cast<QKeyEvent*>(event);
    if (event->type() == QEvent::ShortcutOverride) {
        // Esc during a drag or its settling belongs to the drag, not to Select None.
        if (m_state != State::Idle && key->key() == Qt::Key_Escape) {
            event->accept();
            return true;
        }
        return false;
    }
    if (key->isAutoRepeat()) {
        return m_state == State::Dragging;
    }
    Axis axis = Axis::Free;
    switch (key->key()) {
    case Qt::Key_X:
        axis = Axis::X;
        break;
    case Qt::Key_Y:
        axis = Axis::Y;
        break;
    case Qt::Key_Z:
        axis = Axis::Z;
        break;
    case Qt::Key_Escape:
        if (event->type() == QEvent::KeyPress && m_state != State::Idle) {
            abort(cancelledText());
            return true;
        }
        return false;
    default:
        return false;
    }
    if (event->type() == QEvent::KeyPress) {
        m_heldAxis = axis;
    } else if (m_heldAxis == axis) {
        m_heldAxis = Axis::Free;
    }
    return m_state == State::Dragging;
}

bool DragTool::eventFilter(QObject* watched, QEvent* event) {
    const QEvent::Type type = event->type();
    if (type == QEvent::KeyPress || type == QEvent::KeyRelease ||
        type == QEvent::ShortcutOverride) {
        return m_action->isChecked() && handleKey(event);
    }
    const bool inSheetView = m_sheetView != nullptr && watched == m_sheetView->glWidget();
    if ((watched != m_view->glWidget() && !inSheetView) || !m_action->isChecked()) {
        return false;
    }
    if (m_state != State::Idle && inSheetView != m_inSheet) {
        return false; // the other view's events during a drag
    }
    switch (type) {
    case QEvent::MouseButtonPress: {
        auto* me = static_cast<QMouseEvent*>(event);
        if (me->button() == Qt::LeftButton && m_state == State::Idle &&
            !(me->modifiers() & Qt::ControlModifier)) {
            return inSheetView ? pressSheet(me->position().toPoint())
                               : press(me->position().toPoint());
        }
        return m_state == State::Dragging;
    }
    case QEvent::MouseMove:
        if (m_state == State::Dragging) {
            move(static_cast<QMouseEvent*>(event)->position().toPoint());
            return true;
        }
        if (m_state == State::Idle) {
            hovered(static_cast<QMouseEvent*>(event)->position().toPoint(), inSheetView);
        }
        return false;
    case QEvent::Leave:
        if (m_rest) {
            m_rest->stop(); // the pointer rests elsewhere
        }
        return false;
    case QEvent::MouseButtonRelease: {
        auto* me = static_cast<QMouseEvent*>(event);
        if (m_state == State::Dragging && me->button() == Qt::LeftButton) {
            release(me->position().toPoint(), me->modifiers());
            return true;
        }
        return false;
    }
    default:
        return false;
    }
}

bool DragTool::press(const QPoint& pos) {
    m_inSheet = false;
    const std::optional<Pick> pick = m_view->pickAt(pos);
    document::Document* doc = m_workspace->document();
    m_crease.reset();
    if (pick && pick->kind == Pick::Kind::Edge && dragsCreases() && pick->surface >= 0 &&
        pick->surface < doc->surfaceCount()) {
        return pressCrease(pos, *pick);
    }
    if (!pick || pick->kind != Pick::Kind::Vertex || pick->surface < 0 ||
        pick->surface >= doc->surfaceCount()) {
        return false; // the camera turns as usual
    }
    const model::CompositeSurface& surface = doc->surface(pick->surface);
    if (surface.isPinned(pick->id)) {
        emit statusMessage(
            tr("Vertex %1 is pinned and cannot be dragged; unpin it first.").arg(pick->id));
        return true;
    }
    m_vertices = verticesPressedAt(*pick, surface);
    if (m_vertices.size() == 1 && m_vertices.front() == pick->id &&
        !m_workspace->selection()->contains(*pick)) {
        m_workspace->selection()->set({*pick});
    }
    if (m_solver->isSolving()) {
        m_solver->cancel(tr("a drag started"));
    }
    m_surface = pick->surface;
    m_start.clear();
    for (model::VertexId v : m_vertices) {
        m_start.push_back(surface.position(v));
    }
    m_held.reset();
    if (SolveController::keepsLengths() && surface.vertices().size() <= kHeldCheckVertices &&
        surface.pinnedVertices().size() <= kHeldCheckPins) {
        m_held = model::findVertexHeldByPins(surface, m_vertices); // 0.2 ms on fig8
    }
    return start(pos, surface.position(pick->id));
}

bool DragTool::pressCrease(const QPoint& pos, const Pick& pick) {
    document::Document* doc = m_workspace->document();
    const model::CompositeSurface& surface = doc->surface(pick.surface);
    m_refusal.reset();
    try {
        m_crease = std::make_unique<solver::CreaseDrag>(surface, pick.id);
    } catch (const solver::CreaseDragRefused& refused) {
        m_refusal = refused.reason();
        // Not a crease (or nothing of it may move): say so, and the camera turns as usual.
        switch (refused.reason()) {
        case solver::CreaseDragRefusal::NoSuchEdge:
            emit statusMessage(tr("There is no edge %1.").arg(refused.edge()));
            break;
        case solver::CreaseDragRefusal::NotACrease:
            emit statusMessage(tr("Edge %1 is not a crease (a curve between two patches); only "
                                  "creases can be dragged.")
                                   .arg(refused.edge()));
            break;
        case solver::CreaseDragRefusal::Immovable:
            emit statusMessage(tr("Edge %1 cannot move: both its ends are pinned and it has no "
                                  "other control point.")
                                   .arg(refused.edge()));
            break;
        }
        return false;
    }
    m_workspace->selection()->set({pick});
    if (m_solver->isSolving()) {
        m_solver->cancel(tr("a drag started"));
    }
    m_held.reset(); // a dragged crease stretches its strips on purpose
    m_surface = pick.surface;
    m_vertices = m_crease->vertices();
    m_start = m_crease->vertexStart();
    m_creaseShift = {};
    m_creaseDelta = {};
    m_creaseSlides = true;
    // The plane of the motion passes through the point of the crease nearest the press.
    const model::EdgeRecord& record = surface.edge(pick.id);
    const model::BSplineCurve curve =
        model::BSplineCurve::uniform(record.space, record.controlPoints);
    model::Vec3 anchor = record.controlPoints.front();
    double nearest = std::numeric_limits<double>::infinity();
    constexpr int kSamples = 64;
    for (int i = 0; i <= kSamples; ++i) {
        const double u =
            curve.domainBegin() + (curve.domainEnd() - curve.domainBegin()) * i / kSamples;
        const model::Vec3 p = curve.evaluate(u);
        const double d = (m_view->projectToWidget(p) - pos).manhattanLength();
        if (d < nearest) {
            nearest = d;
            anchor = p;
        }
    }
    return start(pos, anchor);
}

bool DragTool::start(const QPoint& pos, const model::Vec3& anchor) {
    document::Document* doc = m_workspace->document();
    m_anchor = anchor;
    m_normal = m_view->viewDirection();
    m_pressPos = pos;
    m_moved = false;
    m_pressSurfaces = doc->project().surfaces;
    m_targets = m_start;
    if (!begin()) {
        m_crease.reset();
        return true;
    }
    m_sessionKey = sessionKeyAtPress();
    m_pressRevision = doc->revision();
    m_ownRevision = m_pressRevision;
    m_previewed = false;
    m_state = State::Dragging;
    return true;
}

void DragTool::move(const QPoint& pos) {
    if ((pos - m_pressPos).manhattanLength() <= kClickSlop && !m_moved) {
        return;
    }
    if (m_inSheet ? !sheetTargetAt(pos) : !targetsAt(pos, m_targets)) {
        return;
    }
    m_moved = true;
    emit statusMessage(
        heldText() + motionText() +
        (m_snappedCurve >= 0
             ? QStringLiteral(" ") + tr("Snapped to reference curve %1.").arg(m_snappedCurve + 1)
             : QString()));
    submit();
}

bool DragTool::targetsAt(const QPoint& pos, std::vector<model::Vec3>& targets) {
    const std::optional<model::Vec3> hit = m_view->widgetToPlane(pos, m_anchor, m_normal);
    if (!hit) {
        return false;
    }
    model::Vec3 delta = *hit - m_anchor;
    if (axis() != Axis::Free) {
        const model::Vec3 unit = unitVector(axis());
        delta = unit * dot(delta, unit);
    }
    if (m_crease) {
        // Each point of the crease moves its own way (see solver::CreaseDrag); the shift is
        // the motion shown in the status bar.
        m_creaseDelta = delta;
        m_creaseSlides = axis() == Axis::Free;
        m_creaseShift =
            m_crease->displacement(delta, m_creaseSlides) * m_crease->reach(delta, m_creaseSlides);
        targets.clear();
        for (const solver::VertexHandle& handle : m_crease->vertexHandles(delta, m_creaseSlides)) {
            targets.push_back(handle.target);
        }
        return true;
    }
    m_snappedCurve = -1;
    if (m_snapToCurves && axis() == Axis::Free) {
        const std::optional<CurveSnap> snap = snapToCurves(
            *m_view, m_workspace->document()->project().referenceCurves, pos, kSnapPixels);
        if (snap) {
            delta = snap->point - m_anchor; // the pressed vertex onto the curve
            m_snappedCurve = snap->curve;
        }
    }
    targets.resize(m_start.size());
    for (std::size_t i = 0; i < m_start.size(); ++i) {
        targets[i] = m_start[i] + delta;
    }
    return true;
}

solver::JobKind DragTool::jobKind() const {
    return m_crease ? solver::JobKind::CreaseDrag : solver::JobKind::VertexDrag;
}

void DragTool::submit(bool settle) {
    solver::SolveRequest request;
    request.revision = m_pressRevision;
    request.ticket = m_sessionKey;
    solver::JobRequest& job = request.job;
    job.kind = jobKind();
    job.drag = m_sessionKey;
    job.settle = settle;
    job.surfaces = m_pressSurfaces;
    if (m_inSheet) {
        for (std::size_t i = 0; i < m_vertices.size() && i < m_sheetTargets.size(); ++i) {
            job.pulledSheet[m_surface].push_back({m_vertices[i], m_sheetTargets[i]});
        }
    } else {
        std::vector<solver::VertexHandle>& handles = job.pulled[m_surface];
        for (std::size_t i = 0; i < m_vertices.size(); ++i) {
            handles.push_back({m_vertices[i], false, m_targets[i]});
        }
    }
    if (m_crease) {
        job.pulledControlPoints[m_surface] =
            m_crease->controlPointHandles(m_creaseDelta, m_creaseSlides);
    }
    job.lengths = dragLengths();
    m_solver->worker()->submit(std::move(request));
}

solver::DragLengths DragTool::dragLengths() {
    switch (SolveController::lengthsSetting()) {
    case SolveController::LengthsMode::Keep:
        return solver::DragLengths::Keep;
    case SolveController::LengthsMode::Stretch:
        return solver::DragLengths::Stretch;
    case SolveController::LengthsMode::Automatic:
        break;
    }
    return solver::DragLengths::Automatic;
}

std::vector<model::VertexId>
DragTool::verticesPressedAt(const Pick& pressed, const model::CompositeSurface& surface) const {
    // The pressed vertex with the other selected vertices of its surface, if it is selected
    // (a tool that moves the selection as a whole takes them from a press on any vertex).
    const document::Selection* selection = m_workspace->selection();
    std::vector<model::VertexId> vertices;
    for (const Pick& p : selection->picks()) {
        if (p.kind == Pick::Kind::Vertex && p.surface == pressed.surface &&
            surface.hasVertex(p.id) && !surface.isPinned(p.id)) {
            vertices.push_back(p.id);
        }
    }
    if (!selection->contains(pressed) && (!movesWholeSelection() || vertices.size() < 2)) {
        vertices.assign(1, pressed.id);
    }
    return vertices;
}

void DragTool::release(const QPoint& pos, Qt::KeyboardModifiers modifiers) {
    if (!m_moved) {
        // A click on a vertex selects as it does without the tool.
        m_state = State::Idle;
        finish();
        const std::optional<Pick> pick =
            (m_inSheet ? static_cast<views::SceneView*>(m_sheetView) : m_view)->pickAt(pos);
        if (pick && (modifiers & Qt::ShiftModifier)) {
            m_workspace->selection()->toggle(*pick);
        }
        emit dragFinished(false);
        return;
    }
    // The move being solved finishes and is shown; the iterations after the release continue
    // from the session's state with the handles at the release position.
    m_state = State::Finishing;
    submit(true);
}

void DragTool::abort(const QString& sentence) {
    m_solver->worker()->cancel();
    restorePress();
    end(false, sentence);
}

void DragTool::restorePress() {
    document::Document* doc = m_workspace->document();
    if (m_previewed && m_surface < doc->surfaceCount() &&
        !(doc->surface(m_surface) == pressSurface())) {
        doc->previewSurface(m_surface, pressSurface());
    }
    m_previewed = false;
}

void DragTool::end(bool applied, const QString& sentence) {
    m_state = State::Idle;
    finish();
    if (!sentence.isEmpty()) {
        emit statusMessage(sentence);
    }
    emit dragFinished(applied);
}

void DragTool::onResult(const solver::SolveResult& result) {
    const solver::JobOutcome& outcome = result.outcome;
    if (m_prepared && result.ticket != m_prepared->key) {
        m_prepared.reset(); // the worker ran something else since: the preparation is gone
    }
    if (m_state == State::Idle || result.ticket != m_sessionKey || outcome.cancelled() ||
        outcome.prepared) {
        return;
    }
    document::Document* doc = m_workspace->document();
    if (!outcome.ok) {
        const bool settling = m_state == State::Finishing;
        abort(stoppedText(SolveController::failureText(outcome.failure)));
        if (settling) {
            emit reportReady(SolveController::reportOf(result, undoText()));
        }
        return;
    }
    if (doc->revision() != m_ownRevision) {
        // Another edit (an undo, say) changed the design during the drag: it ends without a
        // step, and where the dragged surface still shows a move, the press comes back.
        m_solver->worker()->cancel();
        if (!(m_previewed && m_surface < doc->surfaceCount() &&
              doc->surfaceRevision(m_surface) == m_ownRevision)) {
            m_previewed = false;
        }
        restorePress();
        end(false, changedText());
        return;
    }
    const auto index = static_cast<std::size_t>(m_surface);
    if (index >= outcome.surfaces.size()) {
        return;
    }
    const model::CompositeSurface& shape = outcome.surfaces[index];
    if (!outcome.settled) {
        // A move: shown, outside the undo history (the job validated it).
        doc->previewSurface(m_surface, shape);
        m_previewed = true;
        m_ownRevision = doc->revision();
        return;
    }
    // The release: the settled shape becomes one undo step from the press.
    // The report goes to the Solver panel once the design shows the result (its step pushed,
    // or the press back): the panel files it under that undo state.
    const SolveReport report = SolveController::reportOf(result, undoText());
    if (shape == pressSurface()) {
        restorePress();
        emit reportReady(report);
        end(false, tr("%1: %2").arg(undoText(), report.status));
        return;
    }
    doc->previewSurface(m_surface, shape);
    m_previewed = true;
    document::CommandOrError edit =
        document::ApplySurfaceCommand::createShown(*doc, m_surface, pressSurface(), undoText());
    if (edit.isRefused()) {
        abort(stoppedText(refusalText(edit)));
        return;
    }
    doc->undoStack()->push(edit.takeCommand().release());
    m_previewed = false;
    emit reportReady(report);
    end(true, tr("%1: %2").arg(undoText(), report.status));
}

} // namespace devsurf::app
