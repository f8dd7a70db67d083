// The Drag tool in the development view (two-way editing): the places of a vertex, or of the
// selected vertices, in the sheet a surface holds, dragged there; the surface follows its sheet.
#include "drag_tool.h"

#include "model/document/document.h"
#include "model/document/selection.h"
#include "solve_controller.h"
#include "views/scene_view.h"
#include "workspace.h"

#include <map>

namespace devsurf::app {

using document::Pick;

bool DragTool::pressSheet(const QPoint& pos) {
    const std::optional<Pick> pick = m_sheetView->pickAt(pos);
    document::Document* doc = m_workspace->document();
    if (!pick || pick->kind != Pick::Kind::Vertex || pick->surface < 0 ||
        pick->surface >= doc->surfaceCount()) {
        return false; // the view selects and pans as usual
    }
    const model::CompositeSurface& surface = doc->surface(pick->surface);
    if (!surface.keepsDevelopment() || surface.development().empty()) {
        emit statusMessage(tr("Points of the development can be dragged only where the surface "
                              "holds its sheet (Tools ▸ Hold the Sheet)."));
        return false;
    }
    // The view lays the development out (turned, moved, maybe mirrored): the motion from the
    // kept development to that layout, fitted on the coarse vertices the view draws.
    const std::map<model::VertexId, std::size_t> indexOf = developmentIndices(surface);
    std::vector<model::Vec2> kept;
    std::vector<model::Vec2> shown;
    for (const auto& [id, index] : indexOf) {
        const std::optional<model::Vec3> at = m_sheetView->vertexScenePoint(pick->surface, id);
        if (at && index < surface.development().size()) {
            kept.push_back(surface.development()[index]);
            shown.push_back({at->x, at->y});
        }
    }
    const std::optional<model::PlaneMotion> motion = model::fitPlaneMotion(kept, shown);
    if (!motion || indexOf.at(pick->id) >= surface.development().size()) {
        return false;
    }
    const std::vector<model::VertexId> dragged = sheetVerticesPressedAt(*pick, surface, indexOf);
    if (!m_workspace->selection()->contains(*pick)) {
        m_workspace->selection()->set({*pick});
    }
    if (m_solver->isSolving()) {
        m_solver->cancel(tr("a drag started"));
    }
    m_inSheet = true;
    m_sheetMotion = *motion;
    m_vertices = dragged;
    m_sheetStarts.clear();
    m_start.clear();
    for (model::VertexId v : m_vertices) {
        if (v == pick->id) {
            m_sheetPressed = m_sheetStarts.size();
        }
        m_sheetStarts.push_back(surface.development()[indexOf.at(v)]);
        m_start.push_back(surface.position(v));
    }
    m_sheetTargets = m_sheetStarts;
    m_crease.reset();
    m_held.reset();
    m_surface = pick->surface;
    const model::Vec2 drawn = m_sheetMotion.apply(m_sheetStarts[m_sheetPressed]);
    start(pos, model::Vec3(drawn.x, drawn.y, 0.0));
    m_normal = model::Vec3(0.0, 0.0, 1.0); // the development's plane
    return true;
}

std::map<model::VertexId, std::size_t>
DragTool::developmentIndices(const model::CompositeSurface& surface) {
    std::map<model::VertexId, std::size_t> indexOf;
    for (const auto& [id, p] : surface.vertices()) {
        (void)p;
        const std::size_t index = indexOf.size();
        indexOf[id] = index;
    }
    return indexOf;
}

std::vector<model::VertexId>
DragTool::sheetVerticesPressedAt(const Pick& pressed, const model::CompositeSurface& surface,
                                 const std::map<model::VertexId, std::size_t>& indexOf) const {
    // The pressed vertex with the other selected vertices of its surface, if it is selected.
    const document::Selection* selection = m_workspace->selection();
    if (!selection->contains(pressed)) {
        return {pressed.id};
    }
    std::vector<model::VertexId> vertices;
    for (const Pick& p : selection->picks()) {
        if (p.kind == Pick::Kind::Vertex && p.surface == pressed.surface &&
            surface.hasVertex(p.id) && indexOf.at(p.id) < surface.development().size()) {
            vertices.push_back(p.id);
        }
    }
    return vertices;
}

std::optional<DragTool::Prepared> DragTool::sheetDragRestedOn(solver::JobRequest& job) const {
    const std::optional<Pick> pick = m_sheetView->pickAt(m_restPos);
    document::Document* doc = m_workspace->document();
    if (!pick || pick->kind != Pick::Kind::Vertex || pick->surface < 0 ||
        pick->surface >= doc->surfaceCount()) {
        return std::nullopt;
    }
    const model::CompositeSurface& surface = doc->surface(pick->surface);
    const std::map<model::VertexId, std::size_t> indexOf = developmentIndices(surface);
    if (!surface.keepsDevelopment() || indexOf.at(pick->id) >= surface.development().size()) {
        return std::nullopt; // a press there drags nothing
    }
    Prepared prepared;
    prepared.surface = pick->surface;
    prepared.vertices = sheetVerticesPressedAt(*pick, surface, indexOf);
    // Their places where they are, as the press's first request has them.
    std::vector<solver::SheetHandle>& places = job.pulledSheet[pick->surface];
    for (model::VertexId v : prepared.vertices) {
        places.push_back({v, surface.development()[indexOf.at(v)]});
    }
    return prepared;
}

bool DragTool::sheetTargetAt(const QPoint& pos) {
    const std::optional<model::Vec3> hit = m_sheetView->widgetToPlane(pos, m_anchor, m_normal);
    if (!hit) {
        return false;
    }
    model::Vec2 delta(hit->x - m_anchor.x, hit->y - m_anchor.y);
    if (axis() == Axis::X || axis() == Axis::Y) {
        delta = axis() == Axis::X ? model::Vec2(delta.x, 0.0) : model::Vec2(0.0, delta.y);
    }
    // Every dragged vertex moves by the same amount in the view's layout.
    for (std::size_t i = 0; i < m_sheetStarts.size(); ++i) {
        m_sheetTargets[i] =
            m_sheetMotion.applyInverse(m_sheetMotion.apply(m_sheetStarts[i]) + delta);
    }
    return true;
}

QString DragTool::sheetUndoText() const {
    if (m_vertices.size() == 1) {
        return tr("Drag vertex %1 in the sheet").arg(m_vertices.front());
    }
    return tr("Drag %n vertices in the sheet", nullptr, static_cast<int>(m_vertices.size()));
}

QString DragTool::sheetMotionText() const {
    const QString moved = QString::number(
        (m_sheetTargets[m_sheetPressed] - m_sheetStarts[m_sheetPressed]).norm(), 'f', 2);
    if (m_vertices.size() > 1) {
        return tr("Dragging %n vertices %1 mm along their sheet; the surface follows. Release to "
                  "finish, Esc cancels.",
                  nullptr, static_cast<int>(m_vertices.size()))
            .arg(moved);
    }
    return tr("Dragging vertex %1 %2 mm along its sheet; the surface follows. Release to "
              "finish, Esc cancels.")
        .arg(m_vertices.front())
        .arg(moved);
}

} // namespace devsurf::app
