#include "subdivide_strip_command.h"

#include "model/topology_edits.h"

namespace devsurf::document {

CommandOrError SubdivideStripCommand::create(Document& document, int surfaceIndex,
                                             model::FaceId face, double t) {
    const QString text = tr("Add a crease across patch %1").arg(face);
    return attempt(
        document, surfaceIndex, tr("No crease can be added across patch %1").arg(face),
        [&](const model::CompositeSurface& s) { return model::subdivideStrip(s, face, t); },
        [&](model::CompositeSurface before, model::CompositeSurface after) {
            return std::unique_ptr<QUndoCommand>(
                new SubdivideStripCommand(document, surfaceIndex, std::move(before),
                                          std::move(after), Change::Everything, text));
        });
}

} // namespace devsurf::document
