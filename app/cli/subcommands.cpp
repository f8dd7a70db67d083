#include "subcommands.h"

namespace devsurf::app {

namespace {

const OptionSpec kOutputProject{"o", "OUT.devsurf", "The project file to write."};
const OptionSpec kSurface{"surface", "K", "The surface to change (1 for the first, the default)."};

// The pattern options export and report share.
std::vector<OptionSpec> patternOptions(std::vector<OptionSpec> more) {
    std::vector<OptionSpec> options{
        {"sheet", "W,H", "Sheets of W x H mm (default 600,400)."},
        {"paper", "A4|A3|Letter", "Sheets of a paper's printable size."},
        {"tolerance", "MM", "Curves within MM (default 0.01)."},
        {"seam", "MM", "A seam allowance of MM."},
        {"rulings", "", "Rulings as scoring lines."}};
    options.insert(options.end(), more.begin(), more.end());
    return options;
}

} // namespace

const std::vector<SubcommandSpec>& subcommands() {
    static const std::vector<SubcommandSpec> all{
        {"example",
         "example NAME [--size K] [--as-built | --hold-sheet] -o FILE.devsurf",
         "Write a built-in example (sheet, annulus, cylinder, mixed,\n"
         "fig8, fig6, fig13, torus, column, fig12; `devsurf-cli examples` lists\n"
         "them).\n"
         "An example that starts flat holds the sheet it starts as, as\n"
         "File > New from Example makes it by default: its development kept on\n"
         "the smallest rectangle (annulus for the annulus, free for mixed)\n"
         "around it, curved-fold creases kept where they lie, and of two pins\n"
         "at the ends of a straight line in the sheet only the first kept;\n"
         "the cylinder holds the cylinder its unfolding rolls onto.\n"
         "--as-built writes it as it comes, its sheet unfolded after each\n"
         "solve; --hold-sheet refuses an example that unfolds into no one\n"
         "sheet (the torus) instead of writing it as it comes.",
         {{"size", "K", "The example's size."},
          {"as-built", "", "Write it as it comes, holding no sheet."},
          {"hold-sheet", "", "Refuse an example that cannot hold a sheet."},
          {"o", "FILE.devsurf", "The project file to write."}}},
        {"info",
         "info FILE [--vertices] [--edges] [--json]",
         "Print surfaces, faces per type, spline spaces, control points,\n"
         "vertices and edges, and every reference shape (name, points,\n"
         "triangles); --vertices lists every vertex (id, x y z, pinned,\n"
         "boundary), --edges every edge (id, R or S, its vertices, crease\n"
         "condition, smooth or sharp); --json prints those lists as JSON.",
         {{"vertices", "", "List every vertex."},
          {"edges", "", "List every edge."},
          {"json", "", "Print the lists as JSON."}}},
        {"pin",
         "pin FILE --vertices IDS [--unpin] [--surface K] -o OUT.devsurf",
         "Pin vertices (the solver never moves them) or release them.",
         {{"vertices", "IDS", "The vertices, such as 0,4,7."},
          {"unpin", "", "Release the vertices instead."},
          kSurface,
          kOutputProject}},
        {"sheet",
         "sheet FILE (--free | --rectangle W,H | --disk R | --annulus R1,R2 |\n"
         "      --outline FILE.dxf|FILE.svg | --off)\n"
         "      [--creases FILE.dxf|FILE.svg | --keep-creases] [--surface K] -o OUT.devsurf",
         "Hold the sheet: the surface keeps its development, and every solve\n"
         "and drag keeps it isometric to that sheet (a dragged vertex lags\n"
         "where the sheet cannot follow, instead of the sheet stretching).\n"
         "--free holds the development as it unfolds now. --rectangle, --disk,\n"
         "--annulus and --outline (the closed curves of a DXF, SVG, STEP or\n"
         "IGES file seen from above: the largest the outer boundary, the others\n"
         "holes) confine it to that sheet, placed where it fits the\n"
         "development best: the development may then change inside the\n"
         "sheet, its boundary on the sheet's, its corners at the sheet's; the\n"
         "next solve moves a development that does not fit yet onto the\n"
         "sheet. --off lets the sheet stretch again. Only a surface that\n"
         "unfolds into one flat sheet can hold it. Sizes are in mm.\n"
         "--creases draws the crease pattern in the sheet: every curve of that\n"
         "file (open or closed, seen from above, in the sheet's frame: the\n"
         "rectangle from 0,0 to W,H, circles centred at 0,0, an outline's own\n"
         "coordinates) holds the creases whose development lies near it (on\n"
         "average within half the crease's length, no other crease nearer\n"
         "it), every sample of\n"
         "such a crease on the curve's tangent line; the next solve moves them\n"
         "onto their curves. --keep-creases draws them where they lie in the\n"
         "development now: the crease pattern stays as it is while the rulings\n"
         "move in the sheet (so a flat design folds along its own creases).",
         {{"free", "", "Hold the sheet as it unfolds, its boundary free."},
          {"rectangle", "W,H", "Confine it to a W x H rectangle."},
          {"disk", "R", "Confine it to a disk of radius R."},
          {"annulus", "R1,R2", "Confine it to an annulus between radii R1 and R2."},
          {"outline", "FILE", "Confine it to the closed curves of a DXF, SVG, STEP or IGES file."},
          {"off", "", "No longer hold the sheet."},
          {"creases", "FILE", "Confine creases to the curves of a DXF, SVG, STEP or IGES file."},
          {"keep-creases", "", "Confine every crease to the curve it lies on in the sheet now."},
          kSurface,
          kOutputProject}},
        {"crease",
         "crease FILE --edges IDS --condition curved-fold|geodesic|straight|none [--surface K]\n"
         "      -o OUT.devsurf",
         "Set the condition the solver imposes on creases: a curved fold\n"
         "(the crease's osculating plane bisects the two patches), a\n"
         "geodesic, or straight when unfolded (in its left patch); none\n"
         "clears it.",
         {{"edges", "IDS", "The creases, such as 3,8."},
          {"condition", "CONDITION", "curved-fold, geodesic, straight or none."},
          kSurface,
          kOutputProject}},
        {"smooth",
         "smooth FILE --edges IDS [--off] [--surface K] -o OUT.devsurf",
         "Mark rulings between two patches smooth (the solver keeps the\n"
         "surface smooth across them); --off makes them sharp again.",
         {{"edges", "IDS", "The rulings, such as 3,8."},
          {"off", "", "Make them sharp again."},
          kSurface,
          kOutputProject}},
        {"validate", "validate FILE", "Check every invariant of the model; list all problems.", {}},
        {"export-json",
         "export-json FILE -o OUT.json [--samples N]",
         "Write the interchange JSON (docs/interchange-format.md);\n"
         "N samples per spline interval for the mesh (default 8).\n"
         "-o - writes it to standard output.",
         {{"o", "OUT.json", "The JSON file to write (- for standard output)."},
          {"samples", "N", "Samples per spline interval (1 to 1000)."}}},
        {"examples", "examples", "List the built-in examples and their sizes.", {}},
        {"solve",
         "solve FILE [--iterations N] [--perturb SIGMA [--seed S]] [--fix IDS] -o OUT.devsurf",
         "Solve every surface as Tools > Solve does (the same solve job): until\n"
         "the largest residual is below 1e-12, at most N iterations (default\n"
         "30), ending on the iterate of smallest residual and leaving a surface\n"
         "as it was where solving would make it less developable; write the\n"
         "result; one line per iteration (residual, time for\n"
         "assembly / factorisation / solve, quality). --perturb adds Gaussian\n"
         "noise of SIGMA times the surface's diameter first; --fix keeps the\n"
         "vertices with the given ids (e.g. 0,4,7) where they are. The output\n"
         "may be the input file (its previous version is kept as FILE.bak).",
         {{"iterations", "N", "At most N iterations (1 to 10000, default 30)."},
          {"perturb", "SIGMA", "Gaussian noise of SIGMA times the diameter first."},
          {"seed", "S", "The seed of the noise."},
          {"fix", "IDS", "Vertices kept where they are, such as 0,4,7."},
          kOutputProject}},
        {"drag",
         "drag FILE (--vertices IDS | --crease EDGE) (--by DX,DY,DZ | --rotate "
         "PX,PY,PZ,AX,AY,AZ,DEGREES)\n"
         "     [--steps N] [--pin IDS] [--after K] [--keep-lengths | --stretch] [--surface K]\n"
         "     -o OUT.devsurf",
         "Replay a drag as the desktop application runs it: the vertices are\n"
         "moved by DX,DY,DZ (or rotated by DEGREES about the axis AX,AY,AZ\n"
         "through PX,PY,PZ) in N evenly spaced steps (default 20) with one\n"
         "solver iteration each (on a surface that holds its sheet, a step\n"
         "longer than 0.3 % of the design's size takes one iteration per\n"
         "such length, at most 8; one on a design of more than 15,000\n"
         "solver variables), then K more iterations (default 20 when\n"
         "keeping lengths, else 10; they stop once the residual is below\n"
         "1e-12 and, on a held sheet, the surface no longer nears its sheet).\n"
         "Pins in the file stay; --pin pins more\n"
         "vertices. One line per step (residual, time, quality; a step\n"
         "of a large model that reused an earlier step's factorisation\n"
         "says so, and so does one whose reused factorisation threw it off\n"
         "and was undone). A vertex drag keeps lengths, as the desktop\n"
         "application does by default: stretching of every strip's\n"
         "control net is damped in each step, so the sheet bends rather\n"
         "than stretches (the damping fades over the K iterations after\n"
         "the moves; see the manual); where that fails (no convergence,\n"
         "a fold-over or an overlapping development) the drag is\n"
         "replayed letting the sheet stretch and the result with fewer\n"
         "problems is written. --keep-lengths never replays; --stretch\n"
         "never keeps lengths. Keeping lengths, the iterations after the\n"
         "moves stop early once the residual has stayed above 1e-2 for 4\n"
         "iterations in a row (on a held sheet above 0.1 for 6): they\n"
         "would not converge. A drag whose result would be broken (a\n"
         "patch folded over, a patch sampled more than 1e-4 from\n"
         "developable, or off the sheet it holds) is, keeping lengths, first\n"
         "settled once more from the last step, the damping fading more\n"
         "slowly (\"Settled again\"); if that fails too, it is taken back as far\n"
         "as it must: released at the latest state the drag passed through\n"
         "that then settles developable (a search of at most 1.5 s; on a\n"
         "model too large for that, at most three states from before the\n"
         "moves' residual jumped, each settled as long as the release; one\n"
         "\"partway\" line per iteration of the search), the surface follows\n"
         "part of the way, the dragged points lagging behind their targets;\n"
         "otherwise it is written as it was before the drag.\n"
         "--crease EDGE\n"
         "instead of --vertices drags a crease by DX,DY,DZ: its control points\n"
         "and unpinned ends slide within the surface, along the rulings of the\n"
         "strip the crease leaves (the component along the surface normal is\n"
         "dropped), and the strips on both sides change size; a crease drag\n"
         "never keeps lengths.",
         {{"vertices", "IDS", "The vertices to drag, such as 0,4,7."},
          {"crease", "EDGE", "The crease to drag."},
          {"by", "DX,DY,DZ", "Move by this vector."},
          {"rotate", "PX,PY,PZ,AX,AY,AZ,DEGREES", "Rotate about the axis through a point."},
          {"steps", "N", "Steps of the drag (1 to 10000, default 20)."},
          {"pin", "IDS", "More vertices to pin."},
          {"after", "K", "Iterations after the moves (0 to 10000)."},
          {"keep-lengths", "", "Keep lengths; never replay stretching."},
          {"stretch", "", "Never keep lengths."},
          kSurface,
          kOutputProject}},
        {"export",
         "export FILE --format dxf|svg|pdf|fold [--sheet W,H | --paper A4|A3|Letter]\n"
         "       [--tolerance MM] [--splines] [--r12] [--seam MM] [--rulings] -o OUT\n"
         "export FILE --format step|step214|iges|obj|stl|ply [--tolerance MM]\n"
         "       [--thickness MM] -o OUT",
         "Write the cutting pattern: pieces laid out on sheets of W x H mm\n"
         "(default 600,400) or of a paper's printable size; curves within\n"
         "MM (default 0.01); DXF as SPLINEs (--splines) or R12 (--r12); a seam\n"
         "allowance of MM; rulings as scoring lines. PDF prints 1:1 on the\n"
         "paper (default A4), tiled, after the fabrication report. FOLD\n"
         "always has the rulings (as flat edges, for folding simulators).\n"
         "Or write the 3D shape: STEP (AP242; step214: AP214) or IGES with\n"
         "every patch's exact B-spline surface, each surface sewn into one\n"
         "shell, units mm; or a triangle mesh (OBJ with a group per patch,\n"
         "binary STL or PLY) within MM of the surface (default 0.01),\n"
         "optionally a sheet of --thickness MM (both sides offset, the rim\n"
         "closed). OUT must end in the format's extension (or have none);\n"
         "-o - writes DXF, SVG or FOLD to standard output.",
         patternOptions({{"format", "FORMAT",
                          "dxf, svg, pdf, fold, step, step214, iges, obj, stl or ply "
                          "(default: OUT's extension)."},
                         {"splines", "", "DXF: curves as SPLINEs."},
                         {"r12", "", "DXF: R12 instead of R2000."},
                         {"thickness", "MM", "Meshes: a sheet of this thickness."},
                         {"o", "OUT", "The file to write (- for standard output)."}})},
        {"import-curves",
         "import-curves FILE CURVES [--tolerance MM] -o OUT.devsurf",
         "Add the curves of a DXF (LINE, POLYLINE, LWPOLYLINE, SPLINE, ARC, CIRCLE,\n"
         "ELLIPSE), SVG (every shape, in the plane z = 0), STEP or IGES file\n"
         "(every edge) to the project as reference curves, sampled within MM\n"
         "(default 0.05), in mm. A file that cannot\n"
         "be read changes nothing and writes nothing. The output may be the\n"
         "project itself (its previous version is kept as FILE.bak), never\n"
         "the curve file.",
         {{"tolerance", "MM", "Sample curves within MM (default 0.05)."}, kOutputProject}},
        {"import-reference",
         "import-reference FILE TARGET [--name NAME] -o OUT.devsurf",
         "Add a mesh (OBJ, PLY, STL, OFF) or a point cloud (XYZ, PTS: one\n"
         "point per line, x y z, optionally followed by a normal nx ny nz;\n"
         "PTS may start with the number of points and carry more columns) to\n"
         "the project as a reference shape, in mm, named NAME (default: the\n"
         "file's name). Polygons become triangles. A file that cannot be read\n"
         "changes nothing and writes nothing. The output may be the project\n"
         "itself (its previous version is kept as FILE.bak), never the target.",
         {{"name", "NAME", "The shape's name (default: the file's name)."}, kOutputProject}},
        {"distance",
         "distance FILE TARGET [--json] [--tolerance MM]",
         "How far the project's surfaces are from a mesh or point cloud TARGET\n"
         "(as import-reference reads it): target to surface (each target point,\n"
         "a mesh's vertices, to its closest surface point) and surface to target\n"
         "(sampled; to a mesh's triangles, to a cloud's nearest point), each as\n"
         "mean, 95th percentile and max in mm and\n"
         "in % of the target's bounding-box diagonal, and the coverage: the\n"
         "fraction of target points within MM of the surface (default 1 % of\n"
         "the diagonal).",
         {{"json", "", "Print the report as JSON."},
          {"tolerance", "MM", "The coverage tolerance (default 1 % of the diagonal)."}}},
        {"approximate",
         "approximate TARGET [--from START.devsurf] [--strips K] [--intervals N]\n"
         "            [--iterations N] [--rho R] [--separate] [--join] -o OUT.devsurf",
         "Developable strips pulled towards a mesh or point cloud TARGET (as\n"
         "import-reference reads it): the target is thinned to points at least\n"
         "R mm apart (default 2 % of its bounding-box diagonal), each with the\n"
         "normal of a plane fitted to its neighbours; the strips of START, or K\n"
         "flat strips laid over K patches of the target (k-means on the points,\n"
         "a patch where the target curves both ways drawn out into a band twice\n"
         "as long as wide; default 1), are pulled towards the points they are\n"
         "nearest to for N iterations (default 30), then the pull fades out over\n"
         "10 more so the strips end exactly developable. A strip that cannot\n"
         "follow its points and stay developable (it leaves them, or ends not\n"
         "developable) is pulled again, more weakly and damped, from its start\n"
         "(a new strip: from the cylinder that fits its points best, 7 %\n"
         "larger than its points), and the summary says so. A new strip is\n"
         "then trimmed back where its sides or corners stand off the target,\n"
         "and solved again. Writes the strips and the target to\n"
         "OUT and prints the residual and the distance report. Where the target\n"
         "is one patch seen from one side (its normals within 75 degrees of its\n"
         "plane's, its heights over that plane single-valued), K >= 2 new strips\n"
         "are laid side by side as one surface instead, each two sharing a curve\n"
         "that may kink, bent to the target (its height a cubic along the curves\n"
         "plus a piecewise linear function across them, so every strip is a\n"
         "cylinder): watertight as laid, then pulled as one surface. Where the\n"
         "target instead closes around an axis (a tube, a vase, a sphere; one\n"
         "layer all around the line through its slabs' centres), K >= 2 rings\n"
         "are laid one after another around it, each two sharing a closed curve,\n"
         "every curve a scaled copy of one fitted closed curve so every ring is\n"
         "a cone: watertight but for its two ends (--separate: strips over\n"
         "patches as above, for either). With --join,\n"
         "the strips become one surface: the boundary curves or rulings of two\n"
         "strips that face each other (ends and middles apart by at most 20 %\n"
         "of their length) are pulled onto each other in a second approximation,\n"
         "welded into one shared edge, and the result pulled to the target once\n"
         "more; strips that face no other strip stay separate surfaces.",
         {{"from", "START.devsurf", "Start from the surfaces of this project."},
          {"strips", "K", "Start from K new strips (default 1)."},
          {"intervals", "N", "Spline intervals of each new strip (default 4)."},
          {"iterations", "N", "Iterations of the pull (default 30)."},
          {"rho", "R", "The thinning radius in mm."},
          {"separate", "", "Separate strips over patches, even over one patch or around an axis."},
          {"join", "", "Join strips whose edges face each other into one surface."},
          kOutputProject}},
        {"join",
         "join FILE [--surfaces IDS] [--iterations N] -o OUT.devsurf",
         "Join surfaces into one composite, as approximate --join and the\n"
         "application's Tools > Join Surfaces do: where a boundary curve or\n"
         "ruling of one faces one of another (ends and middles apart by at\n"
         "most 20 % of their length), the two are pulled onto each other and\n"
         "welded into one shared edge; the result is pulled towards the\n"
         "project's reference shapes where it has them, else solved. The\n"
         "joined surface takes the first one's place. Exits 2 and writes\n"
         "nothing when no two surfaces face each other.",
         {{"surfaces", "IDS", "The surfaces to join, such as 1,3 (default: all)."},
          {"iterations", "N", "Iterations of each step (default 30)."},
          kOutputProject}},
        {"fit-edge",
         "fit-edge FILE --edge E [--curve K] [--surface K] -o OUT.devsurf",
         "Lay spline edge E (a crease or a boundary) onto reference curve K\n"
         "(1-based, in the order they were imported; default: the one nearest\n"
         "it): its unpinned ends onto the curve, its control points by least\n"
         "squares along the piece between them. Solve afterwards to make the\n"
         "surface developable again.",
         {{"edge", "E", "The spline edge, such as 6."},
          {"curve", "K", "The reference curve (default: the nearest)."},
          kSurface,
          kOutputProject}},
        {"report", "report FILE [--json] [--sheet W,H | --paper NAME] [--tolerance MM] [--seam MM]",
         "Print the fabrication report: per piece its sheet, size, area,\n"
         "largest isometry error, overlaps, and whether it fits the sheet.",
         patternOptions({{"json", "", "Print the report as JSON."}})},
    };
    return all;
}

const SubcommandSpec* findSubcommand(const std::string& name) {
    for (const SubcommandSpec& spec : subcommands()) {
        if (name == spec.name) {
            return &spec;
        }
    }
    return nullptr;
}

std::string overallHelp() {
    std::string text = "Usage: devsurf-cli COMMAND [OPTIONS]\n\nCommands:\n";
    for (const SubcommandSpec& spec : subcommands()) {
        text += std::string("  ") + spec.synopsis + "\n";
        std::string description = spec.description;
        std::size_t start = 0;
        while (start < description.size()) {
            const std::size_t end = description.find('\n', start);
            text += "                      " +
                    description.substr(start, end == std::string::npos ? end : end - start) + "\n";
            start = end == std::string::npos ? description.size() : end + 1;
        }
    }
    return text + "\nThe solver benchmark is the separate program devsurf-bench [--json].\n\n"
                  "Options:\n"
                  "  -h, --help          Show this help (COMMAND --help: that command's).\n"
                  "  --version           Show the version.\n\n"
                  "Exit codes: 0 success, 1 bad usage, 2 invalid or unreadable input (or an\n"
                  "output that cannot be written).\n";
}

} // namespace devsurf::app
