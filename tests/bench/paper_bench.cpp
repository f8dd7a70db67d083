#include "paper_bench.h"
#include "bench_json.h"

#include "model/development.h"
#include "model/examples.h"
#include "model/model_error.h"
#include "model/sampled_mesh.h"
#include "model/sheet_domain.h"
#include "solver/core/blas_info.h"
#include "solver/core/guided_projection.h"
#include "solver/formulation/perturbation.h"
#include "solver/formulation/surface_formulation.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <utility>

namespace devsurf::bench {

namespace {

// One Fig. 17 row: the example that stands for it and the shape of the sheet it is confined to.
struct PaperCandidate {
    std::string name;
    std::string example; // a built-in example, or "two-strips" (makeTwoStripSheet, curved)
    model::SheetShape shape;
    PaperRow paper;
    std::string note;
};

// The bow (mm) of the curved crease of the Fig. 13 row, as fig6's.
constexpr double kTwoStripBow = 30.0;
// Intervals tried for the two-strip model (its size).
constexpr int kTwoStripMaxIntervals = 200;

model::CompositeSurface makeModel(const std::string& example, int size) {
    if (example == "two-strips") {
        return makeTwoStripSheet(size, kTwoStripBow);
    }
    return model::makeExample(example, size).surfaces.front();
}

std::pair<int, int> sizeRange(const std::string& example) {
    if (example == "two-strips") {
        return {1, kTwoStripMaxIntervals};
    }
    for (const model::ExampleInfo& e : model::builtInExamples()) {
        if (e.name == example) {
            return {e.minSize, e.maxSize};
        }
    }
    throw std::invalid_argument("no example " + example);
}

PaperRow paperRow(const char* figure, int controlPoints, int strips, int variables,
                  double flatnessMean, double flatnessMax, double secondsPerIteration) {
    PaperRow row;
    row.figure = figure;
    row.controlPoints = controlPoints;
    row.strips = strips;
    row.variables = variables;
    row.flatnessMean = flatnessMean;
    row.flatnessMax = flatnessMax;
    row.secondsPerIteration = secondsPerIteration;
    return row;
}

// Fig. 17's rows (MATH.md §8) and the examples that stand for them.
std::vector<PaperCandidate> candidates() {
    using model::SheetShape;
    std::vector<PaperCandidate> rows(5);
    rows[0] = {"fig8", "fig8", SheetShape::Rectangle,
               paperRow("8", 60, 9, 6147, 4.7e-5, 1.6e-4, 0.06), ""};
    // fig6 (two strips, one curved crease) reaches 1,845 variables at its largest size (40
    // intervals): the bench's own two-strip model with the same crease goes further.
    rows[1] = {"fig13", "two-strips", SheetShape::Rectangle,
               paperRow("13", 36, 2, 3795, 1.4e-4, 4.4e-4, 0.04),
               "the paper's Fig. 13 is a disk; here two strips with one curved crease (as fig6) "
               "on their rectangle"};
    rows[2] = {"fig12", "annulus", SheetShape::Annulus,
               paperRow("12", 270, 48, 29574, 1.8e-3, 5.8e-3, 0.36), ""};
    rows[3] = {"fig15a", "sheet", SheetShape::Rectangle,
               paperRow("15a", 320, 32, 39648, 7.2e-5, 7.5e-4, 0.8),
               "the paper's Fig. 15a is a free-form design; here a square of strips on its "
               "rectangle"};
    // The paper's Fig. 12 is folded: the fig12 example, folded exactly, on its own sheet (the
    // Outline its example comes with) stands for it too.
    rows[4] = {"fig12-folded", "fig12", SheetShape::Outline,
               paperRow("12", 270, 48, 29574, 1.8e-3, 5.8e-3, 0.36),
               "the fig12 example: a ring folded along concentric creases (scaled copies of one "
               "wavy curve, not circles), on its own lobed sheet"};
    return rows;
}

std::string shapeName(model::SheetShape shape) {
    switch (shape) {
    case model::SheetShape::Free:
        return "free";
    case model::SheetShape::Rectangle:
        return "rectangle";
    case model::SheetShape::Disk:
        return "disk";
    case model::SheetShape::Annulus:
        return "annulus";
    case model::SheetShape::Outline:
        return "outline";
    case model::SheetShape::Cylinder:
        return "cylinder";
    }
    return "?";
}

std::string sheetText(const model::SheetDomain& d) {
    char text[128];
    switch (d.shape) {
    case model::SheetShape::Rectangle:
        std::snprintf(text, sizeof text, "rectangle %.1f x %.1f mm", d.width, d.height);
        break;
    case model::SheetShape::Disk:
        std::snprintf(text, sizeof text, "disk r %.1f mm", d.radius);
        break;
    case model::SheetShape::Annulus:
        std::snprintf(text, sizeof text, "annulus r %.1f..%.1f mm", d.innerRadius, d.radius);
        break;
    case model::SheetShape::Outline:
        std::snprintf(text, sizeof text, "outline of %zu loops", d.outline.size());
        break;
    default:
        std::snprintf(text, sizeof text, "%s", shapeName(d.shape).c_str());
    }
    return text;
}

// The example at `size` holding the sheet it unfolds to, confined to the smallest sheet of
// `shape` around that development (model::fittingDomain); an Outline: the example's own.
model::CompositeSurface paperSurface(const PaperCandidate& c, int size) {
    model::CompositeSurface surface = makeModel(c.example, size);
    if (c.shape == model::SheetShape::Outline) {
        return surface;
    }
    if (const auto problem = model::keepDevelopment(surface)) {
        throw model::ModelError(*problem);
    }
    const model::SampledMesh mesh =
        model::sampleSurface(surface, model::kDevelopmentSamplesPerInterval);
    surface.setSheetDomain(model::fittingDomain(c.shape, mesh, surface.development()));
    return surface;
}

// The development as solver::SolveSession sets it up for a surface that keeps its development,
// and the three boundary vertices the solver benchmark fixes.
solver::FormulationOptions paperFormulation(const model::CompositeSurface& surface,
                                            const std::vector<model::VertexId>& anchors) {
    solver::FormulationOptions f;
    for (model::VertexId v : anchors) {
        f.handles.push_back({v, true, {}});
    }
    f.developmentSamplesPerInterval = model::kDevelopmentSamplesPerInterval;
    f.developmentStart = surface.development();
    f.fixedDevelopment = surface.sheetDomain().isFree();
    f.developmentDomain = surface.sheetDomain();
    return f;
}

int variableCount(const model::CompositeSurface& surface) {
    const auto anchors = solver::spreadBoundaryVertices(surface, 3);
    return solver::SurfaceFormulation(surface, paperFormulation(surface, anchors))
        .problem()
        .variableCount();
}

// The size of the example whose variable count is nearest the paper's (counts grow with the
// size, so the scan stops once past it).
int nearestSize(const PaperCandidate& c, int cap, int& variables) {
    const auto [first, largest] = sizeRange(c.example);
    const int last = cap > 0 ? std::min(cap, largest) : largest;
    int best = first;
    variables = -1;
    for (int size = first; size <= std::max(last, first); ++size) {
        const int n = variableCount(paperSurface(c, size));
        if (variables < 0 ||
            std::abs(n - c.paper.variables) < std::abs(variables - c.paper.variables)) {
            best = size;
            variables = n;
        }
        if (n > c.paper.variables) {
            break;
        }
    }
    return best;
}

// One run of `iterations` iterations as a SolveSession steps them: one solve() per iteration,
// the schedule continued, the development's fairness measured from the state before it.
struct Run {
    std::vector<solver::IterationStats> iterations;
    std::string status;
    double residual = 0.0;
    std::vector<double> x;
};

Run solveRun(solver::SurfaceFormulation& formulation, const std::vector<double>& start,
             const PaperBenchOptions& options, bool baseline) {
    solver::Options o;
    o.maxIterations = 1;
    o.eps2 = options.eps2;
    if (baseline) {
        o.factorization = solver::FactorizationMethod::Automatic;
    }
    solver::GuidedProjection projection;
    solver::ExperimentalOptions experimental;
    experimental.baseline = baseline;
    projection.setExperimentalOptions(experimental);
    Run run;
    run.x = start;
    for (int i = 0; i < options.iterations; ++i) {
        o.scheduleOffset = i;
        formulation.rebaseDevelopmentFairness(run.x);
        const solver::Summary s = projection.solve(formulation.problem(), run.x, o);
        run.iterations.insert(run.iterations.end(), s.iterations.begin(), s.iterations.end());
        run.status = solver::toString(s.status);
        run.residual = s.finalMaxConstraintResidual;
        if (s.status == solver::Status::Converged) {
            break;
        }
    }
    return run;
}

// Medians per phase over iterations 2..N (the first carries the analysis and cold caches).
PaperTiming timingOf(const std::vector<solver::IterationStats>& iterations) {
    std::vector<double> a, f, s, t;
    for (std::size_t i = 1; i < iterations.size(); ++i) {
        a.push_back(iterations[i].assemblyMs);
        f.push_back(iterations[i].factorizationMs);
        s.push_back(iterations[i].solveMs);
        t.push_back(iterations[i].assemblyMs + iterations[i].factorizationMs +
                    iterations[i].solveMs);
    }
    return {median(a), median(f), median(s), median(t)};
}

PaperTiming medianOf(const std::vector<PaperTiming>& runs) {
    std::vector<double> a, f, s, t;
    for (const PaperTiming& r : runs) {
        a.push_back(r.assembly);
        f.push_back(r.factorize);
        s.push_back(r.solve);
        t.push_back(r.total);
    }
    return {median(a), median(f), median(s), median(t)};
}

PaperRowResult runRow(const PaperCandidate& c, const PaperBenchOptions& options) {
    auto log = [&options](const std::string& line) {
        if (options.log) {
            options.log(line);
        }
    };
    PaperRowResult r;
    r.name = c.name;
    r.paper = c.paper;
    r.example = c.example;
    r.note = c.note;
    r.size = nearestSize(c, options.sizeCap, r.variables);
    r.withinTenPercent = std::abs(r.variables - c.paper.variables) <= 0.1 * c.paper.variables;
    model::CompositeSurface surface = paperSurface(c, r.size);
    r.sheet = sheetText(surface.sheetDomain());
    r.surface = surface;
    r.developmentVariables = 2 * static_cast<int>(surface.development().size());
    log("paper " + c.name + ": " + c.example + " size " + std::to_string(r.size) + ", " +
        std::to_string(r.variables) + " variables (paper " + std::to_string(c.paper.variables) +
        ")");

    // The start: the benchmark's (noise on the control points, three boundary vertices fixed);
    // the development starts as the unperturbed sheet.
    const std::vector<model::VertexId> anchors = solver::spreadBoundaryVertices(surface, 3);
    const double scale = options.noiseOfDiameter ? solver::surfaceDiameter(surface)
                                                 : solver::meanControlSpacing(surface);
    solver::perturbSurface(surface, options.noise * scale, options.seed, anchors);
    solver::SurfaceFormulation formulation(surface, paperFormulation(surface, anchors));
    const std::vector<double> start = formulation.initialState();

    std::vector<PaperTiming> timings;
    Run last;
    for (int i = 0; i < std::max(1, options.runs); ++i) {
        last = solveRun(formulation, start, options, false);
        timings.push_back(timingOf(last.iterations));
    }
    r.ours = medianOf(timings);
    r.status = last.status;
    r.residual = last.residual;
    r.paperRatio = r.ours.total / (1000.0 * c.paper.secondsPerIteration);
    model::CompositeSurface result = surface;
    std::string error;
    if (!formulation.writeBack(last.x, result, &error)) {
        r.status = error;
    } else if (const auto problems = result.validate(); !problems.empty()) {
        r.status = "degenerate result: " + model::technicalKey(problems.front());
    } else {
        r.quality = solver::measureQuality(result);
        r.developmentEdgeError = model::keptSheetStretchRelative(result);
        r.sheetStretchMm = model::keptSheetStretch(result);
    }
    log("paper " + c.name + ": " + std::to_string(r.ours.total) + " ms/iteration, residual " +
        std::to_string(r.residual));

    if (options.runBaseline) {
        std::vector<PaperTiming> baseline;
        for (int i = 0; i < std::max(1, options.runs); ++i) {
            baseline.push_back(timingOf(solveRun(formulation, start, options, true).iterations));
        }
        r.baseline = medianOf(baseline);
        r.baselineRatio = r.ours.total > 0.0 ? r.baseline.total / r.ours.total : 0.0;
        log("paper " + c.name + ": baseline " + std::to_string(r.baseline.total) + " ms/iteration");
    }
    return r;
}

std::string timingJson(const PaperTiming& t) {
    return "{ \"assembly_ms\": " + number(t.assembly) +
           ", \"factorize_ms\": " + number(t.factorize) + ", \"solve_ms\": " + number(t.solve) +
           ", \"total_ms\": " + number(t.total) + " }";
}

} // namespace

PaperReport runPaperBench(const PaperBenchOptions& options) {
    PaperReport report;
    char start[160];
    std::snprintf(start, sizeof start,
                  "Gaussian noise sigma = %g x the %s on the control points, seed %u, three "
                  "boundary vertices fixed",
                  options.noise,
                  options.noiseOfDiameter ? "diameter" : "mean control-polygon edge length",
                  options.seed);
    report.start = start;
    report.iterations = options.iterations;
    report.runs = std::max(1, options.runs);
    for (const PaperCandidate& c : candidates()) {
        if (!options.models.empty() && std::find(options.models.begin(), options.models.end(),
                                                 c.name) == options.models.end()) {
            continue;
        }
        report.rows.push_back(runRow(c, options));
    }
    // The timings are only as good as the machine was quiet: the load says how shared it was.
    if (std::FILE* file = std::fopen("/proc/loadavg", "r")) {
        if (std::fscanf(file, "%lf", &report.loadAverage) != 1) {
            report.loadAverage = -1.0;
        }
        std::fclose(file);
    }
    return report;
}

void printPaperBench(const PaperReport& report, bool json, std::ostream& out) {
    const solver::BlasInfo blas = solver::detectBlas();
    if (json) {
        out << "{\n  \"blas\": " << quoted(blas.describe())
            << ",\n  \"blas_kernel\": " << quoted(blas.kernel)
            << ",\n  \"blas_kernel_chosen_by\": " << quoted(blas.kernelChosenBy)
            << ",\n  \"start\": " << quoted(report.start)
            << ",\n  \"iterations\": " << report.iterations
            << ",\n  \"timing_runs\": " << report.runs
            << ",\n  \"load_average\": " << number(report.loadAverage) << ",\n  \"rows\": [";
        for (std::size_t i = 0; i < report.rows.size(); ++i) {
            const PaperRowResult& r = report.rows[i];
            const solver::QualityMeasures& q = r.quality;
            out << (i == 0 ? "\n" : ",\n") << "    { \"model\": " << quoted(r.name)
                << ", \"paper_figure\": " << quoted(r.paper.figure)
                << ", \"example\": " << quoted(r.example) << ", \"size\": " << r.size
                << ", \"sheet\": " << quoted(r.sheet) << ", \"variables\": " << r.variables
                << ", \"development_variables\": " << r.developmentVariables
                << ", \"paper_variables\": " << r.paper.variables
                << ", \"within_10_percent\": " << (r.withinTenPercent ? "true" : "false")
                << ", \"note\": " << quoted(r.note) << ", \"status\": " << quoted(r.status)
                << ", \"residual\": " << number(r.residual)
                << ",\n      \"ours\": " << timingJson(r.ours)
                << ",\n      \"baseline\": " << timingJson(r.baseline)
                << ",\n      \"paper_s_per_iter\": " << number(r.paper.secondsPerIteration)
                << ", \"ratio_to_paper\": " << number(r.paperRatio)
                << ", \"baseline_over_ours\": " << number(r.baselineRatio)
                << ",\n      \"flatness_mean\": " << number(q.flatnessMean)
                << ", \"flatness_max\": " << number(q.flatnessMax)
                << ", \"paper_flatness_mean\": " << number(r.paper.flatnessMean)
                << ", \"paper_flatness_max\": " << number(r.paper.flatnessMax)
                << ", \"curvature_mean\": " << number(q.curvatureMean)
                << ", \"curvature_max\": " << number(q.curvatureMax)
                << ", \"det_max\": " << number(q.developabilityMax)
                << ", \"development_edge_error\": " << number(r.developmentEdgeError)
                << ", \"sheet_stretch_mm\": " << number(r.sheetStretchMm) << " }";
        }
        out << "\n  ]";
        auto dragJson = [](const PaperDrag& d) {
            return "{ \"measured\": " + std::string(d.measured ? "true" : "false") +
                   ", \"model\": " + quoted(d.model) +
                   ", \"development\": " + quoted(d.development) +
                   ", \"variables\": " + std::to_string(d.variables) +
                   ", \"median_ms\": " + number(d.medianMs) + ", \"p95_ms\": " + number(d.p95Ms) +
                   ", \"residual_after\": " + number(d.residualAfter) +
                   ", \"error\": " + quoted(d.error) + " }";
        };
        out << ",\n  \"drag\": " << dragJson(report.drag) << ",\n  \"drag_references\": [";
        for (std::size_t i = 0; i < report.dragReferences.size(); ++i) {
            out << (i == 0 ? "\n    " : ",\n    ") << dragJson(report.dragReferences[i]);
        }
        out << "\n  ]\n}\n";
        return;
    }
    out << "BLAS: " << blas.describe() << "\n";
    if (!blas.kernel.empty()) {
        out << "BLAS kernel: " << blas.kernel << ", chosen by " << blas.kernelChosenBy << "\n";
    }
    out << "Start: " << report.start << "; " << report.iterations << " iterations; timing: "
        << "medians over iterations 2.." << report.iterations << ", then over " << report.runs
        << " runs; load average " << number(report.loadAverage) << "\n";
    char line[512];
    std::snprintf(line, sizeof line, "%-7s %-10s %4s %7s %7s %4s %8s %8s %8s %8s %8s %7s %7s\n",
                  "row", "example", "size", "vars", "paper", "10%", "asm ms", "fact ms", "solve ms",
                  "ms/iter", "base ms", "/paper", "base×");
    out << line;
    for (const PaperRowResult& r : report.rows) {
        std::snprintf(line, sizeof line,
                      "%-7s %-10s %4d %7d %7d %4s %8.3f %8.3f %8.3f %8.3f %8.3f %7.4f %7.1f\n",
                      r.name.c_str(), r.example.c_str(), r.size, r.variables, r.paper.variables,
                      r.withinTenPercent ? "yes" : "no", r.ours.assembly, r.ours.factorize,
                      r.ours.solve, r.ours.total, r.baseline.total, r.paperRatio, r.baselineRatio);
        out << line;
    }
    out << "\nQuality after the iterations (δ, |K| on the mesh sampled at 8 per interval; the "
           "paper's δ from Fig. 17, which gives no |K|; edge err: relative, vs the kept "
           "development)\n";
    std::snprintf(line, sizeof line, "%-7s %9s %9s %9s %9s %9s %9s %9s %9s %9s\n", "row", "δ mean",
                  "δ max", "paper δ̄", "paper δ⁺", "|K| mean", "|K| max", "det max", "edge err",
                  "residual");
    out << line;
    for (const PaperRowResult& r : report.rows) {
        const solver::QualityMeasures& q = r.quality;
        std::snprintf(line, sizeof line,
                      "%-7s %9.2e %9.2e %9.2e %9.2e %9.2e %9.2e %9.2e %9.2e %9.2e  %s\n",
                      r.name.c_str(), q.flatnessMean, q.flatnessMax, r.paper.flatnessMean,
                      r.paper.flatnessMax, q.curvatureMean, q.curvatureMax, q.developabilityMax,
                      r.developmentEdgeError, r.residual, r.status.c_str());
        out << line;
    }
    for (const PaperRowResult& r : report.rows) {
        out << r.name << ": " << r.example << " size " << r.size << " on its sheet, " << r.sheet
            << " (" << r.developmentVariables << " development variables)"
            << (r.note.empty() ? "" : "; " + r.note) << "\n";
    }
    std::vector<PaperDrag> drags{report.drag};
    drags.insert(drags.end(), report.dragReferences.begin(), report.dragReferences.end());
    for (const PaperDrag& d : drags) {
        if (!d.measured) {
            continue;
        }
        std::snprintf(line, sizeof line,
                      "Drag of %s, %s (%d variables): move to applied median %.1f ms, p95 %.1f "
                      "ms, residual after %.2e%s%s\n",
                      d.model.c_str(), d.development.c_str(), d.variables, d.medianMs, d.p95Ms,
                      d.residualAfter, d.error.empty() ? "" : "; failed: ", d.error.c_str());
        out << line;
    }
}

} // namespace devsurf::bench
