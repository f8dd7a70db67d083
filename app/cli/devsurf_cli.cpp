// devsurf-cli: the command-line tool for scripts and batch work.
// Exit codes: 0 success, 1 bad usage, 2 invalid or unreadable input (or an output that
// cannot be written), each failure explained in one sentence on stderr.

#include "devsurf_cli.h"
#include "example_text.h"
#include "problem_text.h"

#include "approximate_command.h"
#include "cli_arguments.h"
#include "cli_output.h"
#include "command_line.h"
#include "crease_command.h"
#include "curve_commands.h"
#include "drag_command.h"
#include "io/file_error.h"
#include "io/interchange_json.h"
#include "io/project_file.h"
#include "join_command.h"
#include "model/examples.h"
#include "model/model_error.h"
#include "model/surface_statistics.h"
#include "pattern_commands.h"
#include "reference_commands.h"
#include "solve_command.h"
#include "subcommands.h"
#include "vertex_commands.h"

#include <QString>

#include <iostream>
#include <new>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace devsurf::app {

namespace {

int commandExample(const SubcommandArguments& args) {
    const std::string name = args.onePositional("one example name");
    int size = 0;
    if (const std::optional<std::string> text = args.value("size")) {
        size = static_cast<int>(parseWhole(*text, "--size", 1, 1000000));
    }
    const std::string output = args.required("o", kMissingOutput);
    // Held by default, as File ▸ New from Example makes it: an example that starts flat keeps
    // the sheet it starts as. --as-built writes it as it comes; --hold-sheet insists on a sheet
    // and refuses an example that has none.
    const bool asBuilt = args.isSet("as-built");
    const bool insistOnSheet = args.isSet("hold-sheet");
    if (asBuilt && insistOnSheet) {
        throw UsageError{"--as-built and --hold-sheet exclude each other"};
    }
    if (insistOnSheet) {
        for (const model::ExampleInfo& info : model::builtInExamples()) {
            if (info.name == name && !info.canHoldItsSheet && !info.holdsSheetAsBuilt) {
                throw UsageError{"'" + name + "' unfolds into no one sheet, so --hold-sheet " +
                                 "does not apply"};
            }
        }
    }
    checkOutput(output, {}, OutputKind::Project, "the project");
    model::Project project;
    try {
        project = model::makeExample(
            name, size, asBuilt ? model::ExampleSheet::AsBuilt : model::ExampleSheet::Held);
    } catch (const model::ModelError& error) {
        throw UsageError{withoutFinalPeriod(ProblemText::of(error.problem()).toStdString())};
    }
    writeProject(project, output);
    const model::CompositeSurface& surface = project.surfaces.front();
    std::cout << "Wrote " << output << " (" << surface.name() << ", " << surface.faces().size()
              << " faces, " << surface.controlPointCount() << " control points"
              << (surface.keepsDevelopment() ? ", holding its sheet" : "") << ")\n";
    return kExitOk;
}

std::string counted(std::size_t count, const char* singular, const char* plural) {
    return std::to_string(count) + " " + (count == 1 ? singular : plural);
}

std::string faceSummary(const model::SurfaceStatistics& stats) {
    using model::FaceType;
    auto count = [&stats](FaceType type) {
        auto it = stats.facesByType.find(type);
        return it == stats.facesByType.end() ? std::size_t{0} : it->second;
    };
    std::string text = std::to_string(stats.faces()) + " (" +
                       counted(count(FaceType::StripSRSR), "SRSR strip", "SRSR strips") + ", " +
                       counted(count(FaceType::StripSRS), "SRS strip", "SRS strips") + ", " +
                       counted(count(FaceType::ConeSRR), "SRR cone", "SRR cones") + ", " +
                       counted(count(FaceType::Planar), "planar face", "planar faces");
    if (count(FaceType::Invalid) != 0) {
        text += ", " + std::to_string(count(FaceType::Invalid)) + " invalid";
    }
    return text + ")";
}

// ", on a 300 x 300 mm rectangle" and the like: the sheet a kept development is confined to.
std::string sheetShapeText(const model::SheetDomain& d) {
    auto mm = [](double v) { return QString::number(v, 'g', 6).toStdString(); };
    switch (d.shape) {
    case model::SheetShape::Free:
        return "";
    case model::SheetShape::Rectangle:
        return ", on a " + mm(d.width) + " x " + mm(d.height) + " mm rectangle";
    case model::SheetShape::Disk:
        return ", on a disk of radius " + mm(d.radius) + " mm";
    case model::SheetShape::Annulus:
        return ", on an annulus of radii " + mm(d.innerRadius) + " and " + mm(d.radius) + " mm";
    case model::SheetShape::Outline:
        return ", on an outline of " + std::to_string(d.outline.size()) + " loop(s)";
    case model::SheetShape::Cylinder:
        return ", around a cylinder of radius " + mm(d.radius) + " mm";
    }
    return "";
}

int commandInfo(const SubcommandArguments& args) {
    EntityListing listing;
    listing.vertices = args.isSet("vertices");
    listing.edges = args.isSet("edges");
    listing.json = args.isSet("json");
    if (listing.json && !listing.vertices && !listing.edges) {
        throw UsageError{"option '--json' goes with --vertices or --edges"};
    }
    const std::string path = args.onePositional("one project file");
    const model::Project project = io::loadProjectFile(QString::fromStdString(path));
    if (listing.json) {
        app::printEntities(project, listing, std::cout);
        return kExitOk;
    }
    std::cout << "File: " << path << "\n"
              << "Format version: " << io::kProjectFormatVersion << "\n"
              << "Units: " << project.units << "\n"
              << "Surfaces: " << project.surfaces.size() << "\n"
              << "Reference curves: " << project.referenceCurves.size() << "\n"
              << "Reference shapes: " << project.referenceShapes.size() << "\n";
    for (std::size_t i = 0; i < project.referenceShapes.size(); ++i) {
        const model::ReferenceShape& shape = project.referenceShapes[i];
        std::cout << "Reference shape " << i + 1 << ": " << shape.name << " ("
                  << counted(shape.points.size(), "point", "points") << ", "
                  << counted(shape.triangles.size(), "triangle", "triangles")
                  << (shape.normals.empty() ? "" : ", with normals") << ")\n";
    }
    for (std::size_t i = 0; i < project.surfaces.size(); ++i) {
        const model::CompositeSurface& surface = project.surfaces[i];
        const model::SurfaceStatistics stats = model::surfaceStatistics(surface);
        std::cout << "Surface " << i + 1 << ": " << surface.name() << "\n"
                  << "  Faces: " << faceSummary(stats) << "\n"
                  << "  Spline spaces:";
        for (const auto& [space, edges] : stats.splineSpaces) {
            std::cout << (space == stats.splineSpaces.begin()->first ? " " : "; ")
                      << ProblemText::splineSpace(space).toStdString() << " ("
                      << counted(edges, "S-edge", "S-edges") << ")";
        }
        std::cout << "\n"
                  << "  Control points: " << stats.controlPoints << "\n"
                  << "  Vertices: " << stats.vertices << "\n"
                  << "  Edges: " << stats.splineEdges << " S, " << stats.rulingEdges << " R\n"
                  << "  Pinned vertices: " << surface.pinnedVertices().size() << "\n"
                  << "  Sheet: "
                  << (!surface.keepsDevelopment() ? std::string("not held (it may stretch)")
                      : surface.development().empty()
                          ? std::string("held, unfolded at the next solve")
                          : "held (" + std::to_string(surface.development().size()) +
                                " development points)")
                  << sheetShapeText(surface.sheetDomain()) << "\n";
        const model::SheetDomain& sheet = surface.sheetDomain();
        if (!sheet.creaseCurves.empty()) {
            std::cout << "  Crease curves: " << sheet.creaseCurves.size() << ", holding "
                      << counted(sheet.creaseCurveOf.size(), "crease", "creases") << "\n";
        }
    }
    if (listing.vertices || listing.edges) {
        app::printEntities(project, listing, std::cout);
    }
    return kExitOk;
}

int commandValidate(const SubcommandArguments& args) {
    const std::string path = args.onePositional("one project file");
    try {
        const model::Project project = io::loadProjectFile(QString::fromStdString(path));
        std::cout << path << ": valid (" << project.surfaces.size() << " surface"
                  << (project.surfaces.size() == 1 ? "" : "s") << ")\n";
        return kExitOk;
    } catch (const io::FileError& error) {
        std::cerr << "devsurf-cli: " << error.what() << "\n";
        for (const model::Problem& problem : error.problems()) {
            std::cerr << "  - " << ProblemText::of(problem).toStdString() << "\n";
        }
        return kExitInput;
    }
}

int commandExportJson(const SubcommandArguments& args) {
    const std::string input = args.onePositional("one project file");
    int samples = 8;
    if (const std::optional<std::string> text = args.value("samples")) {
        samples = static_cast<int>(parseWhole(*text, "--samples", 1, 1000));
    }
    const std::string output = args.required("o", kMissingOutput);
    checkOutput(output, {input}, OutputKind::Other, "the interchange JSON");
    checkExtension(output, "json", "interchange JSON");
    const model::Project project = io::loadProjectFile(QString::fromStdString(input));
    if (output == "-") {
        const std::string text = io::interchangeJson(project, samples);
        writeStandardOutput(QByteArray(text.data(), static_cast<qsizetype>(text.size())));
        return kExitOk;
    }
    io::saveInterchangeJsonFile(project, QString::fromStdString(output), samples);
    std::cout << "Wrote " << output << "\n";
    return kExitOk;
}

int commandExamples(const SubcommandArguments& args) {
    if (args.positionalCount() != 0) {
        throw UsageError{"'examples' takes no file"};
    }
    for (const model::ExampleInfo& info : model::builtInExamples()) {
        const std::string description =
            withoutFinalPeriod(exampleDescription(info.name).toStdString());
        std::cout << info.name << ": " << description << "; size " << info.minSize << "–"
                  << info.maxSize << ", default " << info.defaultSize << "\n";
    }
    return kExitOk;
}

int commandSolve(const SubcommandArguments& given) {
    const SolveArguments args = solveArguments(given);
    checkOutput(args.output, {args.input}, OutputKind::Project, "the project");
    return runSolveCommand(args);
}

int commandDrag(const SubcommandArguments& given) {
    const DragArguments args = dragArguments(given);
    checkOutput(args.output, {args.input}, OutputKind::Project, "the project");
    return runDragCommand(args);
}

int run(const std::vector<std::string>& args) {
    if (args.empty()) {
        throw UsageError{"a command is missing"};
    }
    const std::string& command = args[0];
    if (command == "-h" || command == "--help" || command == "help") {
        std::cout << overallHelp();
        return kExitOk;
    }
    if (command == "--version") {
        std::cout << "devsurf-cli " << DEVSURF_VERSION << " (project file format "
                  << io::kProjectFormatVersion << ", interchange format " << io::kInterchangeVersion
                  << ")\n";
        return kExitOk;
    }
    if (command == "bench") {
        throw UsageError{"the benchmark is the separate program 'devsurf-bench' (devsurf-bench "
                         "[--json])"};
    }
    const SubcommandSpec* spec = findSubcommand(command);
    if (spec == nullptr) {
        throw UsageError{"unknown command '" + command + "'"};
    }
    const SubcommandArguments parsed(*spec, {args.begin() + 1, args.end()});
    if (parsed.helpRequested()) {
        std::cout << parsed.help();
        return kExitOk;
    }
    using Runner = int (*)(const SubcommandArguments&);
    static const std::pair<const char*, Runner> runners[] = {
        {"example", commandExample},
        {"info", commandInfo},
        {"pin", runPinCommand},
        {"sheet", runSheetCommand},
        {"crease", runCreaseCommand},
        {"smooth", runSmoothCommand},
        {"validate", commandValidate},
        {"export-json", commandExportJson},
        {"examples", commandExamples},
        {"solve", commandSolve},
        {"drag", commandDrag},
        {"export", runExportPatternCommand},
        {"report", runReportCommand},
        {"import-curves", runImportCurvesCommand},
        {"fit-edge", runFitEdgeCommand},
        {"import-reference", runImportReferenceCommand},
        {"distance", runDistanceCommand},
        {"approximate", runApproximateCommand},
        {"join", runJoinCommand}};
    for (const auto& [name, runner] : runners) {
        if (command == name) {
            return runner(parsed);
        }
    }
    throw UsageError{"unknown command '" + command + "'"};
}

} // namespace

int runDevsurfCli(const std::vector<std::string>& args) {
    try {
        return run(args);
    } catch (const UsageError& error) {
        std::cerr << "devsurf-cli: " << error.message << ". Run 'devsurf-cli "
                  << (args.empty() || findSubcommand(args[0]) == nullptr ? "" : args[0] + " ")
                  << "--help' for usage.\n";
        return kExitUsage;
    } catch (const io::FileError& error) {
        std::cerr << "devsurf-cli: " << error.what() << "\n";
        for (const model::Problem& problem : error.problems()) {
            std::cerr << "  - " << ProblemText::of(problem).toStdString() << "\n";
        }
        return kExitInput;
    } catch (const InputError& error) {
        std::cerr << "devsurf-cli: " << error.what() << "\n";
        return kExitInput;
    } catch (const model::ModelError& error) {
        std::cerr << "devsurf-cli: " << ProblemText::of(error.problem()).toStdString() << "\n";
        return kExitInput;
    } catch (const std::bad_alloc&) {
        std::cerr << "devsurf-cli: there is not enough memory for this design.\n";
        return kExitInput;
    } catch (const std::exception& error) {
        std::cerr << "devsurf-cli: unexpected failure: " << error.what() << "\n";
        return kExitInput;
    }
}

} // namespace devsurf::app
