#include "pin_vertices_command.h"

namespace devsurf::document {

CommandOrError PinVerticesCommand::create(Document& document, int surfaceIndex,
                                          const std::set<model::VertexId>& vertices, bool pin) {
    const int count = static_cast<int>(vertices.size());
    if (count == 0) {
        return CommandOrError(pin ? tr("Select at least one vertex to pin.")
                                  : tr("Select at least one vertex to unpin."));
    }
    const QString indexError = checkSurfaceIndex(document, surfaceIndex);
    if (!indexError.isEmpty()) {
        return CommandOrError(indexError);
    }
    const auto& surface = document.project().surfaces[static_cast<std::size_t>(surfaceIndex)];
    bool changes = false;
    for (model::VertexId vertex : vertices) {
        if (!surface.hasVertex(vertex)) {
            return CommandOrError(tr("Vertex %1 does not exist.").arg(vertex));
        }
        changes = changes || surface.isPinned(vertex) != pin;
    }
    if (!changes) {
        return CommandOrError(pin ? tr("The selected vertices are already pinned.")
                                  : tr("The selected vertices are not pinned."));
    }
    const QString text =
        pin ? tr("Pin %n vertices", nullptr, count) : tr("Unpin %n vertices", nullptr, count);
    return attempt(document, surfaceIndex, text,
                   forEach(vertices, [pin](model::CompositeSurface& s,
                                           model::VertexId vertex) { s.setPinned(vertex, pin); }),
                   [&](model::CompositeSurface before, model::CompositeSurface after) {
                       return std::unique_ptr<QUndoCommand>(
                           new PinVerticesCommand(document, surfaceIndex, std::move(before),
                                                  std::move(after), Change::Pins, text));
                   });
}

} // namespace devsurf::document
