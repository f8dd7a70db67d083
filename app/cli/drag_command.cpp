#include "drag_command.h"

#include "io/project_file.h"
#include "model/model_error.h"
#include "outcome_text.h"
#include "solver/quality/quality_measures.h"
#include "solver/session/crease_drag.h"
#include "solver/session/solve_job.h"
#include "vertex_commands.h"

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

std::string findOption(const std::vector<std::pair<std::string, std::string>>& options,
                       const std::string& name) {
    for (const auto& [key, value] : options) {
        if (key == name) {
            return value;
        }
    }
    return {};
}

bool hasOption(const std::vector<std::pair<std::string, std::string>>& options,
               const std::string& name) {
    for (const auto& entry : options) {
        if (entry.first == name) {
            return true;
        }
    }
    return false;
}

// Exactly `count` finite numbers separated by commas.
std::vector<double> parseNumbers(const std::string& text, const std::string& option,
                                 std::size_t count, const char* example) {
    std::vector<double> values;
    std::stringstream stream(text);
    std::string item;
    bool ok = true;
    while (ok && std::getline(stream, item, ',')) {
        try {
            std::size_t used = 0;
            const double value = std::stod(item, &used);
            ok = used == item.size() && std::isfinite(value);
            values.push_back(value);
        } catch (const std::exception&) {
            ok = false;
        }
    }
    if (!ok || values.size() != count || (!text.empty() && text.back() == ',')) {
        throw std::invalid_argument("option '" + option + "' needs " + std::to_string(count) +
                                    " numbers such as " + example + ", not '" + text + "'");
    }
    return values;
}

int parseCount(const std::string& text, const std::string& option, int low, int high) {
    try {
        std::size_t used = 0;
        const long value = std::stol(text, &used);
        if (used == text.size() && value >= low && value <= high) {
            return static_cast<int>(value);
        }
    } catch (const std::exception&) {
    }
    throw std::invalid_argument("option '" + option + "' needs a whole number between " +
                                std::to_string(low) + " and " + std::to_string(high) + ", not '" +
                                text + "'");
}

// The motion of a drag at parameter t in [0, 1]: a translation by t·by or a rotation by
// t·angle about an axis through a point.
struct Motion {
    bool rotate = false;
    model::Vec3 by;
    model::Vec3 point;
    model::Vec3 axis; // unit
    double radians = 0.0;

    model::Vec3 apply(const model::Vec3& p, double t) const {
        if (!rotate) {
            return p + by * t;
        }
        // Rodrigues' rotation of p − point about the axis.
        const double angle = radians * t;
        const double c = std::cos(angle);
        const double s = std::sin(angle);
        const model::Vec3 v = p - point;
        const model::Vec3 k = axis;
        const model::Vec3 cross{k.y * v.z - k.z * v.y, k.z * v.x - k.x * v.z,
                                k.x * v.y - k.y * v.x};
        const double dot = k.x * v.x + k.y * v.y + k.z * v.z;
        return point + v * c + cross * s + k * (dot * (1.0 - c));
    }
};

Motion parseMotion(const std::vector<std::pair<std::string, std::string>>& options) {
    const bool by = hasOption(options, "--by");
    const bool rotate = hasOption(options, "--rotate");
    if (by == rotate) {
        throw std::invalid_argument("give the motion as either --by DX,DY,DZ or --rotate "
                                    "PX,PY,PZ,AX,AY,AZ,DEGREES");
    }
    Motion motion;
    if (by) {
        const auto v = parseNumbers(findOption(options, "--by"), "--by", 3, "0,0,100");
        motion.by = {v[0], v[1], v[2]};
        return motion;
    }
    const auto v = parseNumbers(findOption(options, "--rotate"), "--rotate", 7, "0,0,0,0,0,1,30");
    motion.rotate = true;
    motion.point = {v[0], v[1], v[2]};
    const double length = std::sqrt(v[3] * v[3] + v[4] * v[4] + v[5] * v[5]);
    if (!(length > 0.0) || !std::isfinite(length)) {
        throw std::invalid_argument("option '--rotate' needs a non-zero axis AX,AY,AZ");
    }
    motion.axis = {v[3] / length, v[4] / length, v[5] / length};
    motion.radians = v[6] * std::acos(-1.0) / 180.0;
    return motion;
}

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
    // A move of a large model may solve with the previous move's factorisation
    // (solver::kDragFactorizationReuse).
    std::snprintf(line, sizeof line, "%s %3d/%d  residual %.3e  time %.3f ms  %s%s\n", label, index,
                  count, stats.maxConstraintResidual,
                  stats.assemblyMs + stats.factorizationMs + stats.solveMs,
                  stats.factorizationReused ? "(factorisation reused)  " : "",
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
}

} // namespace

int runDragCommand(const std::vector<std::string>& positional,
                   const std::vector<std::pair<std::string, std::string>>& options) {
    if (positional.size() != 1) {
        throw std::invalid_argument("expected one project file");
    }
    const bool crease = hasOption(options, "--crease");
    const std::string idsText = findOption(options, "--vertices");
    if (crease == !idsText.empty()) {
        throw std::invalid_argument(crease ? "give either --vertices IDS or --crease EDGE, not both"
                                           : "the vertices to drag are missing (use --vertices "
                                             "IDS, or --crease EDGE to drag a crease)");
    }
    std::vector<model::VertexId> dragged;
    model::EdgeId creaseEdge = model::kInvalidId;
    if (crease) {
        const std::vector<model::EdgeId> edges =
            parseVertexIds(findOption(options, "--crease"), "--crease");
        if (edges.size() != 1) {
            throw std::invalid_argument("option '--crease' needs one edge id");
        }
        creaseEdge = edges.front();
        if (hasOption(options, "--rotate")) {
            throw std::invalid_argument("a crease is dragged with --by DX,DY,DZ, not rotated");
        }
    } else {
        dragged = parseVertexIds(idsText, "--vertices");
    }
    const Motion motion = parseMotion(options);
    std::vector<model::VertexId> pins;
    if (hasOption(options, "--pin")) {
        pins = parseVertexIds(findOption(options, "--pin"), "--pin");
    }
    const int steps = hasOption(options, "--steps")
                          ? parseCount(findOption(options, "--steps"), "--steps", 1, 10000)
                          : 20;
    const std::string output = findOption(options, "-o");
    if (output.empty()) {
        throw std::invalid_argument("the output file is missing (use -o FILE)");
    }
    for (model::VertexId id : pins) {
        if (std::find(dragged.begin(), dragged.end(), id) != dragged.end()) {
            throw std::invalid_argument("vertex " + std::to_string(id) +
                                        " cannot be both dragged and pinned");
        }
    }

    const std::string& path = positional[0];
    model::Project project = io::loadProjectFile(QString::fromStdString(path));
    if (project.surfaces.empty()) {
        throw model::ModelError("'" + path + "' has no surface to drag.");
    }
    std::size_t index = 0;
    if (hasOption(options, "--surface")) {
        index = static_cast<std::size_t>(parseCount(findOption(options, "--surface"), "--surface",
                                                    1, static_cast<int>(project.surfaces.size())) -
                                         1);
    }
    model::CompositeSurface& surface = project.surfaces[index];
    // As DragTool: a dragged crease changes the sizes of its strips on purpose and never
    // keeps lengths; a vertex drag keeps them unless --stretch, and without --keep-lengths
    // (Automatic) is replayed stretching where keeping them fails (solver::DragLengths).
    const solver::DragLengths lengths =
        crease || hasOption(options, "--stretch") ? solver::DragLengths::Stretch
        : hasOption(options, "--keep-lengths")    ? solver::DragLengths::Keep
                                                  : solver::DragLengths::Automatic;
    const bool givenAfter = hasOption(options, "--after");
    const int givenAfterCount =
        givenAfter ? parseCount(findOption(options, "--after"), "--after", 0, 10000) : 0;

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
    } catch (const solver::CreaseDragRefused& refused) {
        throw model::ModelError("surface " + std::to_string(index + 1) + " of '" + path +
                                "' cannot be dragged: " + describeCreaseRefusal(refused));
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
        return creaseDrag ? position + creaseShift.at(id) * t : motion.apply(position, t);
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
    const int after = givenAfter ? givenAfterCount : solver::iterationsAfterDrag(keepLengths);
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
        if (step.replaying) {
            char line[160];
            std::snprintf(line, sizeof line, "replay %3d  residual %.3e\n", step.done,
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
            throw model::ModelError(std::string("the solver stopped at ") + what + " (" +
                                    describeFailure(outcome.failure) + "); nothing was written.");
        }
        const solver::Summary& summary = outcome.assessments.at(index).summary;
        if (summary.status == solver::Status::StoppedBeforeDegenerate) {
            std::cout << "At " << label << " " << labelIndex + summary.iterationsCompleted + 1
                      << ": stopped at the last valid state: " << summary.message << "\n";
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
    const solver::Summary& last = assessment.summary;
    char line[256];
    if (last.iterations.empty()) {
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
    printFoldAndShape(assessment);
    surface = outcome.surfaces.at(index);
    io::saveProjectFile(project, QString::fromStdString(output));
    std::cout << "Wrote " << output << "\n";
    return 0;
}

} // namespace devsurf::app
