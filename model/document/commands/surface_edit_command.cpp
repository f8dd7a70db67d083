#include "surface_edit_command.h"

#include "model/model_error.h"

#include "model/document/document.h"

#include <exception>

namespace devsurf::document {

SurfaceEditCommand::SurfaceEditCommand(Document& document, int surfaceIndex,
                                       model::CompositeSurface before,
                                       model::CompositeSurface after, Changes changes,
                                       const QString& text)
    : QUndoCommand(text), m_document(document),
      m_surfaceId(document.project().surfaces.at(static_cast<std::size_t>(surfaceIndex)).id()),
      m_before(std::move(before)), m_after(std::move(after)), m_changes(changes) {}

void SurfaceEditCommand::redo() {
    apply(m_after);
}

void SurfaceEditCommand::undo() {
    apply(m_before);
}

int SurfaceEditCommand::surfaceIndex() const {
    return m_document.project().indexOf(m_surfaceId);
}

void SurfaceEditCommand::apply(const model::CompositeSurface& surface) {
    // The undo stack is cleared whenever the project is replaced, and a surface is only ever
    // removed by a command on the same stack, so the surface exists when this runs.
    const int index = surfaceIndex();
    model::CompositeSurface& target =
        m_document.mutableProject().surfaces.at(static_cast<std::size_t>(index));
    target = surface;
    target.setId(m_surfaceId);
    m_document.notifyChanged(m_changes, index);
}

void SurfaceEditCommand::setAfter(model::CompositeSurface after, Changes changes) {
    m_after = std::move(after);
    m_changes |= changes;
}

QString SurfaceEditCommand::checkSurfaceIndex(const Document& document, int surfaceIndex) {
    const auto count = document.project().surfaces.size();
    if (surfaceIndex < 0 || static_cast<std::size_t>(surfaceIndex) >= count) {
        return tr("There is no surface number %1 in the design.").arg(surfaceIndex + 1);
    }
    return QString();
}

CommandOrError SurfaceEditCommand::attempt(const Document& document, int surfaceIndex,
                                           const QString& refusal, const Edit& edit,
                                           const Factory& make) {
    const QString indexError = checkSurfaceIndex(document, surfaceIndex);
    if (!indexError.isEmpty()) {
        return CommandOrError(indexError);
    }
    const model::CompositeSurface& before =
        document.project().surfaces[static_cast<std::size_t>(surfaceIndex)];
    try {
        model::CompositeSurface after = edit(before);
        return CommandOrError(make(before, std::move(after)));
    } catch (const model::ModelError& e) {
        return CommandOrError(refusal, e.problem());
    } catch (const std::exception& e) {
        return CommandOrError(refusal, model::internalProblem(e.what()));
    }
}

} // namespace devsurf::document
