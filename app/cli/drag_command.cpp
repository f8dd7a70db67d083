#include "drag_command.h"

#include "cli_output.h"
#include "io/project_file.h"
#include "model/held_by_pins.h"
#include "model/model_error.h"
#include "model/pattern/cutting_pattern.h"
#include "solver/quality/crease_quality.h"
#include "solver/quality/quality_measures.h"
#include "solver/quality/shape_change.h"
#include "solver/quality/vertex_stars.h"
#include "solver/session/crease_drag.h"
#include "solver/session/drag_lengths.h"
#include "solver/session/solve_session.h"

#include <QString>

#include <algorithm>
#include <chrono>
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

double elapsedMs(std::chrono::steady_clock::time_point since) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - since)
        .count();
}

void printStep(const char* label, int index, int count, const solver::Summary& summary, double ms,
               const model::CompositeSurface& surface) {
    const solver::QualityMeasures quality = solver::measureQuality(surface);
    char line[512];
    // A move of a large model may solve with the previous move's factorisation
    // (solver::kDragFactorizationReuse).
    const bool reused =
        !summary.iterations.empty() && summary.iterations.front().factorizationReused;
    std::snprintf(line, sizeof line, "%s %3d/%d  residual %.3e  time %.3f ms  %s%s\n", label, index,
                  count, summary.finalMaxConstraintResidual, ms,
                  reused ? "(factorisation reused)  " : "", quality.describe().c_str());
    std::cout << line;
}

// What a designer checks after a drag: how well the crease conditions hold and how far the
// creases fold (measured from the geometry), and whether a strip degenerated.
// What went wrong at the end of a drag (solver::judgeDrag), as the end of a sentence:
// "did not converge (residual 1.4e-04), folded over in 2 places".
std::string describeOutcome(const solver::DragOutcome& outcome) {
    std::vector<std::string> parts;
    char text[120];
    if (outcome.stopped) {
        parts.push_back("stopped before a degenerate shape");
    }
    if (outcome.residual > solver::kDragConvergedResidual) {
        std::snprintf(text, sizeof text, "did not converge (residual %.1e)", outcome.residual);
        parts.push_back(text);
    }
    if (outcome.foldOverPlaces > 0) {
        std::snprintf(text, sizeof text, "folded over in %d place%s", outcome.foldOverPlaces,
                      outcome.foldOverPlaces == 1 ? "" : "s");
        parts.push_back(text);
    }
    if (!outcome.overlapping.empty()) {
        std::snprintf(text, sizeof text, "left a development overlapping itself at %zu patch%s",
                      outcome.overlapping.size(), outcome.overlapping.size() == 1 ? "" : "es");
        parts.push_back(text);
    }
    if (outcome.collapsed()) {
        std::snprintf(text, sizeof text,
                      "collapsed strips (rulings at %.2f of their length, curve speeds at %.2f of "
                      "their mean)",
                      outcome.shortestRuling, outcome.slowestSpeed);
        parts.push_back(text);
    }
    if (!outcome.measurable) {
        parts.push_back("left a shape too degenerate to measure");
    }
    if (parts.empty()) {
        return "ended without a problem";
    }
    std::string sentence;
    for (std::size_t i = 0; i < parts.size(); ++i) {
        sentence += (i == 0 ? "" : i + 1 == parts.size() ? " and " : ", ") + parts[i];
    }
    return sentence;
}

void printFoldAndShape(const model::CompositeSurface& start,
                       const model::CompositeSurface& result) {
    const solver::CreaseQuality creases = solver::measureCreaseQuality(result);
    const solver::ShapeChange change = solver::measureShapeChange(start, result);
    double defect = 0.0;
    const auto defects = solver::vertexAngleDefects(result);
    for (const solver::VertexAngleDefect& d : defects) {
        defect = std::max(defect, d.defect);
    }
    char line[640];
    std::snprintf(line, sizeof line,
                  "Creases: %d with a condition, residual max %.2e mean %.2e; mean |fold angle| "
                  "%.2f deg; angle defect at %zu interior crease vertices max %.2e rad. Shortest "
                  "ruling %.2f of its start length, slowest curve speed %.2f of its mean.\n",
                  creases.creases, creases.residualMax, creases.residualMean,
                  creases.meanFoldDegrees, defects.size(), defect, change.shortestRuling,
                  change.slowestSpeed);
    std::cout << line << solver::describeFoldOvers(change.foldOvers) << "\n"
              << model::describeSelfOverlap(model::selfOverlappingPatches(result)) << "\n";
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
        throw model::ModelError("'" + path + "' has no surface to drag.");
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
        throw model::ModelError("surface '" + surface.name() + "' has no vertex " +
                                idList(unknown) +
                                " (list them with 'devsurf-cli info FILE --vertices').");
    }
    std::vector<model::VertexId> pinnedDragged;
    for (model::VertexId id : dragged) {
        if (surface.isPinned(id)) {
            pinnedDragged.push_back(id);
        }
    }
    if (!pinnedDragged.empty()) {
        throw model::ModelError("vertex " + idList(pinnedDragged) + " of surface '" +
                                surface.name() + "' is pinned and cannot be dragged.");
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
    } catch (const std::invalid_argument& error) {
        throw model::ModelError("surface " + std::to_string(index + 1) + " of '" + path +
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

    // Pins that hold a dragged vertex where the sheet cannot bend (e.g. the four corners of a
    // flat square): keeping lengths then cannot follow the drag, and the output says why.
    std::optional<model::HeldVertex> held;
    if (!crease && lengths != solver::DragLengths::Stretch) {
        held = model::findVertexHeldByPins(surface, dragged);
        if (held) {
            std::cout << model::describeHeldVertex(*held) << "\n";
        }
    }

    // The whole drag from the press, keeping lengths or not: one line per iteration; the
    // result stays in `session`. `stopped`: an iteration was refused as degenerate (the
    // session stays at the last valid state, which is written, as the desktop application
    // keeps it).
    std::unique_ptr<solver::SolveSession> session;
    solver::Summary last;
    bool stopped = false;
    auto runDrag = [&](bool keepLengths) {
        const int after = givenAfter ? givenAfterCount : solver::iterationsAfterDrag(keepLengths);
        try {
            session = std::make_unique<solver::SolveSession>(
                surface, pulled, points,
                keepLengths ? solver::keepLengthsSessionOptions()
                : crease    ? solver::creaseDragSessionOptions()
                            : solver::SessionOptions{});
        } catch (const std::invalid_argument& error) {
            throw model::ModelError("surface " + std::to_string(index + 1) + " of '" + path +
                                    "' cannot be " + (crease ? "dragged: " : "solved: ") +
                                    error.what());
        }
        std::cout << "Surface " << index + 1 << " (" << surface.name() << "): dragging "
                  << (crease ? "crease " + std::to_string(creaseEdge)
                             : std::to_string(start.size()) +
                                   (start.size() == 1 ? " vertex" : " vertices"))
                  << (keepLengths ? " keeping lengths" : "") << " in " << steps << " steps, then "
                  << after << " iterations; " << surface.pinnedVertices().size() << " pinned\n";
        last = solver::Summary{};
        stopped = false;
        // One iteration; false once the session refused a degenerate iterate.
        auto runIteration = [&](const char* label, int i, int count) {
            const auto begin = std::chrono::steady_clock::now();
            const solver::Summary summary = session->step(1);
            const double ms = elapsedMs(begin);
            if (summary.status == solver::Status::StoppedBeforeDegenerate) {
                std::cout << "At " << label << " " << i
                          << ": stopped at the last valid state: " << summary.message << "\n";
                stopped = true;
                return false;
            }
            if (!summary.succeeded() || summary.iterations.empty()) {
                throw model::ModelError(std::string("the solver stopped at ") + label + " " +
                                        std::to_string(i) + " (" +
                                        solver::toString(summary.status) +
                                        (summary.message.empty() ? "" : ": " + summary.message) +
                                        "); nothing was written.");
            }
            printStep(label, i, count, summary, ms, session->surface());
            last = summary;
            return true;
        };
        bool going = true;
        for (int k = 1; k <= steps && going; ++k) {
            const double t = static_cast<double>(k) / steps;
            for (const auto& [id, position] : start) {
                session->setHandleTarget(id, targetAt(id, position, t));
            }
            for (const solver::ControlPointHandle& point : points) {
                session->setControlPointTarget(point.edge, point.index, pointTargetAt(point, t));
            }
            going = runIteration("step", k, steps);
        }
        session->settle();
        for (int k = 1; k <= after && going; ++k) {
            going = runIteration("after", k, after);
        }
    };

    runDrag(lengths != solver::DragLengths::Stretch);
    if (lengths == solver::DragLengths::Automatic) {
        const solver::DragOutcome kept = solver::judgeDrag(
            surface, session->surface(), last.finalMaxConstraintResidual, stopped);
        if (kept.problems() > 0) {
            std::unique_ptr<solver::SolveSession> keptSession = std::move(session);
            const solver::Summary keptLast = last;
            const bool keptStopped = stopped;
            std::cout << "Keeping lengths, the drag " << describeOutcome(kept)
                      << "; replaying it letting the sheet stretch.\n";
            runDrag(false);
            const solver::DragOutcome stretched = solver::judgeDrag(
                surface, session->surface(), last.finalMaxConstraintResidual, stopped);
            const int before = kept.problems();
            const int now = stretched.problems();
            std::cout << "Letting the sheet stretch, the drag " << describeOutcome(stretched)
                      << ": " << (solver::prefersStretched(kept, stretched) ? "taken" : "not taken")
                      << " (" << now << (now == 1 ? " problem" : " problems") << " against "
                      << before << ").\n";
            if (!solver::prefersStretched(kept, stretched)) {
                session = std::move(keptSession);
                last = keptLast;
                stopped = keptStopped;
            }
        }
    }

    double largestMiss = 0.0;
    for (const auto& [id, position] : start) {
        largestMiss = std::max(
            largestMiss, (session->surface().position(id) - targetAt(id, position, 1.0)).norm());
    }
    for (const solver::ControlPointHandle& point : points) {
        const model::Vec3& reached = session->surface()
                                         .edge(point.edge)
                                         .controlPoints[static_cast<std::size_t>(point.index)];
        largestMiss = std::max(largestMiss, (reached - pointTargetAt(point, 1.0)).norm());
    }
    char line[256];
    if (last.iterations.empty()) {
        std::snprintf(line, sizeof line,
                      "No iteration completed; dragged points within %.3g of their targets.\n",
                      largestMiss);
    } else {
        std::snprintf(line, sizeof line,
                      "Largest residual %.2e (tolerance %.1e %s); dragged points within %.3g of "
                      "their targets.\n",
                      last.finalMaxConstraintResidual, last.tolerance,
                      last.toleranceReached ? "reached" : "not reached", largestMiss);
    }
    std::cout << line;
    printFoldAndShape(surface, session->surface());
    surface = session->surface();
    writeProject(project, output);
    std::cout << "Wrote " << output << "\n";
    return 0;
}

} // namespace devsurf::app
