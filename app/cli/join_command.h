#pragma once

#include "command_line.h"
#include "model/composite_surface.h"
#include "model/reference/thinning.h"
#include "solver/session/solve_job.h"

#include <memory>
#include <optional>
#include <vector>

namespace devsurf::app {

// One iteration's line of a solve the command line prints (residual and timings).
void printIterationLine(const solver::JobProgress& step);

// The Join job (solver/session/join_job.h) on `surfaces` (at least two), pulled towards
// `target` where given, with its lines printed: the stages, the pairs of facing edges, the
// welds refused, the result. The joined surface, or none when no two surfaces face each other
// (said); `joined`, where given, gets the indices of the surfaces it joined (the others face
// none). Throws InputError when the solver stops.
std::optional<model::CompositeSurface>
joinSurfaces(const std::vector<model::CompositeSurface>& surfaces,
             std::shared_ptr<const model::reference::ThinningResult> target, double rho,
             std::optional<int> iterations, solver::SolveJob& job,
             std::vector<int>* joined = nullptr);

// `devsurf-cli join FILE [--surfaces IDS] [--iterations N] -o OUT`: the surfaces (numbers
// from 1; all by default) joined into one composite where their boundary edges face each
// other, pulled towards the project's reference shapes where it has them; the joined surface
// takes the place of the first. Returns the exit code.
int runJoinCommand(const SubcommandArguments& args);

} // namespace devsurf::app
