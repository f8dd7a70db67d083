#include "tool_reactions.h"
#include "edit_refusal.h"

#include "../distance_report_dialog.h"
#include "../edit_preview.h"
#include "../move_dialog.h"
#include "../position_dialog.h"
#include "../solve_controller.h"
#include "../workspace.h"
#include "model/document/commands/command_or_error.h"
#include "model/document/commands/merge_strips_command.h"
#include "model/document/commands/move_vertices_command.h"
#include "model/document/commands/refine_spline_class_command.h"
#include "model/document/commands/relabel_edge_command.h"
#include "model/document/commands/split_at_ruling_command.h"
#include "model/document/commands/subdivide_strip_command.h"
#include "model/document/commands/surface_edit_command.h"
#include "model/document/document.h"
#include "model/document/selection.h"
#include "model/model_error.h"
#include "model/reference/distance_report.h"
#include "model/reference/surface_samples.h"
#include "model/strip.h"
#include "model/topology_edits.h"
#include "views/scene_view.h"

#include <QAction>
#include <QMessageBox>

namespace devsurf::app {

namespace {

using document::Pick;

// A merged strip this close (mm) to the two it replaces kept the shape (the rest is the
// sampling of the distance measurement).
constexpr double kUnchangedMm = 1e-6;

std::optional<SelectedIds> selected(const Workspace* workspace, Pick::Kind kind) {
    std::optional<SelectedIds> result;
    for (const Pick& pick : workspace->selection()->picks()) {
        if (pick.kind != kind) {
            continue;
        }
        if (!result) {
            result = SelectedIds{pick.surface, {}};
        } else if (result->surface != pick.surface) {
            return std::nullopt;
        }
        result->ids.insert(pick.id);
    }
    return result;
}

const model::CompositeSurface* surfaceOf(const Workspace* workspace, int index) {
    const auto& surfaces = workspace->document()->project().surfaces;
    if (index < 0 || index >= static_cast<int>(surfaces.size())) {
        return nullptr;
    }
    return &surfaces[static_cast<std::size_t>(index)];
}

// The one selected face of the given types, if exactly one face is selected.
std::optional<std::pair<int, model::FaceId>>
singleFace(const Workspace* workspace, std::initializer_list<model::FaceType> types) {
    const auto faces = selected(workspace, Pick::Kind::Face);
    if (!faces || faces->ids.size() != 1) {
        return std::nullopt;
    }
    const model::CompositeSurface* surface = surfaceOf(workspace, faces->surface);
    const model::FaceId face = *faces->ids.begin();
    if (surface == nullptr || !surface->hasFace(face)) {
        return std::nullopt;
    }
    for (model::FaceType type : types) {
        if (surface->faceType(face) == type) {
            return std::make_pair(faces->surface, face);
        }
    }
    return std::nullopt;
}

void explainDisabled(QAction* action, bool enabled, const QString& what) {
    action->setEnabled(enabled);
    action->setStatusTip(what);
    action->setToolTip(what);
}

} // namespace

RelabelEdgeReaction::RelabelEdgeReaction(QAction* action, Workspace* workspace)
    : Reaction(action, workspace) {
    followDocumentAndSelection();
}

namespace {

// The relabelling of the selected edges (each R ↔ S), if edges of one surface are selected.
std::optional<document::CommandOrError> relabelSelection(Workspace* workspace) {
    const auto edges = selected(workspace, Pick::Kind::Edge);
    const model::CompositeSurface* surface = edges ? surfaceOf(workspace, edges->surface) : nullptr;
    if (surface == nullptr) {
        return std::nullopt;
    }
    std::vector<std::pair<model::EdgeId, model::EdgeLabel>> changes;
    for (model::EdgeId edge : edges->ids) {
        if (surface->hasEdge(edge)) {
            changes.emplace_back(edge, surface->edge(edge).isSpline() ? model::EdgeLabel::Ruling
                                                                      : model::EdgeLabel::Spline);
        }
    }
    return document::RelabelEdgeCommand::create(*workspace->document(), edges->surface, changes);
}

} // namespace

void RelabelEdgeReaction::updateEnableState() {
    // The edit is tried on a copy: an edge whose relabelling would leave a patch that is
    // neither strip, cone nor planar polygon (every edge of the cylinder) is not offered.
    const std::optional<document::CommandOrError> edit = relabelSelection(workspace());
    if (edit && edit->isRefused()) {
        explainDisabled(action(), false, tr("Cannot relabel: %1").arg(refusalText(*edit)));
        return;
    }
    explainDisabled(action(), edit.has_value(),
                    tr("Turn the selected edges from rulings (R) into spline curves (S) or back. "
                       "Select edges of one surface first."));
}

void RelabelEdgeReaction::onTriggered() {
    std::optional<document::CommandOrError> edit = relabelSelection(workspace());
    if (edit) {
        workspace()->apply(std::move(*edit), tr("Cannot relabel"));
    }
}

SubdivideStripReaction::SubdivideStripReaction(QAction* action, Workspace* workspace,
                                               views::SceneView* preview)
    : Reaction(action, workspace), m_preview(preview) {
    followDocumentAndSelection();
}

void SubdivideStripReaction::updateEnableState() {
    explainDisabled(action(), singleFace(workspace(), {model::FaceType::StripSRSR}).has_value(),
                    tr("Add a crease across the selected strip and the row of strips it belongs "
                       "to. Select one patch of type strip (SRSR) first."));
}

void SubdivideStripReaction::onTriggered() {
    const auto face = singleFace(workspace(), {model::FaceType::StripSRSR});
    if (!face) {
        return;
    }
    const model::CompositeSurface surface =
        workspace()->document()->project().surfaces[static_cast<std::size_t>(face->first)];
    PositionDialog dialog(tr("Add Crease"),
                          tr("Where the new crease crosses patch %1 and the strips of its row "
                             "(green in the 3D view): per cent of the way from one curve of the "
                             "strip to the other.")
                              .arg(face->second),
                          workspace()->window());
    auto preview = [this, &surface, face](double t) {
        if (m_preview == nullptr) {
            return;
        }
        try {
            m_preview->setPreviewLines(
                addedEdgeLines(surface, model::subdivideStrip(surface, face->second, t),
                               model::EdgeLabel::Spline));
        } catch (const model::ModelError&) {
            m_preview->setPreviewLines({}); // the dialog's OK then says why
        }
    };
    connect(&dialog, &PositionDialog::fractionChanged, this, preview);
    dialog.setRange(1.0, 99.0, 50.0);
    const bool ok = dialog.exec() == QDialog::Accepted;
    if (m_preview != nullptr) {
        m_preview->setPreviewLines({});
    }
    if (!ok) {
        return;
    }
    const double t = dialog.fraction();
    workspace()->apply(document::SubdivideStripCommand::create(*workspace()->document(),
                                                               face->first, face->second, t),
                       tr("Cannot add the crease"));
}

SplitAtRulingReaction::SplitAtRulingReaction(QAction* action, Workspace* workspace,
                                             views::SceneView* preview)
    : Reaction(action, workspace), m_preview(preview) {
    followDocumentAndSelection();
}

void SplitAtRulingReaction::updateEnableState() {
    explainDisabled(action(),
                    singleFace(workspace(), {model::FaceType::StripSRSR, model::FaceType::StripSRS,
                                             model::FaceType::ConeSRR})
                        .has_value(),
                    tr("Add a ruling across the selected strip and the strips that share its "
                       "curves. Select one strip or cone patch first."));
}

void SplitAtRulingReaction::onTriggered() {
    const auto face =
        singleFace(workspace(), {model::FaceType::StripSRSR, model::FaceType::StripSRS,
                                 model::FaceType::ConeSRR});
    if (!face) {
        return;
    }
    document::Document& doc = *workspace()->document();
    auto surface = [&doc, &face]() -> const model::CompositeSurface& {
        return doc.project().surfaces[static_cast<std::size_t>(face->first)];
    };
    // Refining keeps the edge ids, so the strip's curve a stays the same edge.
    const model::EdgeId curveA = model::stripOfFace(surface(), face->second).aSide.edge;
    if (surface().edge(curveA).space.intervals < 2) {
        const auto answer = QMessageBox::question(
            workspace()->window(), tr("Add Ruling"),
            tr("The curves of this strip have a single spline interval, so a ruling can only be "
               "added after refining them (the shape stays the same). Refine now?"));
        if (answer != QMessageBox::Yes ||
            !workspace()->apply(
                document::RefineSplineClassCommand::create(doc, face->first, curveA, 2),
                tr("Cannot refine"))) {
            return;
        }
    }
    const int n = surface().edge(curveA).space.intervals;
    // A ruling can go through the curves' breakpoints only: offer those, in per cent along.
    std::vector<double> positions;
    for (int i = 1; i < n; ++i) {
        positions.push_back(static_cast<double>(i) / n);
    }
    const model::CompositeSurface before = surface();
    PositionDialog dialog(tr("Add Ruling"),
                          tr("Where the new ruling crosses patch %1 and the strips that share "
                             "its curves (green in the 3D view): per cent of the way along the "
                             "strip. Rulings can go through the %n breakpoint(s) of the curves; "
                             "refine the curves (Ctrl+Shift+R) for more.",
                             nullptr, n - 1)
                              .arg(face->second),
                          workspace()->window());
    auto preview = [this, &before, face, &dialog](double) {
        if (m_preview == nullptr) {
            return;
        }
        try {
            m_preview->setPreviewLines(addedEdgeLines(
                before, model::splitAtRuling(before, face->second, dialog.choice() + 1),
                model::EdgeLabel::Ruling));
        } catch (const model::ModelError&) {
            m_preview->setPreviewLines({});
        }
    };
    connect(&dialog, &PositionDialog::fractionChanged, this, preview);
    dialog.setChoices(positions, (n - 1) / 2);
    const bool ok = dialog.exec() == QDialog::Accepted;
    if (m_preview != nullptr) {
        m_preview->setPreviewLines({});
    }
    if (!ok) {
        return;
    }
    const int breakpoint = dialog.choice() + 1;
    workspace()->apply(
        document::SplitAtRulingCommand::create(doc, face->first, face->second, breakpoint),
        tr("Cannot add the ruling"));
}

RemoveRulingReaction::RemoveRulingReaction(QAction* action, Workspace* workspace)
    : Reaction(action, workspace) {
    followDocumentAndSelection();
}

namespace {

// The one selected edge, if it is a ruling between two patches.
std::optional<std::pair<int, model::EdgeId>> innerRuling(const Workspace* workspace) {
    const auto edges = selected(workspace, Pick::Kind::Edge);
    if (!edges || edges->ids.size() != 1) {
        return std::nullopt;
    }
    const model::CompositeSurface* surface = surfaceOf(workspace, edges->surface);
    const model::EdgeId edge = *edges->ids.begin();
    if (surface == nullptr || !surface->hasEdge(edge) || surface->edge(edge).isSpline() ||
        surface->facesOfEdge(edge).size() != 2) {
        return std::nullopt;
    }
    return std::make_pair(edges->surface, edge);
}

} // namespace

void RemoveRulingReaction::updateEnableState() {
    explainDisabled(action(), innerRuling(workspace()).has_value(),
                    tr("Remove the selected ruling between two strips, merging them into one "
                       "strip whose curves join theirs. Select one ruling between two strips "
                       "first."));
}

void RemoveRulingReaction::onTriggered() {
    const auto ruling = innerRuling(workspace());
    if (!ruling) {
        return;
    }
    document::Document& doc = *workspace()->document();
    const model::CompositeSurface before = doc.surface(ruling->first);
    if (!workspace()->apply(
            document::MergeStripsCommand::create(doc, ruling->first, ruling->second),
            tr("Cannot remove the ruling"))) {
        return;
    }
    // How far the merged strip lies from the two it replaced (dense samples of theirs).
    const model::reference::SurfaceSamples samples = model::reference::sampleDensely({before}, 8);
    const double moved =
        model::reference::measureDistance(doc.surface(ruling->first), samples.positions)
            .targetToSurface.max;
    emit workspace()->statusMessage(
        moved <= kUnchangedMm
            ? tr("Ruling %1 removed: its two strips are one strip, the shape unchanged.")
                  .arg(ruling->second)
            : tr("Ruling %1 removed: its two strips are one strip, up to %2 from where they "
                 "were; Tools ▸ Solve makes it developable again if it is not.")
                  .arg(ruling->second)
                  .arg(DistanceReportDialog::millimetres(moved)));
}

RefineCurvesReaction::RefineCurvesReaction(QAction* action, Workspace* workspace)
    : Reaction(action, workspace) {
    followDocumentAndSelection();
}

namespace {

// An S-edge to refine: the selected S-edge, or the curve a of the selected strip.
std::optional<std::pair<int, model::EdgeId>> curveToRefine(const Workspace* workspace) {
    const auto edges = selected(workspace, Pick::Kind::Edge);
    if (edges && edges->ids.size() == 1) {
        const model::CompositeSurface* surface = surfaceOf(workspace, edges->surface);
        const model::EdgeId edge = *edges->ids.begin();
        if (surface != nullptr && surface->hasEdge(edge) && surface->edge(edge).isSpline()) {
            return std::make_pair(edges->surface, edge);
        }
    }
    const auto face = singleFace(workspace, {model::FaceType::StripSRSR, model::FaceType::StripSRS,
                                             model::FaceType::ConeSRR});
    if (face) {
        const model::CompositeSurface* surface = surfaceOf(workspace, face->first);
        return std::make_pair(face->first, model::stripOfFace(*surface, face->second).aSide.edge);
    }
    return std::nullopt;
}

} // namespace

void RefineCurvesReaction::updateEnableState() {
    explainDisabled(action(), curveToRefine(workspace()).has_value(),
                    tr("Double the spline intervals of the selected curve and of all curves "
                       "joined to it through strips; the shape stays the same. Select one "
                       "spline edge or strip first."));
}

void RefineCurvesReaction::onTriggered() {
    const auto curve = curveToRefine(workspace());
    if (curve) {
        workspace()->apply(document::RefineSplineClassCommand::create(
                               *workspace()->document(), curve->first, curve->second, 2),
                           tr("Cannot refine"));
    }
}

MoveVerticesReaction::MoveVerticesReaction(QAction* action, Workspace* workspace,
                                           SolveController* solver)
    : Reaction(action, workspace), m_solver(solver) {
    followDocumentAndSelection();
}

void MoveVerticesReaction::updateEnableState() {
    explainDisabled(action(), selected(workspace(), Pick::Kind::Vertex).has_value(),
                    tr("Translate or rotate the selected vertices with their neighbouring control "
                       "points. Select vertices of one surface first."));
}

void MoveVerticesReaction::onTriggered() {
    const auto vertices = selected(workspace(), Pick::Kind::Vertex);
    const model::CompositeSurface* surface =
        vertices ? surfaceOf(workspace(), vertices->surface) : nullptr;
    if (surface == nullptr) {
        return;
    }
    model::Vec3 centroid;
    for (model::VertexId v : vertices->ids) {
        centroid += surface->position(v);
    }
    centroid = centroid / static_cast<double>(vertices->ids.size());
    MoveDialog dialog(centroid, workspace()->window());
    if (dialog.exec() != QDialog::Accepted) {
        return;
    }
    document::Document& doc = *workspace()->document();
    const std::set<model::VertexId> ids(vertices->ids.begin(), vertices->ids.end());
    document::CommandOrError edit = dialog.isRotation()
                                        ? document::MoveVerticesCommand::createRotation(
                                              doc, vertices->surface, ids, dialog.axisPoint(),
                                              dialog.axisDirection(), dialog.angleRadians())
                                        : document::MoveVerticesCommand::createTranslation(
                                              doc, vertices->surface, ids, dialog.translation());
    const QString refusal = dialog.isRotation() ? tr("Cannot rotate") : tr("Cannot move");
    const auto* motion = dynamic_cast<const document::SurfaceEditCommand*>(edit.command());
    if (!dialog.keepDevelopable() || m_solver == nullptr || motion == nullptr) {
        workspace()->apply(std::move(edit), refusal);
        return;
    }
    // The motion is not applied yet: the solver starts from the moved surface, holding the
    // moved vertices where the motion put them; its result, if any, is the one undo step.
    if (m_solver->isSolving()) {
        m_solver->cancel(tr("the vertices are moved"));
    }
    m_solver->solveEdit(vertices->surface, motion->after(), ids, motion->text());
}

} // namespace devsurf::app
