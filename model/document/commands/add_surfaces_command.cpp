#include "add_surfaces_command.h"

#include "model/document/change_flags.h"

#include <cstddef>
#include <utility>

namespace devsurf::document {

AddSurfacesCommand::AddSurfacesCommand(Document& document,
                                       std::vector<model::CompositeSurface> surfaces,
                                       const QString& text)
    : QUndoCommand(text), m_document(document), m_surfaces(std::move(surfaces)) {}

CommandOrError AddSurfacesCommand::create(Document& document,
                                          std::vector<model::CompositeSurface> surfaces,
                                          const QString& text) {
    if (surfaces.empty()) {
        return CommandOrError(tr("There is no surface to add."));
    }
    for (const model::CompositeSurface& surface : surfaces) {
        const std::vector<model::Problem> problems = surface.validate();
        if (!problems.empty()) {
            return CommandOrError(tr("A surface to add is not valid."), problems.front());
        }
    }
    return CommandOrError(
        std::unique_ptr<QUndoCommand>(new AddSurfacesCommand(document, std::move(surfaces), text)));
}

void AddSurfacesCommand::redo() {
    model::Project& project = m_document.mutableProject();
    if (!m_numbered) {
        // The first time: new ids, kept for every later redo.
        for (model::CompositeSurface& surface : m_surfaces) {
            surface.setId(project.addSurface(surface));
        }
        m_numbered = true;
    } else {
        project.surfaces.insert(project.surfaces.end(), m_surfaces.begin(), m_surfaces.end());
    }
    m_document.notifyChanged(Change::Topology | Change::Geometry | Change::Labels);
}

void AddSurfacesCommand::undo() {
    // The surfaces redo appended are the last: the commands after it were undone first.
    std::vector<model::CompositeSurface>& surfaces = m_document.mutableProject().surfaces;
    surfaces.erase(surfaces.end() - static_cast<std::ptrdiff_t>(m_surfaces.size()), surfaces.end());
    m_document.notifyChanged(Change::Topology | Change::Geometry | Change::Labels);
}

} // namespace devsurf::document
