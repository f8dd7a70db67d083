#include "crease_condition_command.h"

namespace devsurf::document {

QString CreaseConditionCommand::conditionText(model::CreaseCondition condition) {
    switch (condition) {
    case model::CreaseCondition::CurvedFold:
        return tr("Curved fold");
    case model::CreaseCondition::Geodesic:
        return tr("Geodesic");
    case model::CreaseCondition::Straight:
        return tr("Straight when unfolded");
    case model::CreaseCondition::None:
        break;
    }
    return tr("No condition");
}

CommandOrError CreaseConditionCommand::create(Document& document, int surfaceIndex,
                                              const std::set<model::EdgeId>& edges,
                                              model::CreaseCondition condition) {
    const int count = static_cast<int>(edges.size());
    if (count == 0) {
        return CommandOrError(tr("Select at least one crease."));
    }
    const QString indexError = checkSurfaceIndex(document, surfaceIndex);
    if (!indexError.isEmpty()) {
        return CommandOrError(indexError);
    }
    const auto& surface = document.project().surfaces[static_cast<std::size_t>(surfaceIndex)];
    bool changes = false;
    for (model::EdgeId edge : edges) {
        if (!surface.hasEdge(edge)) {
            return CommandOrError(tr("Edge %1 does not exist.").arg(edge));
        }
        if (!surface.edge(edge).isSpline()) {
            return CommandOrError(
                tr("Edge %1 is a ruling; conditions apply to creases (curves between two "
                   "patches).")
                    .arg(edge));
        }
        if (surface.facesOfEdge(edge).size() != 2) {
            return CommandOrError(
                tr("Edge %1 is a curve on the boundary, not a crease; conditions apply to "
                   "curves between two patches.")
                    .arg(edge));
        }
        changes = changes || surface.edge(edge).condition != condition;
    }
    if (!changes) {
        return CommandOrError(tr("The selected creases already have the condition \"%1\".")
                                  .arg(conditionText(condition)));
    }
    const QString text = condition == model::CreaseCondition::None
                             ? tr("Clear the condition of %n creases", nullptr, count)
                             : tr("%1 on %n creases", nullptr, count).arg(conditionText(condition));
    return attempt(
        document, surfaceIndex, text,
        forEach(edges, [condition](model::CompositeSurface& s,
                                   model::EdgeId edge) { s.setCreaseCondition(edge, condition); }),
        [&](model::CompositeSurface before, model::CompositeSurface after) {
            return std::unique_ptr<QUndoCommand>(new CreaseConditionCommand(
                document, surfaceIndex, std::move(before), std::move(after), Change::Labels, text));
        });
}

} // namespace devsurf::document
