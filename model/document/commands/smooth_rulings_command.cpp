#include "smooth_rulings_command.h"

namespace devsurf::document {

CommandOrError SmoothRulingsCommand::create(Document& document, int surfaceIndex,
                                            const std::set<model::EdgeId>& edges, bool smooth) {
    const int count = static_cast<int>(edges.size());
    if (count == 0) {
        return CommandOrError(tr("Select at least one ruling between two patches."));
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
        if (surface.edge(edge).isSpline()) {
            return CommandOrError(
                tr("Edge %1 is a curve; only rulings between two patches are smooth or sharp "
                   "(curves take a crease condition).")
                    .arg(edge));
        }
        if (surface.facesOfEdge(edge).size() != 2) {
            return CommandOrError(
                tr("Edge %1 is a ruling on the boundary; only rulings between two patches are "
                   "smooth or sharp.")
                    .arg(edge));
        }
        changes = changes || surface.edge(edge).smooth != smooth;
    }
    if (!changes) {
        return CommandOrError(smooth ? tr("The selected rulings are already smooth.")
                                     : tr("The selected rulings are already sharp."));
    }
    const QString text = smooth ? tr("Make %n rulings smooth", nullptr, count)
                                : tr("Make %n rulings sharp", nullptr, count);
    return attempt(document, surfaceIndex, text,
                   forEach(edges, [smooth](model::CompositeSurface& s,
                                           model::EdgeId edge) { s.setSmooth(edge, smooth); }),
                   [&](model::CompositeSurface before, model::CompositeSurface after) {
                       return std::unique_ptr<QUndoCommand>(
                           new SmoothRulingsCommand(document, surfaceIndex, std::move(before),
                                                    std::move(after), Change::Labels, text));
                   });
}

} // namespace devsurf::document
