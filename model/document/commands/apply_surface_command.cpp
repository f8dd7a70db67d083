#include "apply_surface_command.h"

#include "command_ids.h"

namespace devsurf::document {

ApplySurfaceCommand::ApplySurfaceCommand(Document& document, int surfaceIndex,
                                         model::CompositeSurface before,
                                         model::CompositeSurface after, Changes changes,
                                         const QString& text, int mergeKey)
    : SurfaceEditCommand(document, surfaceIndex, std::move(before), std::move(after), changes,
                         text),
      m_mergeKey(mergeKey) {}

CommandOrError ApplySurfaceCommand::create(Document& document, int surfaceIndex,
                                           model::CompositeSurface newSurface, const QString& text,
                                           Changes changes, int mergeKey) {
    const auto problems = newSurface.validate();
    if (!problems.empty()) {
        return CommandOrError(tr("The new shape cannot be applied"), problems.front());
    }
    return createValidated(document, surfaceIndex, std::move(newSurface), text, changes, mergeKey);
}

CommandOrError ApplySurfaceCommand::createValidated(Document& document, int surfaceIndex,
                                                    model::CompositeSurface newSurface,
                                                    const QString& text, Changes changes,
                                                    int mergeKey) {
    return attempt(
        document, surfaceIndex, text,
        [&newSurface](const model::CompositeSurface&) { return std::move(newSurface); },
        [&](model::CompositeSurface before, model::CompositeSurface after) {
            return std::unique_ptr<QUndoCommand>(
                new ApplySurfaceCommand(document, surfaceIndex, std::move(before), std::move(after),
                                        changes, text, mergeKey));
        });
}

CommandOrError ApplySurfaceCommand::createShown(Document& document, int surfaceIndex,
                                                model::CompositeSurface before,
                                                const QString& text) {
    const QString indexError = checkSurfaceIndex(document, surfaceIndex);
    if (!indexError.isEmpty()) {
        return CommandOrError(indexError);
    }
    model::CompositeSurface after = document.surface(surfaceIndex);
    before.setId(after.id());
    auto* command = new ApplySurfaceCommand(document, surfaceIndex, std::move(before),
                                            std::move(after), Change::Geometry, text, -1);
    command->m_shown = true;
    return CommandOrError(std::unique_ptr<QUndoCommand>(command));
}

void ApplySurfaceCommand::redo() {
    if (m_shown) {
        m_shown = false; // pushed: the document shows the result already
        return;
    }
    SurfaceEditCommand::redo();
}

int ApplySurfaceCommand::id() const {
    return m_mergeKey < 0 ? -1 : kApplySurfaceCommandId;
}

bool ApplySurfaceCommand::mergeWith(const QUndoCommand* other) {
    const auto* next = dynamic_cast<const ApplySurfaceCommand*>(other);
    if (next == nullptr || m_mergeKey < 0 || next->m_mergeKey != m_mergeKey ||
        next->surfaceIndex() != surfaceIndex()) {
        return false;
    }
    setAfter(next->after(), next->changes());
    return true;
}

} // namespace devsurf::document
