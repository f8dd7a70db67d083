#include "split_at_ruling_command.h"

#include "model/strip.h"
#include "model/topology_edits.h"

#include <cmath>

namespace devsurf::document {

CommandOrError SplitAtRulingCommand::create(Document& document, int surfaceIndex,
                                            model::FaceId face, int breakpoint) {
    const QString text = tr("Add a ruling across patch %1").arg(face);
    return attempt(
        document, surfaceIndex, tr("No ruling can be added across patch %1").arg(face),
        [&](const model::CompositeSurface& s) { return model::splitAtRuling(s, face, breakpoint); },
        [&](model::CompositeSurface before, model::CompositeSurface after) {
            return std::unique_ptr<QUndoCommand>(
                new SplitAtRulingCommand(document, surfaceIndex, std::move(before),
                                         std::move(after), Change::Everything, text));
        });
}

std::pair<int, int> SplitAtRulingCommand::nearestBreakpoint(const model::CompositeSurface& surface,
                                                            model::FaceId face, double u) {
    if (!surface.hasFace(face)) {
        return {-1, 0};
    }
    const model::FaceType type = surface.faceType(face);
    if (type == model::FaceType::Planar || type == model::FaceType::Invalid) {
        return {-1, 0};
    }
    const int n = surface.edge(model::stripOfFace(surface, face).aSide.edge).space.intervals;
    return {static_cast<int>(std::lround(u * n)), n};
}

} // namespace devsurf::document
