#include "refine_spline_class_command.h"

#include "model/topology_edits.h"

namespace devsurf::document {

CommandOrError RefineSplineClassCommand::create(Document& document, int surfaceIndex,
                                                model::EdgeId edge, int factor) {
    const QString text = tr("Refine curves");
    return attempt(
        document, surfaceIndex, tr("The curves of edge %1 cannot be refined").arg(edge),
        [&](const model::CompositeSurface& s) { return model::refineSplineClass(s, edge, factor); },
        [&](model::CompositeSurface before, model::CompositeSurface after) {
            return std::unique_ptr<QUndoCommand>(new RefineSplineClassCommand(
                document, surfaceIndex, std::move(before), std::move(after),
                Change::Labels | Change::Geometry, text));
        });
}

} // namespace devsurf::document
