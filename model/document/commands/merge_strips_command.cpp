#include "merge_strips_command.h"

#include "model/strip_joining.h"

namespace devsurf::document {

CommandOrError MergeStripsCommand::create(Document& document, int surfaceIndex,
                                          model::EdgeId ruling) {
    const QString text = tr("Remove ruling %1").arg(ruling);
    return attempt(
        document, surfaceIndex, tr("Ruling %1 cannot be removed").arg(ruling),
        [&](const model::CompositeSurface& s) { return model::mergeStrips(s, ruling); },
        [&](model::CompositeSurface before, model::CompositeSurface after) {
            return std::unique_ptr<QUndoCommand>(
                new MergeStripsCommand(document, surfaceIndex, std::move(before), std::move(after),
                                       Change::Everything, text));
        });
}

} // namespace devsurf::document
