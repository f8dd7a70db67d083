// The Drag tool in the development view (two-way editing): a vertex's place in the sheet a
// surface holds, dragged there; the surface follows its sheet.
#include "drag_tool.h"

#include "model/document/document.h"
#include "model/document/selection.h"
#include "solve_controller.h"
#include "views/scene_view.h"
#include "workspace.h"

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
    const auto& vertices = surface.vertices();
    std::vector<model::Vec2> kept;
    std::vector<model::Vec2> shown;
    std::size_t index = 0;
    std::size_t pressed = 0;
    for (const auto& [id, p] : vertices) {
        (void)p;
        const std::optional<model::Vec3> at = m_sheetView->vertexScenePoint(pick->surface, id);
        if (at && index < surface.development().size()) {
            kept.push_back(surface.development()[index]);
            shown.push_back({at->x, at->y});
        }
        if (id == pick->id) {
            pressed = index;
        }
        ++index;
    }
    const std::optional<model::pattern::PlaneMotion> motion =
        model::pattern::fitPlaneMotion(kept, shown);
    if (!motion || pressed >= surface.development().size()) {
        return false;
    }
    m_workspace->selection()->set({*pick});
    if (m_solver->isSolving()) {
        m_solver->cancel(tr("a drag started"));
    }
    m_inSheet = true;
    m_sheetMotion = *motion;
    m_sheetStart = surface.development()[pressed];
    m_sheetTarget = m_sheetStart;
    m_crease.reset();
    m_held.reset();
    m_surface = pick->surface;
    m_vertices.assign(1, pick->id);
    m_start.assign(1, surface.position(pick->id));
    const model::Vec2 drawn = m_sheetMotion.apply(m_sheetStart);
    start(pos, model::Vec3(drawn.x, drawn.y, 0.0));
    m_normal = model::Vec3(0.0, 0.0, 1.0); // the development's plane
    return true;
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
    const model::Vec2 drawn = m_sheetMotion.apply(m_sheetStart) + delta;
    m_sheetTarget = m_sheetMotion.applyInverse(drawn);
    return true;
}

} // namespace devsurf::app
