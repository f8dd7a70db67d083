#include "reference_shapes_command.h"

#include "model/document/change_flags.h"

#include <cmath>
#include <utility>

namespace devsurf::document {

bool isUsableReferenceShape(const model::ReferenceShape& shape) {
    if (shape.points.empty() ||
        (!shape.normals.empty() && shape.normals.size() != shape.points.size())) {
        return false;
    }
    for (const model::Vec3& p : shape.points) {
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) {
            return false;
        }
    }
    const auto count = static_cast<long long>(shape.points.size());
    for (const std::array<int, 3>& triangle : shape.triangles) {
        for (int index : triangle) {
            if (index < 0 || index >= count) {
                return false;
            }
        }
    }
    return true;
}

ReferenceShapesCommand::ReferenceShapesCommand(Document& document, Kind kind,
                                               std::vector<model::ReferenceShape> held,
                                               const QString& text)
    : QUndoCommand(text), m_document(document), m_kind(kind), m_held(std::move(held)) {}

CommandOrError ReferenceShapesCommand::createImport(Document& document,
                                                    model::ReferenceShape shape) {
    if (!isUsableReferenceShape(shape)) {
        return CommandOrError(tr("The shape to import has no points, a coordinate that is not "
                                 "a number or a triangle naming a point it does not have."));
    }
    std::vector<model::ReferenceShape> held;
    held.push_back(std::move(shape));
    return CommandOrError(std::unique_ptr<QUndoCommand>(new ReferenceShapesCommand(
        document, Kind::Import, std::move(held), tr("Import Reference Shape"))));
}

CommandOrError ReferenceShapesCommand::createRemoveAll(Document& document) {
    if (document.project().referenceShapes.empty()) {
        return CommandOrError(tr("The design has no reference shapes."));
    }
    return CommandOrError(std::unique_ptr<QUndoCommand>(
        new ReferenceShapesCommand(document, Kind::RemoveAll, {}, tr("Remove Reference Shapes"))));
}

void ReferenceShapesCommand::redo() {
    std::vector<model::ReferenceShape>& shapes = m_document.mutableProject().referenceShapes;
    if (m_kind == Kind::Import) {
        shapes.push_back(std::move(m_held.back()));
        m_held.clear();
    } else {
        m_held.swap(shapes);
    }
    notify();
}

void ReferenceShapesCommand::undo() {
    std::vector<model::ReferenceShape>& shapes = m_document.mutableProject().referenceShapes;
    if (m_kind == Kind::Import) {
        // The shape redo appended is the last: the commands after it were undone first.
        m_held.push_back(std::move(shapes.back()));
        shapes.pop_back();
    } else {
        m_held.swap(shapes);
    }
    notify();
}

void ReferenceShapesCommand::notify() {
    m_document.notifyChanged(Change::ReferenceShapes);
}

} // namespace devsurf::document
