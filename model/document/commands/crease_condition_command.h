#pragma once

#include "surface_edit_command.h"

#include <set>

namespace devsurf::document {

// Sets the condition of creases (curved fold, geodesic, straight when unfolded, or none),
// which the solver then imposes. Refused, with a sentence naming the edge, when no edge is
// given, an edge does not exist or is not a crease (a ruling, or a curve on the boundary), or
// every edge already has the condition.
class CreaseConditionCommand : public SurfaceEditCommand {
    Q_DECLARE_TR_FUNCTIONS(CreaseConditionCommand)
public:
    static CommandOrError create(Document& document, int surfaceIndex,
                                 const std::set<model::EdgeId>& edges,
                                 model::CreaseCondition condition);

    // The condition's name as the application shows it ("Curved fold", …).
    static QString conditionText(model::CreaseCondition condition);

private:
    using SurfaceEditCommand::SurfaceEditCommand;
};

} // namespace devsurf::document
