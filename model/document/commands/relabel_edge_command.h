#pragma once

#include "surface_edit_command.h"

#include <utility>
#include <vector>

namespace devsurf::document {

// Relabels edges R↔S (model::relabelEdges): an edge that becomes S gets a straight control
// sequence in the spline space of the S-edges it will share a face with; an edge that becomes R
// drops its control points. Refused, with validate()'s sentence naming the face, when the result
// would be an invalid labelling, or when an edge already has the requested label.
class RelabelEdgeCommand : public SurfaceEditCommand {
    Q_DECLARE_TR_FUNCTIONS(RelabelEdgeCommand)
public:
    static CommandOrError create(Document& document, int surfaceIndex, model::EdgeId edge,
                                 model::EdgeLabel label);
    // Several edges in one step, validated together (e.g. two opposite sides of a planar
    // quadrilateral that becomes an SRSR strip).
    static CommandOrError
    create(Document& document, int surfaceIndex,
           const std::vector<std::pair<model::EdgeId, model::EdgeLabel>>& labels);

private:
    using SurfaceEditCommand::SurfaceEditCommand;
};

} // namespace devsurf::document
