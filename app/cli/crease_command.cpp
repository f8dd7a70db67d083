#include "crease_command.h"

#include "cli_output.h"
#include "io/project_file.h"

#include <QString>

#include <iostream>
#include <optional>
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
    throw UsageError{"option '--condition' needs curved-fold, geodesic, straight or none, not '" +
                     text + "'"};
}

int surfaceNumberOf(const SubcommandArguments& args) {
    const std::optional<std::string> text = args.value("surface");
    return text ? static_cast<int>(parseWhole(*text, "--surface", 1, 1000000)) : 0;
}

} // namespace

int runCreaseCommand(const SubcommandArguments& args) {
    const std::string input = args.onePositional("one project file");
    const std::string idsText = args.required("edges", "the creases are missing (use --edges IDS)");
    const std::string conditionText =
        args.required("condition", "the condition is missing (use --condition "
                                   "curved-fold|geodesic|straight|none)");
    const std::string output = args.required("o", kMissingOutput);
    const std::vector<std::uint32_t> ids = parseIds(idsText, "--edges", "edge");
    const model::CreaseCondition condition = parseCondition(conditionText);
    const int surfaceNumber = surfaceNumberOf(args);
    checkOutput(output, {input}, OutputKind::Project, "the project");
    model::Project project = io::loadProjectFile(QString::fromStdString(input));
    const std::size_t index = surfaceIndex(surfaceNumber, project, "set crease conditions on");
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
    writeProject(project, output);
    std::cout << "Wrote " << output << " (" << ids.size() << " crease"
              << (ids.size() == 1 ? "" : "s") << " set to " << model::creaseConditionName(condition)
              << " in '" << surface.name() << "')\n";
    return 0;
}

int runSmoothCommand(const SubcommandArguments& args) {
    const std::string input = args.onePositional("one project file");
    const std::string idsText = args.required("edges", "the rulings are missing (use --edges IDS)");
    const std::string output = args.required("o", kMissingOutput);
    const std::vector<std::uint32_t> ids = parseIds(idsText, "--edges", "edge");
    const bool sharp = args.isSet("off");
    const int surfaceNumber = surfaceNumberOf(args);
    checkOutput(output, {input}, OutputKind::Project, "the project");
    model::Project project = io::loadProjectFile(QString::fromStdString(input));
    const std::size_t index =
        surfaceIndex(surfaceNumber, project, "mark rulings smooth or sharp in");
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
    writeProject(project, output);
    std::cout << "Wrote " << output << " (" << ids.size() << " ruling"
              << (ids.size() == 1 ? "" : "s") << " made " << (sharp ? "sharp" : "smooth") << " in '"
              << surface.name() << "')\n";
    return 0;
}

} // namespace devsurf::app
