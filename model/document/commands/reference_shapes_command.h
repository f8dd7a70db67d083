#pragma once

#include "command_or_error.h"
#include "model/document/document.h"
#include "model/reference_shape.h"

#include <QCoreApplication>
#include <QUndoCommand>

#include <vector>

namespace devsurf::document {

// Adds one reference shape or removes them all. A shape may hold millions of points, so the
// command never copies one: it moves the shapes between the project and itself (redo and undo
// swap them back), which restores the project bit for bit and keeps a shape's storage, and so
// the views' caches of it, where it was.
class ReferenceShapesCommand : public QUndoCommand {
    Q_DECLARE_TR_FUNCTIONS(ReferenceShapesCommand)
public:
    // Appends the shape (one undo step). Refused when it has no point, a coordinate that is
    // not finite, or a triangle naming a point it does not have.
    static CommandOrError createImport(Document& document, model::ReferenceShape shape);
    // Removes every reference shape; refused when there is none.
    static CommandOrError createRemoveAll(Document& document);

    void redo() override;
    void undo() override;

private:
    enum class Kind { Import, RemoveAll };
    ReferenceShapesCommand(Document& document, Kind kind, std::vector<model::ReferenceShape> held,
                           const QString& text);
    void notify();

    Document& m_document;
    Kind m_kind;
    // Import: the shape while it is not in the project (before redo, after undo). RemoveAll:
    // the shapes while they are not in the project (after redo).
    std::vector<model::ReferenceShape> m_held;
};

// Whether a shape can be shown and stored: at least one point, every coordinate finite, every
// triangle naming three of its points.
bool isUsableReferenceShape(const model::ReferenceShape& shape);

} // namespace devsurf::document
