#pragma once

#include "surface_edit_command.h"

namespace devsurf::document {

// Adds a ruling to a strip or cone at the breakpoint u = breakpoint / n of its curve a(u)
// (stripOfFace(face).a, n intervals), 1 <= breakpoint <= n−1 (model::splitAtRuling). Every
// strip and cone along the curves' spline class gets the ruling at the same point; the pieces
// are uniform with i and n−i intervals and the geometry is unchanged. Positions between
// breakpoints need RefineSplineClassCommand first; a curve with one interval is refused with a
// message that says so.
class SplitAtRulingCommand : public SurfaceEditCommand {
    Q_DECLARE_TR_FUNCTIONS(SplitAtRulingCommand)
public:
    static CommandOrError create(Document& document, int surfaceIndex, model::FaceId face,
                                 int breakpoint);

    // The breakpoint index nearest to the parameter u of the face's curve a, and the number of
    // intervals n (so the interface can offer "refine" when u is far from every i/n).
    // Returns {-1, 0} for a face that is not a strip or a cone.
    static std::pair<int, int> nearestBreakpoint(const model::CompositeSurface& surface,
                                                 model::FaceId face, double u);

private:
    using SurfaceEditCommand::SurfaceEditCommand;
};

} // namespace devsurf::document
