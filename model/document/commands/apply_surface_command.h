#pragma once

#include "surface_edit_command.h"

namespace devsurf::document {

// Replaces one surface by a given one: what the solver uses to apply its result. A drag is one
// command: push with the same non-negative mergeKey (e.g. a drag counter) for every solver
// result of the drag; consecutive commands with that key merge, keeping the state at mouse press
// as "before" and the latest solved state as "after".
class ApplySurfaceCommand : public SurfaceEditCommand {
    Q_DECLARE_TR_FUNCTIONS(ApplySurfaceCommand)
public:
    // Refused if there is no such surface or newSurface does not validate.
    static CommandOrError create(Document& document, int surfaceIndex,
                                 model::CompositeSurface newSurface, const QString& text,
                                 Changes changes = Change::Geometry, int mergeKey = -1);

    int id() const override;
    bool mergeWith(const QUndoCommand* other) override;
    int mergeKey() const { return m_mergeKey; }

private:
    ApplySurfaceCommand(Document& document, int surfaceIndex, model::CompositeSurface before,
                        model::CompositeSurface after, Changes changes, const QString& text,
                        int mergeKey);

    int m_mergeKey;
};

} // namespace devsurf::document
