#pragma once

#include "command_or_error.h"
#include "model/composite_surface.h"
#include "model/document/change_flags.h"
#include "model/document/document.h"

#include <QCoreApplication>
#include <QUndoCommand>

#include <functional>

namespace devsurf::document {

class Document;

// The base of every edit of one surface: it holds the whole surface before and after the edit
// (surfaces are small), so undo restores bit-identical state and redo applies the stored result
// without recomputing anything. The surface is addressed by its id (see model::SurfaceId), so
// that adding or removing other surfaces does not redirect the command.
class SurfaceEditCommand : public QUndoCommand {
    Q_DECLARE_TR_FUNCTIONS(SurfaceEditCommand)
public:
    SurfaceEditCommand(Document& document, int surfaceIndex, model::CompositeSurface before,
                       model::CompositeSurface after, Changes changes, const QString& text);

    void redo() override;
    void undo() override;

    // The surface's current index in the project (-1 if it is gone).
    int surfaceIndex() const;
    model::SurfaceId surfaceId() const { return m_surfaceId; }
    const model::CompositeSurface& before() const { return m_before; }
    const model::CompositeSurface& after() const { return m_after; }
    Changes changes() const { return m_changes; }

    // Empty if the project has a surface with this index, else the refusal sentence.
    static QString checkSurfaceIndex(const Document& document, int surfaceIndex);

    using Edit = std::function<model::CompositeSurface(const model::CompositeSurface&)>;
    using Factory = std::function<std::unique_ptr<QUndoCommand>(model::CompositeSurface before,
                                                                model::CompositeSurface after)>;
    // Runs edit on the document's current surface (without changing the document) and wraps
    // before and after with make; a ModelError (or any std::exception) from the edit becomes the
    // refusal "refusal: reason".
    static CommandOrError attempt(const Document& document, int surfaceIndex,
                                  const QString& refusal, const Edit& edit, const Factory& make);
    // The edit that calls set(surface, id) for every id on a copy of the surface (for the
    // commands that set one property of many entities). `ids` must outlive the edit.
    template <class Ids, class Set> static Edit forEach(const Ids& ids, Set set) {
        return [&ids, set](const model::CompositeSurface& surface) {
            model::CompositeSurface result = surface;
            for (const auto& id : ids) {
                set(result, id);
            }
            return result;
        };
    }

protected:
    // For mergeWith(): the merged command ends where the later one ended.
    void setAfter(model::CompositeSurface after, Changes changes);
    void apply(const model::CompositeSurface& surface);

private:
    Document& m_document;
    model::SurfaceId m_surfaceId;
    model::CompositeSurface m_before;
    model::CompositeSurface m_after;
    Changes m_changes;
};

} // namespace devsurf::document
