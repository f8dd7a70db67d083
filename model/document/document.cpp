#include "document.h"

#include <QUndoStack>

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
    setFilePath(filePath);
    emit projectReset();
    emit changed(Change::Everything);
    emit modifiedChanged(false);
}

void Document::notifyChanged(Changes changes) {
    ++m_revision;
    emit changed(changes);
}

} // namespace devsurf::document
