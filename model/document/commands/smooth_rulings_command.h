#pragma once

#include "surface_edit_command.h"

#include <set>

namespace devsurf::document {

// Marks rulings (R-edges between two patches) smooth, so that the solver keeps the surface
// smooth across them, or sharp, so that it may fold there. Refused, with a sentence naming the
// edge, when no edge is given, an edge does not exist or is not a ruling between two patches
// (a curve, or a ruling on the boundary), or every edge already has the flag.
class SmoothRulingsCommand : public SurfaceEditCommand {
    Q_DECLARE_TR_FUNCTIONS(SmoothRulingsCommand)
public:
    static CommandOrError create(Document& document, int surfaceIndex,
                                 const std::set<model::EdgeId>& edges, bool smooth);

private:
    using SurfaceEditCommand::SurfaceEditCommand;
};

} // namespace devsurf::document
