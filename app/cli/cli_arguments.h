#pragma once

// The parsed arguments of the subcommands that compute (solve, drag): plain structs, so the
// computing code reads no option text.

#include "command_line.h"

#include "model/ids.h"
#include "model/topology_edits.h"
#include "solver/session/drag_lengths.h"

#include <optional>
#include <string>
#include <vector>

namespace devsurf::app {

struct SolveArguments {
    std::string input;
    std::string output;
    std::optional<int> iterations; // a limit; unset: Tools ▸ Solve's (30, stops at 1e-12)
    std::optional<double> perturb; // SIGMA times the surface's diameter
    unsigned seed = 1;
    std::vector<model::VertexId> fixed;
};

// The motion of a drag: a translation by `by` or a rotation by `radians` about `axis` through
// `point`.
struct DragMotion {
    bool rotate = false;
    model::Vec3 by;
    model::Vec3 point;
    model::Vec3 axis;
    double radians = 0.0;
    // The motion at parameter t in [0, 1] of the drag (t times the translation or angle).
    model::RigidMotion at(double t) const;
};

struct DragArguments {
    std::string input;
    std::string output;
    std::vector<model::VertexId> vertices; // empty for a crease drag
    std::optional<model::EdgeId> crease;
    DragMotion motion;
    int steps = 20;
    std::vector<model::VertexId> pins;
    std::optional<int> after; // iterations after the moves; the job's default when absent
    solver::DragLengths lengths = solver::DragLengths::Automatic;
    int surface = 0; // 1-based; 0: the first
};

// Throw UsageError.
SolveArguments solveArguments(const SubcommandArguments& args);
DragArguments dragArguments(const SubcommandArguments& args);

} // namespace devsurf::app
