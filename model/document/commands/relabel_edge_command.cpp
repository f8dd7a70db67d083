#include "relabel_edge_command.h"

#include "model/topology_edits.h"

namespace devsurf::document {

CommandOrError RelabelEdgeCommand::create(Document& document, int surfaceIndex, model::EdgeId edge,
                                          model::EdgeLabel label) {
    return create(document, surfaceIndex, {{edge, label}});
}

CommandOrError
RelabelEdgeCommand::create(Document& document, int surfaceIndex,
                           const std::vector<std::pair<model::EdgeId, model::EdgeLabel>>& labels) {
    if (labels.empty()) {
        return CommandOrError(tr("Select at least one edge to relabel."));
    }
    QString text;
    QString refusal;
    if (labels.size() == 1) {
        const QString id = QString::number(labels.front().first);
        const bool spline = labels.front().second == model::EdgeLabel::Spline;
        text = spline ? tr("Make edge %1 a spline curve").arg(id)
                      : tr("Make edge %1 a ruling").arg(id);
        refusal = spline ? tr("Edge %1 cannot become a spline curve").arg(id)
                         : tr("Edge %1 cannot become a ruling").arg(id);
    } else {
        text = tr("Relabel %n edges", nullptr, static_cast<int>(labels.size()));
        refusal = tr("The edges cannot be relabelled");
    }
    const QString indexError = checkSurfaceIndex(document, surfaceIndex);
    if (!indexError.isEmpty()) {
        return CommandOrError(indexError);
    }
    const auto& surface = document.project().surfaces[static_cast<std::size_t>(surfaceIndex)];
    for (const auto& [edge, label] : labels) {
        if (surface.hasEdge(edge) && surface.edge(edge).label == label) {
            return CommandOrError(label == model::EdgeLabel::Spline
                                      ? tr("Edge %1 is already a spline curve.").arg(edge)
                                      : tr("Edge %1 is already a ruling.").arg(edge));
        }
    }
    return attempt(
        document, surfaceIndex, refusal,
        [&labels](const model::CompositeSurface& s) { return model::relabelEdges(s, labels); },
        [&](model::CompositeSurface before, model::CompositeSurface after) {
            return std::unique_ptr<QUndoCommand>(
                new RelabelEdgeCommand(document, surfaceIndex, std::move(before), std::move(after),
                                       Change::Labels | Change::Geometry, text));
        });
}

} // namespace devsurf::document
