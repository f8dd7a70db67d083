#pragma once

#include "command_or_error.h"
#include "model/composite_surface.h"
#include "model/document/document.h"

#include <QCoreApplication>
#include <QUndoCommand>

#include <vector>

namespace devsurf::document {

// Appends surfaces to the design, one undo step (the strips Tools ▸ Approximate Reference
// Shape… fits). Each gets a new id on the first redo, which later redos keep, so undo and redo
// restore the project bit for bit.
class AddSurfacesCommand : public QUndoCommand {
    Q_DECLARE_TR_FUNCTIONS(AddSurfacesCommand)
public:
    // Refused when there is no surface to add or one does not validate.
    static CommandOrError create(Document& document, std::vector<model::CompositeSurface> surfaces,
                                 const QString& text);

    void redo() override;
    void undo() override;

private:
    AddSurfacesCommand(Document& document, std::vector<model::CompositeSurface> surfaces,
                       const QString& text);

    Document& m_document;
    std::vector<model::CompositeSurface> m_surfaces; // as added (ids set after the first redo)
    bool m_numbered = false;
};

} // namespace devsurf::document
