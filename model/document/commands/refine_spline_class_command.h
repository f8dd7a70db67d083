#pragma once

#include "surface_edit_command.h"

namespace devsurf::document {

// "Refine curves": every S-edge of the spline class of `edge` goes from n to factor·n intervals
// by knot insertion (model::refineSplineClass); the geometry is unchanged.
class RefineSplineClassCommand : public SurfaceEditCommand {
    Q_DECLARE_TR_FUNCTIONS(RefineSplineClassCommand)
public:
    static CommandOrError create(Document& document, int surfaceIndex, model::EdgeId edge,
                                 int factor = 2);

private:
    using SurfaceEditCommand::SurfaceEditCommand;
};

} // namespace devsurf::document
