// devsurf-cli: the command-line tool for scripts and batch work.
// Exit codes: 0 success, 1 bad usage, 2 invalid or unreadable input (or an output that
// cannot be written), each failure explained in one sentence on stderr.

#include "crease_command.h"
#include "drag_command.h"
#include "io/file_error.h"
#include "io/interchange_json.h"
#include "io/project_file.h"
#include "model/examples.h"
#include "model/model_error.h"
#include "model/surface_statistics.h"
#include "pattern_commands.h"
#include "solve_command.h"
#include "vertex_commands.h"

#include <QCoreApplication>
#include <QString>

#include <cstdio>
#include <iostream>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

using namespace devsurf;

constexpr int kExitOk = 0;
constexpr int kExitUsage = 1;
constexpr int kExitInput = 2;

const char* const kUsage = R"(Usage: devsurf-cli COMMAND [OPTIONS]

Commands:
  example NAME [--size K] -o FILE.devsurf
                      Write a built-in example (sheet, annulus, cylinder, mixed,
                      fig8, fig6; `devsurf-cli examples` lists them).
  info FILE [--vertices] [--edges] [--json]
                      Print surfaces, faces per type, spline spaces, control points,
                      vertices and edges; --vertices lists every vertex (id, x y z,
                      pinned, boundary), --edges every edge (id, R or S, its vertices,
                      crease condition, smooth or sharp); --json prints those lists
                      as JSON.
  pin FILE --vertices IDS [--unpin] [--surface K] -o OUT.devsurf
                      Pin vertices (the solver never moves them) or release them.
  crease FILE --edges IDS --condition curved-fold|geodesic|straight|none [--surface K]
        -o OUT.devsurf
                      Set the condition the solver imposes on creases: a curved fold
                      (the crease's osculating plane bisects the two patches), a
                      geodesic, or straight when unfolded (in its left patch); none
                      clears it.
  smooth FILE --edges IDS [--off] [--surface K] -o OUT.devsurf
                      Mark rulings between two patches smooth (the solver keeps the
                      surface smooth across them); --off makes them sharp again.
  validate FILE       Check every invariant of the model; list all problems.
  export-json FILE -o OUT.json [--samples N]
                      Write the interchange JSON (docs/interchange-format.md);
                      N samples per spline interval for the mesh (default 8).
  examples            List the built-in examples and their sizes.
  solve FILE [--iterations N] [--perturb SIGMA [--seed S]] [--fix IDS] -o OUT.devsurf
                      Run N guided-projection iterations (default 10) on every surface and
                      write the result; one line per iteration (residual, time for
                      assembly / factorisation / solve, quality). --perturb adds Gaussian
                      noise of SIGMA times the surface's diameter first; --fix keeps the
                      vertices with the given ids (e.g. 0,4,7) where they are.
  drag FILE (--vertices IDS | --crease EDGE) (--by DX,DY,DZ | --rotate PX,PY,PZ,AX,AY,AZ,DEGREES)
       [--steps N] [--pin IDS] [--after K] [--keep-lengths | --stretch] [--surface K]
       -o OUT.devsurf
                      Replay a drag as the desktop application runs it: the vertices are
                      moved by DX,DY,DZ (or rotated by DEGREES about the axis AX,AY,AZ
                      through PX,PY,PZ) in N evenly spaced steps (default 20) with one
                      solver iteration each, then K more iterations (default 20 when
                      keeping lengths, else 10). Pins in the file stay; --pin pins more
                      vertices. One line per step (residual, time, quality; a step
                      of a large model that reused the previous step's factorisation
                      says so). A vertex drag keeps lengths, as the desktop
                      application does by default: stretching of every strip's
                      control net is damped in each step, so the sheet bends rather
                      than stretches (the damping fades over the K iterations after
                      the moves; see the manual); where that fails (no convergence,
                      a fold-over or an overlapping development) the drag is
                      replayed letting the sheet stretch and the result with fewer
                      problems is written. --keep-lengths never replays; --stretch
                      never keeps lengths. --crease EDGE
                      instead of --vertices drags a crease by DX,DY,DZ: its control points
                      and unpinned ends slide within the surface, along the rulings of the
                      strip the crease leaves (the component along the surface normal is
                      dropped), and the strips on both sides change size; a crease drag
                      never keeps lengths.
  export FILE --format dxf|svg|pdf|fold [--sheet W,H | --paper A4|A3|Letter]
         [--tolerance MM] [--splines] [--r12] [--seam MM] [--rulings] -o OUT
                      Write the cutting pattern: pieces laid out on sheets of W x H mm
                      (default 600,400) or of a paper's printable size; curves within
                      MM (default 0.01); DXF as SPLINEs (--splines) or R12 (--r12); a seam
                      allowance of MM; rulings as scoring lines. PDF prints 1:1 on the
                      paper (default A4), tiled, after the fabrication report. FOLD
                      always has the rulings (as flat edges, for folding simulators).
  report FILE [--json] [--sheet W,H | --paper NAME] [--tolerance MM] [--seam MM]
                      Print the fabrication report: per piece its sheet, size, area,
                      largest isometry error, overlaps, and whether it fits the sheet.

The solver benchmark is the separate program devsurf-bench [--json].

Options:
  -h, --help          Show this help.
  --version           Show the version.

Exit codes: 0 success, 1 bad usage, 2 invalid or unreadable input.
)";

struct UsageError {
    std::string message;
};

struct Arguments {
    std::vector<std::string> positional;
    std::map<std::string, std::string> options;
};

// Splits arguments into positionals and "--name value" options (only the names given).
Arguments parse(const std::vector<std::string>& args, const std::vector<std::string>& valued) {
    Arguments result;
    for (std::size_t i = 0; i < args.size(); ++i) {
        const std::string& arg = args[i];
        if (arg.size() > 1 && arg[0] == '-') {
            bool known = false;
            for (const std::string& name : valued) {
                if (arg == name) {
                    known = true;
                }
            }
            if (!known) {
                throw UsageError{"unknown option '" + arg + "'"};
            }
            if (i + 1 >= args.size()) {
                throw UsageError{"option '" + arg + "' needs a value"};
            }
            if (result.options.count(arg) != 0) {
                throw UsageError{"option '" + arg + "' is given twice"};
            }
            result.options[arg] = args[++i];
        } else {
            result.positional.push_back(arg);
        }
    }
    return result;
}

int parseInteger(const std::string& text, const std::string& option) {
    try {
        std::size_t used = 0;
        const long value = std::stol(text, &used);
        if (used == text.size() && value >= -1000000 && value <= 1000000) {
            return static_cast<int>(value);
        }
    } catch (const std::exception&) {
    }
    throw UsageError{"option '" + option + "' needs a whole number, not '" + text + "'"};
}

std::string requiredOutput(const Arguments& args) {
    auto it = args.options.find("-o");
    if (it == args.options.end()) {
        throw UsageError{"the output file is missing (use -o FILE)"};
    }
    return it->second;
}

void expectPositionals(const Arguments& args, std::size_t count, const char* what) {
    if (args.positional.size() != count) {
        throw UsageError{std::string("expected ") + what};
    }
}

int commandExample(const std::vector<std::string>& rest) {
    const Arguments args = parse(rest, {"-o", "--size"});
    expectPositionals(args, 1, "one example name");
    int size = 0;
    if (auto it = args.options.find("--size"); it != args.options.end()) {
        size = parseInteger(it->second, "--size");
        if (size <= 0) {
            throw UsageError{"option '--size' must be positive"};
        }
    }
    const std::string output = requiredOutput(args);
    model::Project project;
    try {
        project = model::makeExample(args.positional[0], size);
    } catch (const model::ModelError& error) {
        throw UsageError{error.what()};
    }
    io::saveProjectFile(project, QString::fromStdString(output));
    std::cout << "Wrote " << output << " (" << project.surfaces.front().name() << ", "
              << project.surfaces.front().faces().size() << " faces, "
              << project.surfaces.front().controlPointCount() << " control points)\n";
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

int commandInfo(const std::vector<std::string>& given) {
    app::EntityListing listing;
    std::vector<std::string> rest;
    for (const std::string& arg : given) {
        if (arg == "--vertices") {
            listing.vertices = true;
        } else if (arg == "--edges") {
            listing.edges = true;
        } else if (arg == "--json") {
            listing.json = true;
        } else {
            rest.push_back(arg);
        }
    }
    if (listing.json && !listing.vertices && !listing.edges) {
        throw UsageError{"option '--json' goes with --vertices or --edges"};
    }
    const Arguments args = parse(rest, {});
    expectPositionals(args, 1, "one project file");
    const std::string& path = args.positional[0];
    const model::Project project = io::loadProjectFile(QString::fromStdString(path));
    if (listing.json) {
        app::printEntities(project, listing, std::cout);
        return kExitOk;
    }
    std::cout << "File: " << path << "\n"
              << "Format version: " << io::kProjectFormatVersion << "\n"
              << "Units: " << project.units << "\n"
              << "Surfaces: " << project.surfaces.size() << "\n";
    for (std::size_t i = 0; i < project.surfaces.size(); ++i) {
        const model::CompositeSurface& surface = project.surfaces[i];
        const model::SurfaceStatistics stats = model::surfaceStatistics(surface);
        std::cout << "Surface " << i + 1 << ": " << surface.name() << "\n"
                  << "  Faces: " << faceSummary(stats) << "\n"
                  << "  Spline spaces:";
        for (const auto& [space, edges] : stats.splineSpaces) {
            std::cout << (space == stats.splineSpaces.begin()->first ? " " : "; ")
                      << space.describe() << " (" << counted(edges, "S-edge", "S-edges") << ")";
        }
        std::cout << "\n"
                  << "  Control points: " << stats.controlPoints << "\n"
                  << "  Vertices: " << stats.vertices << "\n"
                  << "  Edges: " << stats.splineEdges << " S, " << stats.rulingEdges << " R\n"
                  << "  Pinned vertices: " << surface.pinnedVertices().size() << "\n";
    }
    if (listing.vertices || listing.edges) {
        app::printEntities(project, listing, std::cout);
    }
    return kExitOk;
}

int commandCrease(const std::vector<std::string>& given) {
    const Arguments args = parse(given, {"-o", "--edges", "--condition", "--surface"});
    try {
        return app::runCreaseCommand(args.positional, {args.options.begin(), args.options.end()});
    } catch (const std::invalid_argument& error) {
        throw UsageError{error.what()};
    }
}

int commandSmooth(const std::vector<std::string>& given) {
    bool sharp = false;
    std::vector<std::string> rest;
    for (const std::string& arg : given) {
        if (arg == "--off") {
            sharp = true;
        } else {
            rest.push_back(arg);
        }
    }
    const Arguments args = parse(rest, {"-o", "--edges", "--surface"});
    try {
        return app::runSmoothCommand(args.positional, {args.options.begin(), args.options.end()},
                                     sharp);
    } catch (const std::invalid_argument& error) {
        throw UsageError{error.what()};
    }
}

int commandPin(const std::vector<std::string>& given) {
    bool unpin = false;
    std::vector<std::string> rest;
    for (const std::string& arg : given) {
        if (arg == "--unpin") {
            unpin = true;
        } else {
            rest.push_back(arg);
        }
    }
    const Arguments args = parse(rest, {"-o", "--vertices", "--surface"});
    try {
        return app::runPinCommand(args.positional, {args.options.begin(), args.options.end()},
                                  unpin);
    } catch (const std::invalid_argument& error) {
        throw UsageError{error.what()};
    }
}

int commandValidate(const std::vector<std::string>& rest) {
    const Arguments args = parse(rest, {});
    expectPositionals(args, 1, "one project file");
    const std::string& path = args.positional[0];
    try {
        const model::Project project = io::loadProjectFile(QString::fromStdString(path));
        std::cout << path << ": valid (" << project.surfaces.size() << " surface"
                  << (project.surfaces.size() == 1 ? "" : "s") << ")\n";
        return kExitOk;
    } catch (const io::FileError& error) {
        std::cerr << "devsurf-cli: " << error.what() << "\n";
        for (const std::string& problem : error.details()) {
            std::cerr << "  - " << problem << "\n";
        }
        return kExitInput;
    }
}

int commandExportJson(const std::vector<std::string>& rest) {
    const Arguments args = parse(rest, {"-o", "--samples"});
    expectPositionals(args, 1, "one project file");
    int samples = 8;
    if (auto it = args.options.find("--samples"); it != args.options.end()) {
        samples = parseInteger(it->second, "--samples");
        if (samples < 1 || samples > 1000) {
            throw UsageError{"option '--samples' must be between 1 and 1000"};
        }
    }
    const std::string output = requiredOutput(args);
    const model::Project project = io::loadProjectFile(QString::fromStdString(args.positional[0]));
    io::saveInterchangeJsonFile(project, QString::fromStdString(output), samples);
    std::cout << "Wrote " << output << "\n";
    return kExitOk;
}

int commandExamples() {
    for (const model::ExampleInfo& info : model::builtInExamples()) {
        std::cout << info.name << ": " << info.description << "; size " << info.minSize << "–"
                  << info.maxSize << ", default " << info.defaultSize << "\n";
    }
    return kExitOk;
}

int run(const std::vector<std::string>& args) {
    if (args.empty()) {
        throw UsageError{"a command is missing"};
    }
    const std::string& command = args[0];
    const std::vector<std::string> rest(args.begin() + 1, args.end());
    if (command == "-h" || command == "--help" || command == "help") {
        std::cout << kUsage;
        return kExitOk;
    }
    if (command == "--version") {
        std::cout << "devsurf-cli " << DEVSURF_VERSION << " (project file format "
                  << io::kProjectFormatVersion << ", interchange format " << io::kInterchangeVersion
                  << ")\n";
        return kExitOk;
    }
    for (const std::string& arg : rest) {
        if (arg == "-h" || arg == "--help") {
            std::cout << kUsage;
            return kExitOk;
        }
    }
    if (command == "example") {
        return commandExample(rest);
    }
    if (command == "info") {
        return commandInfo(rest);
    }
    if (command == "validate") {
        return commandValidate(rest);
    }
    if (command == "pin") {
        return commandPin(rest);
    }
    if (command == "crease") {
        return commandCrease(rest);
    }
    if (command == "smooth") {
        return commandSmooth(rest);
    }
    if (command == "export-json") {
        return commandExportJson(rest);
    }
    if (command == "examples") {
        return commandExamples();
    }
    if (command == "solve") {
        const Arguments args = parse(rest, {"-o", "--iterations", "--perturb", "--seed", "--fix"});
        try {
            return app::runSolveCommand(args.positional,
                                        {args.options.begin(), args.options.end()});
        } catch (const std::invalid_argument& error) {
            throw UsageError{error.what()};
        }
    }
    if (command == "export" || command == "report") {
        try {
            return command == "export" ? app::runExportPatternCommand(rest)
                                       : app::runReportCommand(rest);
        } catch (const std::invalid_argument& error) {
            throw UsageError{error.what()};
        }
    }
    if (command == "drag") {
        std::vector<std::string> valued;
        bool saidKeep = false;
        bool saidStretch = false;
        for (const std::string& arg : rest) {
            if (arg == "--keep-lengths") {
                saidKeep = true;
            } else if (arg == "--stretch") {
                saidStretch = true;
            } else {
                valued.push_back(arg);
            }
        }
        if (saidKeep && saidStretch) {
            throw UsageError{"--keep-lengths and --stretch exclude each other"};
        }
        const Arguments args = parse(valued, {"-o", "--vertices", "--crease", "--by", "--rotate",
                                              "--steps", "--pin", "--after", "--surface"});
        std::vector<std::pair<std::string, std::string>> options(args.options.begin(),
                                                                 args.options.end());
        if (saidKeep || saidStretch) {
            options.emplace_back(saidKeep ? "--keep-lengths" : "--stretch", "");
        }
        try {
            return app::runDragCommand(args.positional, options);
        } catch (const std::invalid_argument& error) {
            throw UsageError{error.what()};
        }
    }
    if (command == "bench") {
        throw UsageError{"the benchmark is the separate program 'devsurf-bench' (devsurf-bench "
                         "[--json])"};
    }
    throw UsageError{"unknown command '" + command + "'"};
}

} // namespace

int main(int argc, char** argv) {
    const auto application = devsurf::app::makeCliApplication(argc, argv);
    std::vector<std::string> args(argv + 1, argv + argc);
    try {
        return run(args);
    } catch (const UsageError& error) {
        std::cerr << "devsurf-cli: " << error.message << ". Run 'devsurf-cli --help' for usage.\n";
        return kExitUsage;
    } catch (const io::FileError& error) {
        std::cerr << "devsurf-cli: " << error.what() << "\n";
        return kExitInput;
    } catch (const model::ModelError& error) {
        std::cerr << "devsurf-cli: " << error.what() << "\n";
        return kExitInput;
    } catch (const std::exception& error) {
        std::cerr << "devsurf-cli: unexpected failure: " << error.what() << "\n";
        return kExitInput;
    }
}
