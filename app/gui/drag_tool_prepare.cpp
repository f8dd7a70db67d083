// The Drag tool's preparation: while the pointer rests on a vertex (in the 3D view, or on its
// place in the development view) or on a crease, the worker builds the drag a press there
// would start (its session, the normal equations' structure, the ordering and the symbolic
// analysis), so that the first move of a large design answers in one iteration's time instead
// of waiting for all of that (annulus-14: the first result 299 ms cold, 70 ms prepared;
// docs/tuning.md "A drag prepared while the pointer rests").

#include "drag_tool.h"

#include "model/document/document.h"
#include "model/document/selection.h"
#include "solve_controller.h"
#include "solver/worker/solver_worker.h"
#include "views/surface_view.h"
#include "workspace.h"

#include <QAction>
#include <QTimer>

namespace devsurf::app {

using document::Pick;

namespace {

// How long the pointer rests on a vertex before its drag is prepared: long enough that moving
// across the view prepares nothing, short against the time it takes to aim and press.
constexpr int kRestMs = 150;
// Designs with fewer patches answer their first move within a frame or two anyway (fig8's
// nine patches in 2 ms, the annulus's 48 in 57 ms cold and 18 ms prepared), so only surfaces
// of at least this many patches are prepared.
constexpr std::size_t kPreparedFaces = 40;

} // namespace

void DragTool::hovered(const QPoint& pos, bool inSheetView) {
    if (!m_rest) {
        m_rest = new QTimer(this);
        m_rest->setSingleShot(true);
        m_rest->setInterval(kRestMs);
        connect(m_rest, &QTimer::timeout, this, &DragTool::rested);
    }
    m_restPos = pos;
    m_restInSheet = inSheetView;
    m_rest->start();
}

void DragTool::rested() {
    document::Document* doc = m_workspace->document();
    if (!m_action->isChecked() || m_state != State::Idle) {
        return;
    }
    if (m_solver->isSolving() || m_solver->worker()->isBusy()) {
        // A preparation never delays a Solve, an approximation or another preparation; it
        // follows them while the pointer still rests here.
        m_rest->start();
        return;
    }
    solver::SolveRequest request;
    solver::JobRequest& job = request.job;
    std::optional<Prepared> prepared;
    if (m_restInSheet) {
        prepared = sheetDragRestedOn(job);
    } else if (const std::optional<Pick> pick = m_view->pickAt(m_restPos);
               pick && pick->surface >= 0 && pick->surface < doc->surfaceCount()) {
        const model::CompositeSurface& surface = doc->surface(pick->surface);
        if (pick->kind == Pick::Kind::Vertex && !surface.isPinned(pick->id)) {
            prepared = Prepared{};
            prepared->surface = pick->surface;
            prepared->vertices = verticesPressedAt(*pick, surface);
            std::vector<solver::VertexHandle>& handles = job.pulled[pick->surface];
            for (model::VertexId v : prepared->vertices) {
                handles.push_back({v, false, surface.position(v)});
            }
        } else if (pick->kind == Pick::Kind::Edge && dragsCreases()) {
            prepared = creaseDragRestedOn(*pick, surface, job);
        }
    }
    if (!prepared || doc->surface(prepared->surface).faces().size() < kPreparedFaces) {
        return;
    }
    prepared->revision = doc->revision();
    if (prepared->crease == model::kInvalidId) {
        prepared->kind = jobKind();
    }
    prepared->lengths = dragLengths();
    prepared->inSheet = m_restInSheet;
    if (m_prepared && m_prepared->sameDragAs(*prepared)) {
        return; // prepared already
    }
    prepared->key = nextSessionKey();
    request.revision = prepared->revision;
    request.ticket = prepared->key;
    job.kind = prepared->kind;
    job.drag = prepared->key;
    job.prepare = true;
    job.lengths = prepared->lengths;
    job.surfaces = doc->project().surfaces;
    m_prepared = std::move(prepared);
    m_solver->worker()->submit(std::move(request));
}

std::optional<DragTool::Prepared>
DragTool::creaseDragRestedOn(const Pick& pick, const model::CompositeSurface& surface,
                             solver::JobRequest& job) const {
    std::optional<solver::CreaseDrag> crease;
    try {
        crease.emplace(surface, pick.id);
    } catch (const solver::CreaseDragRefused&) {
        return std::nullopt; // a press there drags nothing
    }
    Prepared prepared;
    prepared.surface = pick.surface;
    prepared.kind = solver::JobKind::CreaseDrag;
    prepared.crease = pick.id;
    prepared.vertices = crease->vertices();
    // As the press's first request has them: the crease where it is.
    std::vector<solver::VertexHandle>& handles = job.pulled[pick.surface];
    for (std::size_t i = 0; i < prepared.vertices.size(); ++i) {
        handles.push_back({prepared.vertices[i], false, crease->vertexStart()[i]});
    }
    job.pulledControlPoints[pick.surface] = crease->controlPointHandles({}, true);
    return prepared;
}

quint64 DragTool::sessionKeyAtPress() {
    if (m_rest) {
        m_rest->stop();
    }
    std::optional<Prepared> prepared;
    prepared.swap(m_prepared); // a preparation serves one press at most
    Prepared pressed;
    pressed.revision = m_workspace->document()->revision();
    pressed.surface = m_surface;
    pressed.vertices = m_vertices;
    pressed.kind = jobKind();
    pressed.lengths = dragLengths();
    pressed.inSheet = m_inSheet;
    pressed.crease = m_crease ? m_crease->edge() : model::kInvalidId;
    if (prepared && prepared->sameDragAs(pressed)) {
        return prepared->key;
    }
    return nextSessionKey();
}

} // namespace devsurf::app
