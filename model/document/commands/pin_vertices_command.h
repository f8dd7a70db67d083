#pragma once

#include "surface_edit_command.h"

#include <set>

namespace devsurf::document {

// Pins vertices (the solver never moves them, in solves and drags alike) or releases them.
// Refused when no vertex is given, a vertex does not exist, or every vertex already is in the
// requested state.
class PinVerticesCommand : public SurfaceEditCommand {
    Q_DECLARE_TR_FUNCTIONS(PinVerticesCommand)
public:
    static CommandOrError create(Document& document, int surfaceIndex,
                                 const std::set<model::VertexId>& vertices, bool pin);

private:
    using SurfaceEditCommand::SurfaceEditCommand;
};

} // namespace devsurf::document
