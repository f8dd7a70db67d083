#include "cli_arguments.h"

#include "model/model_error.h"

#include <algorithm>
#include <cmath>

namespace devsurf::app {

namespace {

int wholeOption(const SubcommandArguments& args, const char* name, long low, long high,
                int fallback) {
    const std::optional<std::string> text = args.value(name);
    return text ? static_cast<int>(parseWhole(*text, optionText(name), low, high)) : fallback;
}

} // namespace

model::RigidMotion DragMotion::at(double t) const {
    return rotate ? model::RigidMotion::rotationAbout(point, axis, radians * t)
                  : model::RigidMotion::translationBy(by * t);
}

SolveArguments solveArguments(const SubcommandArguments& args) {
    SolveArguments result;
    result.input = args.onePositional("one project file");
    if (args.value("iterations")) {
        result.iterations = wholeOption(args, "iterations", 1, 10000, 0);
    }
    if (const std::optional<std::string> sigma = args.value("perturb")) {
        result.perturb = parseReal(*sigma, "--perturb", 0.0, 1e6);
    }
    if (const std::optional<std::string> seed = args.value("seed")) {
        if (!result.perturb) {
            throw UsageError{"option '--seed' only makes sense with '--perturb'"};
        }
        result.seed = static_cast<unsigned>(parseWhole(*seed, "--seed", 0, 0x7fffffff));
    }
    if (const std::optional<std::string> ids = args.value("fix")) {
        result.fixed = parseIds(*ids, "--fix", "vertex");
    }
    result.output = args.required("o", kMissingOutput);
    return result;
}

DragArguments dragArguments(const SubcommandArguments& args) {
    DragArguments result;
    result.input = args.onePositional("one project file");
    if (args.isSet("keep-lengths") && args.isSet("stretch")) {
        throw UsageError{"--keep-lengths and --stretch exclude each other"};
    }
    const std::optional<std::string> vertices = args.value("vertices");
    const std::optional<std::string> crease = args.value("crease");
    if (vertices && crease) {
        throw UsageError{"give either --vertices IDS or --crease EDGE, not both"};
    }
    if (!vertices && !crease) {
        throw UsageError{"the vertices to drag are missing (use --vertices IDS, or --crease EDGE "
                         "to drag a crease)"};
    }
    if (crease) {
        const std::vector<std::uint32_t> edges = parseIds(*crease, "--crease", "edge");
        if (edges.size() != 1) {
            throw UsageError{"option '--crease' needs one edge id"};
        }
        result.crease = edges.front();
        if (args.isSet("rotate")) {
            throw UsageError{"a crease is dragged with --by DX,DY,DZ, not rotated"};
        }
    } else {
        result.vertices = parseIds(*vertices, "--vertices", "vertex");
    }
    const std::optional<std::string> by = args.value("by");
    const std::optional<std::string> rotate = args.value("rotate");
    if (by.has_value() == rotate.has_value()) {
        throw UsageError{"give the motion as either --by DX,DY,DZ or --rotate "
                         "PX,PY,PZ,AX,AY,AZ,DEGREES"};
    }
    if (by) {
        const std::vector<double> v = parseReals(*by, "--by", 3, "0,0,100");
        result.motion.by = {v[0], v[1], v[2]};
    } else {
        const std::vector<double> v = parseReals(*rotate, "--rotate", 7, "0,0,0,0,0,1,30");
        result.motion.rotate = true;
        result.motion.point = {v[0], v[1], v[2]};
        result.motion.axis = {v[3], v[4], v[5]};
        result.motion.radians = v[6] * std::acos(-1.0) / 180.0;
        try {
            result.motion.at(1.0); // refuses a zero or non-finite axis
        } catch (const model::ModelError&) {
            throw UsageError{"option '--rotate' needs a non-zero axis AX,AY,AZ of finite length"};
        }
    }
    if (const std::optional<std::string> pins = args.value("pin")) {
        result.pins = parseIds(*pins, "--pin", "vertex");
    }
    result.steps = wholeOption(args, "steps", 1, 10000, 20);
    if (args.isSet("after")) {
        result.after = wholeOption(args, "after", 0, 10000, 0);
    }
    result.surface = wholeOption(args, "surface", 1, 1000000, 0);
    result.output = args.required("o", kMissingOutput);
    for (model::VertexId id : result.pins) {
        if (std::find(result.vertices.begin(), result.vertices.end(), id) !=
            result.vertices.end()) {
            throw UsageError{"vertex " + std::to_string(id) + " cannot be both dragged and pinned"};
        }
    }
    // As the drag tool: a dragged crease changes the sizes of its strips on purpose and never
    // keeps lengths; a vertex drag keeps them unless --stretch, and without --keep-lengths
    // (Automatic) is replayed stretching where keeping them fails.
    result.lengths = result.crease || args.isSet("stretch") ? solver::DragLengths::Stretch
                     : args.isSet("keep-lengths")           ? solver::DragLengths::Keep
                                                            : solver::DragLengths::Automatic;
    return result;
}

} // namespace devsurf::app
