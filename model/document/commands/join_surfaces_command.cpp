#include "join_surfaces_command.h"

#include "model/document/change_flags.h"
#include "model/strip_joining.h"

#include <algorithm>
#include <cstddef>
#include <utility>

namespace devsurf::document {

JoinSurfacesCommand::JoinSurfacesCommand(Document& document, std::vector<int> indices,
                                         model::CompositeSurface joined, const QString& text)
    : QUndoCommand(text), m_document(document), m_indices(std::move(indices)),
      m_joined(std::move(joined)) {
    for (int index : m_indices) {
        m_originals.push_back(document.surface(index));
    }
}

CommandOrError JoinSurfacesCommand::create(Document& document, std::vector<int> indices,
                                           model::CompositeSurface joined, const QString& text) {
    std::sort(indices.begin(), indices.end());
    const bool distinct = std::adjacent_find(indices.begin(), indices.end()) == indices.end();
    if (indices.size() < 2 || !distinct || indices.front() < 0 ||
        indices.back() >= document.surfaceCount()) {
        return CommandOrError(tr("Choose at least two surfaces of the design to join."));
    }
    const std::vector<model::Problem> problems = joined.validate();
    if (!problems.empty()) {
        return CommandOrError(tr("The joined surface is not valid."), problems.front());
    }
    return CommandOrError(std::unique_ptr<QUndoCommand>(
        new JoinSurfacesCommand(document, std::move(indices), std::move(joined), text)));
}

void JoinSurfacesCommand::redo() {
    std::vector<model::CompositeSurface>& surfaces = m_document.mutableProject().surfaces;
    surfaces = model::replaceByJoined(surfaces, m_indices, m_joined);
    m_document.notifyChanged(Change::Topology | Change::Geometry | Change::Labels);
}

void JoinSurfacesCommand::undo() {
    std::vector<model::CompositeSurface>& surfaces = m_document.mutableProject().surfaces;
    surfaces.erase(surfaces.begin() + m_indices.front());
    for (std::size_t i = 0; i < m_indices.size(); ++i) {
        surfaces.insert(surfaces.begin() + m_indices[i], m_originals[i]);
    }
    m_document.notifyChanged(Change::Topology | Change::Geometry | Change::Labels);
}

} // namespace devsurf::document
