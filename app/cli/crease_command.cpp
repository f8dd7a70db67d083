#include "crease_command.h"

#include "io/project_file.h"
#include "vertex_commands.h"

#include <QString>

#include <iostream>
#include <stdexcept>

namespace devsurf::app {

namespace {

model::CreaseCondition parseCondition(const std::string& text) {
    if (text == "curved-fold") {
        return model::CreaseCondition::CurvedFold;
    }
    if (text == "geodesic") {
        return model::CreaseCondition::Geodesic;
    }
    if (text == "none") {
        return model::CreaseCondition::None;
    }
    if (text == "straight") {
        return model::CreaseCondition::Straight;
    }
    throw std::invalid_argument(
        "option '--condition' needs curved-fold, geodesic, straight or none, not '" + text + "'");
}

} // namespace

int runCreaseCommand(const std::vector<std::string>& positional,
                     const std::vector<std::pair<std::string, std::string>>& options) {
    if (positional.size() != 1) {
        throw std::invalid_argument("expected one project file");
    }
    const std::string idsText =
        requiredOption(options, "--edges", "the creases are missing (use --edges IDS)");
    const std::string conditionText = requiredOption(options, "--condition",
                                                     "the condition is missing (use --condition "
                                                     "curved-fold|geodesic|straight|none)");
    const std::string output =
        requiredOption(options, "-o", "the output file is missing (use -o FILE)");
    const std::vector<std::uint32_t> ids = parseIds(idsText, "--edges", "edge");
    const model::CreaseCondition condition = parseCondition(conditionText);
    model::Project project = io::loadProjectFile(QString::fromStdString(positional[0]));
    const std::size_t index = surfaceOption(options, project, "set crease conditions on");
    model::CompositeSurface& surface = project.surfaces[index];
    for (model::EdgeId id : ids) {
        std::string problem;
        if (!surface.hasEdge(id)) {
            problem = "has no edge " + std::to_string(id);
        } else if (!surface.edge(id).isSpline()) {
            problem = "edge " + std::to_string(id) + " is a ruling, not a crease";
        } else if (surface.facesOfEdge(id).size() != 2) {
            problem = "edge " + std::to_string(id) + " is a curve on the boundary, not a crease";
        }
        if (!problem.empty()) {
            std::cerr << "devsurf-cli: surface '" << surface.name() << "' " << problem
                      << " (list the edges with 'devsurf-cli info FILE --edges').\n";
            return 2;
        }
    }
    for (model::EdgeId id : ids) {
        surface.setCreaseCondition(id, condition);
    }
    io::saveProjectFile(project, QString::fromStdString(output));
    std::cout << "Wrote " << output << " (" << ids.size() << " crease"
              << (ids.size() == 1 ? "" : "s") << " set to " << model::creaseConditionName(condition)
              << " in '" << surface.name() << "')\n";
    return 0;
}

int runSmoothCommand(const std::vector<std::string>& positional,
                     const std::vector<std::pair<std::string, std::string>>& options, bool sharp) {
    if (positional.size() != 1) {
        throw std::invalid_argument("expected one project file");
    }
    const std::string idsText =
        requiredOption(options, "--edges", "the rulings are missing (use --edges IDS)");
    const std::string output =
        requiredOption(options, "-o", "the output file is missing (use -o FILE)");
    const std::vector<std::uint32_t> ids = parseIds(idsText, "--edges", "edge");
    model::Project project = io::loadProjectFile(QString::fromStdString(positional[0]));
    const std::size_t index = surfaceOption(options, project, "mark rulings smooth or sharp in");
    model::CompositeSurface& surface = project.surfaces[index];
    for (model::EdgeId id : ids) {
        std::string problem;
        if (!surface.hasEdge(id)) {
            problem = "has no edge " + std::to_string(id);
        } else if (surface.edge(id).isSpline()) {
            problem = "edge " + std::to_string(id) +
                      " is a curve, not a ruling (curves take a crease condition)";
        } else if (surface.facesOfEdge(id).size() != 2) {
            problem = "edge " + std::to_string(id) +
                      " is a ruling on the boundary, not between "
                      "two patches";
        }
        if (!problem.empty()) {
            std::cerr << "devsurf-cli: surface '" << surface.name() << "' " << problem
                      << " (list the edges with 'devsurf-cli info FILE --edges').\n";
            return 2;
        }
    }
    for (model::EdgeId id : ids) {
        surface.setSmooth(id, !sharp);
    }
    io::saveProjectFile(project, QString::fromStdString(output));
    std::cout << "Wrote " << output << " (" << ids.size() << " ruling"
              << (ids.size() == 1 ? "" : "s") << " made " << (sharp ? "sharp" : "smooth") << " in '"
              << surface.name() << "')\n";
    return 0;
}

} // namespace devsurf::app
