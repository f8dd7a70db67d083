#include "document.h"

#include <QUndoStack>

#include <algorithm>

namespace devsurf::document {

Document::Document(QObject* parent) : QObject(parent), m_undoStack(new QUndoStack(this)) {
    connect(m_undoStack, &QUndoStack::cleanChanged, this,
            [this](bool clean) { emit modifiedChanged(!clean); });
}

Document::~Document() = default;

void Document::setFilePath(const QString& path) {
    if (path != m_filePath) {
        m_filePath = path;
        emit filePathChanged(path);
    }
}

bool Document::isModified() const {
    return !m_undoStack->isClean();
}

void Document::markSaved() {
    m_undoStack->setClean();
}

void Document::resetProject(model::Project project, const QString& filePath) {
    m_undoStack->clear();
    m_project = std::move(project);
    m_project.assignSurfaceIds(); // commands address surfaces by id
    ++m_revision;
    m_allSurfacesRevision = m_revision;
    m_surfaceRevisions.clear();
    m_changedSurface = -1;
    setFilePath(filePath);
    emit projectReset();
    emit changed(Change::Everything);
    emit modifiedChanged(false);
}

quint64 Document::surfaceRevision(int index) const {
    const auto it = m_surfaceRevisions.find(surface(index).id());
    return it == m_surfaceRevisions.end() ? m_allSurfacesRevision
                                          : std::max(it->second, m_allSurfacesRevision);
}

void Document::previewSurface(int index, const model::CompositeSurface& surface) {
    model::CompositeSurface& target = m_project.surfaces.at(static_cast<std::size_t>(index));
    const model::SurfaceId id = target.id();
    target = surface;
    target.setId(id);
    notifyChanged(Change::Geometry, index);
}

void Document::notifyChanged(Changes changes, int surfaceIndex) {
    ++m_revision;
    if ((changes & ~Changes(Change::ReferenceCurves | Change::ReferenceShapes)) == Changes()) {
        // No surface changed: their caches of derived geometry stay valid.
        m_changedSurface = -1;
        emit changed(changes);
        return;
    }
    if (surfaceIndex >= 0 && surfaceIndex < surfaceCount()) {
        m_surfaceRevisions[surface(surfaceIndex).id()] = m_revision;
        m_changedSurface = surfaceIndex;
    } else {
        m_allSurfacesRevision = m_revision;
        m_surfaceRevisions.clear();
        m_changedSurface = -1;
    }
    emit changed(changes);
}

} // namespace devsurf::document
