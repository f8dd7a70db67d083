#pragma once

#include "command_or_error.h"
#include "model/composite_surface.h"
#include "model/document/document.h"

#include <QCoreApplication>
#include <QUndoCommand>

#include <vector>

namespace devsurf::document {

// Replaces several surfaces of the design by the one surface they were joined into (Tools ▸
// Join Surfaces), one undo step. The joined surface takes the place and the id of the first of
// them; undo puts the originals back where they were, so undo and redo restore the project bit
// for bit.
class JoinSurfacesCommand : public QUndoCommand {
    Q_DECLARE_TR_FUNCTIONS(JoinSurfacesCommand)
public:
    // `indices`: the surfaces joined (at least two, each once, in range); refused otherwise,
    // or when `joined` does not validate.
    static CommandOrError create(Document& document, std::vector<int> indices,
                                 model::CompositeSurface joined, const QString& text);

    void redo() override;
    void undo() override;

private:
    JoinSurfacesCommand(Document& document, std::vector<int> indices,
                        model::CompositeSurface joined, const QString& text);

    Document& m_document;
    std::vector<int> m_indices; // ascending
    std::vector<model::CompositeSurface> m_originals;
    model::CompositeSurface m_joined;
};

} // namespace devsurf::document
