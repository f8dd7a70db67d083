#pragma once

#include "surface_edit_command.h"

namespace devsurf::document {

// Removes the ruling between two strips and merges them into one strip whose curves join
// theirs (model::mergeStrips; §4.2, "merge two strips by joining their control sequences"):
// exact for two pieces of one strip (as Add Ruling splits it), the nearest spline of the
// joined space otherwise. One undo step; refused with the model's reason for a ruling that is
// not between two SRSR strips of its own.
class MergeStripsCommand : public SurfaceEditCommand {
    Q_DECLARE_TR_FUNCTIONS(MergeStripsCommand)
public:
    static CommandOrError create(Document& document, int surfaceIndex, model::EdgeId ruling);

private:
    using SurfaceEditCommand::SurfaceEditCommand;
};

} // namespace devsurf::document
