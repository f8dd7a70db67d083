#pragma once

#include "surface_edit_command.h"

namespace devsurf::document {

// Replaces one surface by a given one: what the solver uses to apply its result. Consecutive
// commands with the same non-negative mergeKey merge, keeping the first "before" and the last
// "after".
class ApplySurfaceCommand : public SurfaceEditCommand {
    Q_DECLARE_TR_FUNCTIONS(ApplySurfaceCommand)
public:
    // Refused if there is no such surface or newSurface does not validate.
    static CommandOrError create(Document& document, int surfaceIndex,
                                 model::CompositeSurface newSurface, const QString& text,
                                 Changes changes = Change::Geometry, int mergeKey = -1);
    // As create(), for a surface already validated off this thread (a solve job's outcome):
    // validating a large design takes milliseconds the GUI thread should not stall for.
    static CommandOrError createValidated(Document& document, int surfaceIndex,
                                          model::CompositeSurface newSurface, const QString& text,
                                          Changes changes = Change::Geometry, int mergeKey = -1);

    // The command of a drag whose result the document shows already (Document::previewSurface,
    // with a validated surface): undo returns `before` (the press); its first redo, when pushed,
    // changes nothing.
    static CommandOrError createShown(Document& document, int surfaceIndex,
                                      model::CompositeSurface before, const QString& text);

    void redo() override;
    int id() const override;
    bool mergeWith(const QUndoCommand* other) override;
    int mergeKey() const { return m_mergeKey; }

private:
    ApplySurfaceCommand(Document& document, int surfaceIndex, model::CompositeSurface before,
                        model::CompositeSurface after, Changes changes, const QString& text,
                        int mergeKey);

    int m_mergeKey;
    bool m_shown = false; // the document shows `after` until the first redo
};

} // namespace devsurf::document
