#include "drag_command.h"

#include "io/project_file.h"
#include "model/model_error.h"
#include "solver/quality/crease_quality.h"
#include "solver/quality/quality_measures.h"
#include "solver/quality/shape_change.h"
#include "solver/quality/vertex_stars.h"
#include "solver/session/solve_session.h"
#include "vertex_commands.h"

#include <QString>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <map>
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

double elapsedMs(std::chrono::steady_clock::time_point since) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - since)
        .count();
}

void printStep(const char* label, int index, int count, const solver::Summary& summary, double ms,
               const model::CompositeSurface& surface) {
    const solver::QualityMeasures quality = solver::measureQuality(surface);
    char line[512];
    std::snprintf(line, sizeof line, "%s %3d/%d  residual %.3e  time %.3f ms  %s\n", label, index,
                  count, summary.finalMaxConstraintResidual, ms, quality.describe().c_str());
    std::cout << line;
}

// What a designer checks after a drag: how well the crease conditions hold and how far the
// creases fold (measured from the geometry), and whether a strip degenerated.
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
    std::cout << line;
}

} // namespace

int runDragCommand(const std::vector<std::string>& positional,
                   const std::vector<std::pair<std::string, std::string>>& options) {
    if (positional.size() != 1) {
        throw std::invalid_argument("expected one project file");
    }
    const std::string idsText = findOption(options, "--vertices");
    if (idsText.empty()) {
        throw std::invalid_argument("the vertices to drag are missing (use --vertices IDS)");
    }
    const std::vector<model::VertexId> dragged = parseVertexIds(idsText, "--vertices");
    const Motion motion = parseMotion(options);
    std::vector<model::VertexId> pins;
    if (hasOption(options, "--pin")) {
        pins = parseVertexIds(findOption(options, "--pin"), "--pin");
    }
    const int steps = hasOption(options, "--steps")
                          ? parseCount(findOption(options, "--steps"), "--steps", 1, 10000)
                          : 20;
    const int after = hasOption(options, "--after")
                          ? parseCount(findOption(options, "--after"), "--after", 0, 10000)
                          : 10;
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

    // The vertices' positions at the press, and a handle on each pulled there.
    std::map<model::VertexId, model::Vec3> start;
    std::vector<solver::VertexHandle> pulled;
    for (model::VertexId id : std::set<model::VertexId>(dragged.begin(), dragged.end())) {
        start[id] = surface.position(id);
        pulled.push_back({id, false, surface.position(id)});
    }
    std::unique_ptr<solver::SolveSession> session;
    try {
        session = std::make_unique<solver::SolveSession>(surface, pulled);
    } catch (const std::invalid_argument& error) {
        throw model::ModelError("surface " + std::to_string(index + 1) + " of '" + path +
                                "' cannot be solved: " + error.what());
    }
    std::cout << "Surface " << index + 1 << " (" << surface.name() << "): dragging " << start.size()
              << (start.size() == 1 ? " vertex" : " vertices") << " in " << steps << " steps, then "
              << after << " iterations; " << surface.pinnedVertices().size() << " pinned\n";

    auto runIteration = [&](const char* label, int i, int count) {
        const auto begin = std::chrono::steady_clock::now();
        const solver::Summary summary = session->step(1);
        const double ms = elapsedMs(begin);
        if (!summary.succeeded() || summary.iterations.empty()) {
            throw model::ModelError(std::string("the solver stopped at ") + label + " " +
                                    std::to_string(i) + " (" + solver::toString(summary.status) +
                                    (summary.message.empty() ? "" : ": " + summary.message) +
                                    "); nothing was written.");
        }
        printStep(label, i, count, summary, ms, session->surface());
        return summary;
    };

    solver::Summary last;
    for (int k = 1; k <= steps; ++k) {
        const double t = static_cast<double>(k) / steps;
        for (const auto& [id, position] : start) {
            session->setHandleTarget(id, motion.apply(position, t));
        }
        last = runIteration("step", k, steps);
    }
    for (int k = 1; k <= after; ++k) {
        last = runIteration("after", k, after);
    }

    double largestMiss = 0.0;
    for (const auto& [id, position] : start) {
        const model::Vec3 miss = session->surface().position(id) - motion.apply(position, 1.0);
        largestMiss =
            std::max(largestMiss, std::sqrt(miss.x * miss.x + miss.y * miss.y + miss.z * miss.z));
    }
    char line[256];
    std::snprintf(line, sizeof line,
                  "Largest residual %.2e (tolerance %.1e %s); dragged vertices within %.3g of "
                  "their targets.\n",
                  last.finalMaxConstraintResidual, last.tolerance,
                  last.toleranceReached ? "reached" : "not reached", largestMiss);
    std::cout << line;
    printFoldAndShape(surface, session->surface());
    surface = session->surface();
    io::saveProjectFile(project, QString::fromStdString(output));
    std::cout << "Wrote " << output << "\n";
    return 0;
}

} // namespace devsurf::app
