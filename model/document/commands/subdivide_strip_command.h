#pragma once

#include "surface_edit_command.h"

namespace devsurf::document {

// Cuts a strip by a new crease c = (1−t) a + t b between its curves a and b (model::
// subdivideStrip: a is stripOfFace(face).a); the cut runs across the whole row of SRSR strips
// joined through rulings, and the geometry is unchanged. Refused (with a sentence naming the
// face) for a face that is not an SRSR strip, for t outside (0, 1), and where the row meets an
// SRS strip or a cone across a ruling.
class SubdivideStripCommand : public SurfaceEditCommand {
    Q_DECLARE_TR_FUNCTIONS(SubdivideStripCommand)
public:
    static CommandOrError create(Document& document, int surfaceIndex, model::FaceId face,
                                 double t);

private:
    using SurfaceEditCommand::SurfaceEditCommand;
};

} // namespace devsurf::document
