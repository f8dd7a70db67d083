#include "drag_command.h"

#include "cli_output.h"
#include "io/project_file.h"
#include "model/model_error.h"
#include "outcome_text.h"
#include "sheet_text.h"
#include "solver/quality/quality_measures.h"
#include "solver/session/crease_drag.h"
#include "solver/session/solve_job.h"
#include "solver/session/verdict.h"

#include <QString>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <stdexcept>

namespace devsurf::app {

namespace {

std::string idList(const std::vector<model::VertexId>& ids) {
    std::string text;
    for (model::VertexId id : ids) {
        text += (text.empty() ? "" : ", ") + std::to_string(id);
    }
    return text;
}

void printStep(const char* label, int index, int count, const solver::IterationStats& stats,
               const model::CompositeSurface& surface) {
    const solver::QualityMeasures quality = solver::measureQuality(surface);
    char line[512];
    // A move of a large model may solve with an earlier move's factorisation
    // (solver::kDragFactorizationReuse), or undo such a step (Options::reusedStepMeritRise).
    std::snprintf(line, sizeof line, "%s %3d/%d  residual %.3e  time %.3f ms  %s%s\n", label, index,
                  count, stats.maxConstraintResidual,
                  stats.assemblyMs + stats.factorizationMs + stats.solveMs,
                  stats.factorizationReused ? "(factorisation reused)  "
                  : stats.reuseUndone       ? "(reused factorisation undone)  "
                                            : "",
                  describeQuality(quality).c_str());
    std::cout << line;
}

void printFoldAndShape(const solver::SurfaceAssessment& assessment) {
    const solver::CreaseQuality& creases = assessment.creases;
    char line[640];
    std::snprintf(line, sizeof line,
                  "Creases: %d with a condition, residual max %.2e mean %.2e; mean |fold angle| "
                  "%.2f deg; angle defect at %d interior crease vertices max %.2e rad. Shortest "
                  "ruling %.2f of its start length, slowest curve speed %.2f of its mean.\n",
                  creases.creases, creases.residualMax, creases.residualMean,
                  creases.meanFoldDegrees, assessment.vertexStars, assessment.largestVertexDefect,
                  assessment.shortestRuling, assessment.slowestSpeed);
    std::cout << line << describeFoldOvers(assessment.foldOvers) << "\n"
              << describeSelfOverlap(assessment.overlapping) << "\n";
    if (assessment.sheetStretchMm >= 0.0) {
        const double limit = solver::kKeptSheetTolerance * std::max(assessment.sheetExtent, 1.0);
        std::snprintf(line, sizeof line,
                      "Distance from the sheet it keeps: %.2g mm (at most %.2g mm counts as "
                      "kept).\n",
                      assessment.sheetStretchMm, limit);
        std::cout << line;
    }
}

} // namespace

int runDragCommand(const DragArguments& args) {
    const bool crease = args.crease.has_value();
    const std::vector<model::VertexId>& dragged = args.vertices;
    const model::EdgeId creaseEdge = crease ? *args.crease : model::kInvalidId;
    const DragMotion& motion = args.motion;
    const std::vector<model::VertexId>& pins = args.pins;
    const int steps = args.steps;
    const std::string& output = args.output;

    const std::string& path = args.input;
    model::Project project = io::loadProjectFile(QString::fromStdString(path));
    if (project.surfaces.empty()) {
        throw InputError("'" + path + "' has no surface to drag.");
    }
    const std::size_t index = surfaceIndex(args.surface, project, "drag");
    model::CompositeSurface& surface = project.surfaces[index];
    const solver::DragLengths lengths = args.lengths;
    const bool givenAfter = args.after.has_value();
    const int givenAfterCount = args.after.value_or(0);

    std::vector<model::VertexId> unknown;
    std::vector<model::VertexId> mentioned = dragged;
    mentioned.insert(mentioned.end(), pins.begin(), pins.end());
    for (model::VertexId id : mentioned) {
        if (!surface.hasVertex(id)) {
            unknown.push_back(id);
        }
    }
    if (!unknown.empty()) {
        throw InputError("surface '" + surface.name() + "' has no vertex " + idList(unknown) +
                         " (list them with 'devsurf-cli info FILE --vertices').");
    }
    std::vector<model::VertexId> pinnedDragged;
    for (model::VertexId id : dragged) {
        if (surface.isPinned(id)) {
            pinnedDragged.push_back(id);
        }
    }
    if (!pinnedDragged.empty()) {
        throw InputError("vertex " + idList(pinnedDragged) + " of surface '" + surface.name() +
                         "' is pinned and cannot be dragged.");
    }
    for (model::VertexId id : pins) {
        surface.setPinned(id, true);
    }

    // The vertices' positions at the press, and a handle on each pulled there (for a crease:
    // its unpinned ends and interior control points, sliding within the surface).
    std::map<model::VertexId, model::Vec3> start;
    std::vector<solver::VertexHandle> pulled;
    std::vector<solver::ControlPointHandle> points;
    std::unique_ptr<solver::CreaseDrag> creaseDrag;
    try {
        if (crease) {
            creaseDrag = std::make_unique<solver::CreaseDrag>(surface, creaseEdge);
            pulled = creaseDrag->vertexHandles({}, true);
            points = creaseDrag->controlPointHandles({}, true);
            for (const solver::VertexHandle& handle : pulled) {
                start[handle.vertex] = handle.target;
            }
        }
    } catch (const solver::CreaseDragRefused& refused) {
        throw InputError("surface " + std::to_string(index + 1) + " of '" + path +
                         "' cannot be dragged: " + describeCreaseRefusal(refused));
    } catch (const std::invalid_argument& error) {
        throw InputError("surface " + std::to_string(index + 1) + " of '" + path +
                         "' cannot be dragged: " + error.what());
    }
    for (model::VertexId id : std::set<model::VertexId>(dragged.begin(), dragged.end())) {
        start[id] = surface.position(id);
        pulled.push_back({id, false, surface.position(id)});
    }
    // Where the handles are at parameter t of the motion (a crease's points each move along
    // their own direction, see CreaseDrag).
    std::map<model::VertexId, model::Vec3> creaseShift;
    std::vector<model::Vec3> pointShift; // per control point of the crease, ends included
    if (creaseDrag) {
        for (const solver::VertexHandle& handle : creaseDrag->vertexHandles(motion.by, true)) {
            creaseShift[handle.vertex] = handle.target - start.at(handle.vertex);
        }
        pointShift = creaseDrag->pointDisplacements(motion.by, true);
    }
    auto targetAt = [&](model::VertexId id, const model::Vec3& position, double t) {
        return creaseDrag ? position + creaseShift.at(id) * t : motion.at(t).apply(position);
    };
    auto pointTargetAt = [&](const solver::ControlPointHandle& point, double t) {
        return point.target + pointShift.at(static_cast<std::size_t>(point.index)) * t;
    };
    if (creaseDrag) {
        const model::Vec3 d = creaseDrag->displacement(motion.by, true);
        char line[200];
        std::snprintf(line, sizeof line,
                      "Crease %u slides by %.3f,%.3f,%.3f within the surface (%zu control points "
                      "and %zu end vertices pulled).\n",
                      creaseEdge, d.x, d.y, d.z, points.size(), pulled.size());
        std::cout << line;
    }

    // The drag as the desktop application's Drag and Rotate tools run it: the same solve job,
    // one request per step (one iteration each), then the release.
    solver::JobRequest request;
    request.kind = crease          ? solver::JobKind::CreaseDrag
                   : motion.rotate ? solver::JobKind::Rotate
                                   : solver::JobKind::VertexDrag;
    request.drag = 1;
    request.lengths = lengths;
    request.surfaces = project.surfaces;
    auto setTargets = [&](double t) {
        std::vector<solver::VertexHandle>& handles = request.pulled[static_cast<int>(index)];
        handles.clear();
        for (const auto& [id, position] : start) {
            handles.push_back({id, false, targetAt(id, position, t)});
        }
        if (creaseDrag) {
            std::vector<solver::ControlPointHandle>& moved =
                request.pulledControlPoints[static_cast<int>(index)];
            moved = points;
            for (solver::ControlPointHandle& point : moved) {
                point.target = pointTargetAt(point, t);
            }
        }
    };
    const bool keepLengths = !crease && lengths != solver::DragLengths::Stretch;
    const int after =
        givenAfter
            ? givenAfterCount
            : solver::iterationsAfterDrag(keepLengths, !crease && surface.keepsDevelopment());
    std::cout << "Surface " << index + 1 << " (" << surface.name() << "): dragging "
              << (crease ? "crease " + std::to_string(creaseEdge)
                         : std::to_string(start.size()) +
                               (start.size() == 1 ? " vertex" : " vertices"))
              << (keepLengths ? " keeping lengths" : "") << " in " << steps << " steps, then "
              << after << " iterations; " << surface.pinnedVertices().size() << " pinned\n";

    solver::SolveJob job;
    const char* label = "step";
    int labelIndex = 0;
    int labelCount = steps;
    auto progress = [&](const solver::JobProgress& step) {
        if (step.replaying || step.followingPartway) {
            char line[160];
            std::snprintf(line, sizeof line, "%s %3d  residual %.3e\n",
                          step.replaying ? "replay" : "partway", step.done,
                          step.stats->maxConstraintResidual);
            std::cout << line;
            return;
        }
        printStep(label, labelIndex + step.done, labelCount, *step.stats, *step.current);
    };
    // Runs one request; a failure ends the command (nothing is written).
    auto run = [&](const char* what) {
        solver::JobOutcome outcome = job.run(request, nullptr, progress);
        if (!outcome.ok) {
            throw InputError(std::string("the solver stopped at ") + what + " (" +
                             describeFailure(outcome.failure) + "); nothing was written.");
        }
        const solver::SurfaceAssessment& assessment = outcome.assessments.at(index);
        const solver::Summary& summary = assessment.summary;
        if (summary.status == solver::Status::StoppedBeforeDegenerate) {
            std::cout << "At " << label << " " << labelIndex + summary.iterationsCompleted + 1
                      << ": stopped at the last valid state" << refusedText(assessment) << "\n";
        }
        return outcome;
    };
    for (int k = 1; k <= steps; ++k) {
        labelIndex = k - 1;
        setTargets(static_cast<double>(k) / steps);
        run("a step");
    }
    label = "after";
    labelIndex = 0;
    labelCount = after;
    request.settle = true;
    request.iterations = after;
    const solver::JobOutcome outcome = run("the release");
    const solver::SurfaceAssessment& assessment = outcome.assessments.at(index);
    if (assessment.held) {
        std::cout << describeHeld(*assessment.held) << "\n";
    }
    if (assessment.settledAgain) {
        std::cout << "Settled again: the iterations after the release did not converge, so the "
                     "last state of the moves was settled once more, the keep-lengths energy "
                     "fading more slowly (the \"after\" lines past "
                  << assessment.firstSettlingIterations << ").\n";
    }
    if (assessment.stalledAfter > 0) {
        std::cout << "Stalled: the iterations after the release stopped after "
                  << assessment.stalledAfter
                  << ", their residual no longer falling (more would not have brought it nearer "
                     "the tolerance).\n";
    }
    if (assessment.replay) {
        const solver::LengthsReplay& replay = *assessment.replay;
        const int before = replay.keepingLengths.problems();
        const int now = replay.stretching.problems();
        std::cout << "Keeping lengths, the drag " << describeOutcome(replay.keepingLengths)
                  << "; replayed letting the sheet stretch.\n"
                  << "Letting the sheet stretch, the drag " << describeOutcome(replay.stretching)
                  << ": " << (replay.taken ? "taken" : "not taken") << " (" << now
                  << (now == 1 ? " problem" : " problems") << " against " << before << ").\n";
    }
    if (assessment.takenBack && assessment.followed > 0.0) {
        char share[160];
        std::snprintf(share, sizeof share,
                      "Held back: the surface follows %.0f %% of the drag (the dragged points "
                      "are %.1f mm from their targets), since the whole drag ",
                      100.0 * assessment.followed, assessment.largestHandleGap);
        std::cout << share << describeTakenBack(*assessment.takenBack)
                  << "; it stays at its last developable state.\n";
    } else if (assessment.takenBack) {
        const solver::SurfaceAssessment& refused = *assessment.takenBack;
        std::cout << "Taken back: the drag " << describeTakenBack(refused)
                  << ", so the surface stays as it was before the drag (its last developable "
                     "state)"
                  << (refused.sheetHeld && refused.largestHandleGap > solver::kNegligibleLag
                          ? "; where the sheet cannot follow, drag less far"
                          : "")
                  << ".\n";
    }
    const solver::Summary& last = assessment.summary;
    char line[256];
    if (assessment.takenBack && assessment.followed == 0.0) {
        std::snprintf(line, sizeof line,
                      "As before the drag: largest sampled developability residual %.2e.\n",
                      last.finalMaxConstraintResidual);
    } else if (last.iterations.empty()) {
        std::snprintf(line, sizeof line,
                      "No iteration completed; dragged points within %.3g of their targets.\n",
                      assessment.largestHandleGap);
    } else {
        std::snprintf(line, sizeof line,
                      "Largest residual %.2e (tolerance %.1e %s); dragged points within %.3g of "
                      "their targets.\n",
                      last.finalMaxConstraintResidual, last.tolerance,
                      last.toleranceReached ? "reached" : "not reached",
                      assessment.largestHandleGap);
    }
    std::cout << line;
    if (assessment.sheetHeld && !assessment.takenBack &&
        assessment.largestHandleGap > solver::kNegligibleLag) {
        std::snprintf(line, sizeof line,
                      "The sheet is kept: the dragged points are held back %.1f mm by it.\n",
                      assessment.largestHandleGap);
        std::cout << line;
    }
    if (!assessment.tautPins.empty()) {
        QString why = SheetText::tautPins(assessment.tautPins.front().first,
                                          assessment.tautPins.front().second);
        why[0] = why[0].toUpper();
        std::cout << why.toStdString() << ".\n";
    }
    printFoldAndShape(assessment);
    surface = outcome.surfaces.at(index);
    writeProject(project, output);
    std::cout << "Wrote " << output << "\n";
    return 0;
}

} // namespace devsurf::app
