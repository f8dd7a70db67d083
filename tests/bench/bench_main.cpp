// devsurf-bench: the solver benchmark (`devsurf-cli` no longer links it), and a quality
// study of one model over seeds with adjustable options (for measuring solver choices).
#include "approximation_bench.h"
#include "bench_models.h"
#include "benchmark.h"
#include "drag_bench.h"
#include "paper_bench.h"
#include "quality_study.h"

#include "model/examples.h"
#include "solver/core/blas_info.h"
#include "solver/formulation/perturbation.h"

#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <string>

namespace {

using namespace devsurf;

// Sets one option of the study by name; false if unknown.
bool setOption(bench::StudyOptions& o, const std::string& name, double v) {
    solver::FormulationOptions& f = o.formulation;
    solver::Options& s = o.solver;
    if (name == "normalizedRows")
        f.normalizedRows = v != 0.0;
    else if (name == "rulingGuard")
        f.rulingGuard = v;
    else if (name == "speedGuard")
        f.speedGuard = v;
    else if (name == "guardWeight")
        f.guardWeight = v;
    else if (name == "relativeFairness")
        f.relativeFairness = v != 0.0;
    else if (name == "fairnessWeight")
        f.fairnessWeight = v;
    else if (name == "normalFairnessWeight")
        f.normalFairnessWeight = v;
    else if (name == "unitControlNormalWeight")
        f.unitControlNormalWeight = v;
    else if (name == "exactNormalSpace")
        f.exactNormalSpace = v != 0.0;
    else if (name == "eps2")
        s.eps2 = v;
    else if (name == "eps2Minimum")
        s.eps2Minimum = v;
    else if (name == "eps1Initial")
        s.eps1Initial = v;
    else if (name == "eps1Decay")
        s.eps1Decay = v;
    else if (name == "eps1Iterations")
        s.eps1Iterations = static_cast<int>(v);
    else if (name == "eps1Final")
        s.eps1Final = v;
    else if (name == "guardShrinkLimit")
        s.guardShrinkLimit = v;
    else if (name == "residualEps2Maximum")
        s.eps2Schedule = solver::residualEps2Schedule(v, s.eps2Minimum, 1.0);
    else if (name == "eps1ResidualFactor")
        s.eps1ResidualFactor = v;
    else if (name == "rejectWorseSteps")
        o.experimental.rejectWorseSteps = v != 0.0;
    else if (name == "adaptiveEps2")
        s.adaptiveEps2 = v != 0.0;
    else if (name == "roughStart")
        solver::useRoughStartConfiguration(f, s);
    else if (name == "proximityWeight")
        f.proximityWeight = v;
    else if (name == "proximityThreshold")
        s.proximityThreshold = v;
    else if (name == "levenbergMarquardt")
        o.experimental.levenbergMarquardt = v != 0.0;
    else if (name == "normalProximityWeight")
        f.normalProximityWeight = v;
    else if (name == "proximityFactor")
        s.proximityFactor = v;
    else if (name == "proximityMaximum")
        s.proximityMaximum = v;
    else if (name == "fixed")
        o.fixedVertices = static_cast<int>(v);
    else
        return false;
    return true;
}

int runStudy(const std::string& name, const bench::StudyStart& start,
             const bench::StudyOptions& options, bool trace) {
    model::CompositeSurface surface;
    const auto models = bench::benchModels({name});
    if (!models.empty()) {
        surface = models.front().surface;
    } else {
        try {
            surface = model::makeExample(name, 0).surfaces.front();
        } catch (const std::exception& error) {
            std::cerr << "devsurf-bench: no model or example '" << name << "'.\n";
            return 1;
        }
    }
    const auto runs = bench::runStudy(surface, start, options);
    for (const auto& r : runs) {
        for (const solver::IterationStats& it :
             trace ? r.iterations : std::vector<solver::IterationStats>{}) {
            std::printf("  it %d eps1 %.1e eps2 %.1e mu %.1e res %.2e energy %.2e step %.2e%s\n",
                        it.iteration, it.eps1, it.eps2, it.proximity, it.maxConstraintResidual,
                        it.energy, it.stepNorm, it.rejected ? " rejected" : "");
        }
        std::printf(
            "seed %u %-16s res %.2e det %.2e flat %.2e ruling %.3f speed %.3f fold %.2f "
            "start %.2f deg move %.1e folded over %d development overlaps at %zu patches  %.2f "
            "ms/it\n",
            r.seed, r.status.c_str(), r.residual, r.detMax, r.flatnessMean, r.change.shortestRuling,
            r.change.slowestSpeed, r.change.creaseFoldMean * 57.2958,
            r.change.startNormalAngleMean * 57.2958,
            r.change.largestMove / solver::surfaceDiameter(surface), r.change.foldOverPlaces(),
            r.overlapping.size(), r.msPerIteration);
        if (r.ceresResidual >= 0.0) {
            std::printf("  Ceres from the same start: residual %.2e after %d iterations\n",
                        r.ceresResidual, r.ceresIterations);
        }
    }
    const auto s = bench::summarize(runs);
    std::printf("%s: det worst %.2e median %.2e | flat worst %.2e | ruling worst %.3f median %.3f "
                "| speed worst %.3f median %.3f | fold/start worst %.2f median %.2f | folded over "
                "in %d seeds (at most %d places) | development overlaps itself in %d seeds\n",
                name.c_str(), s.detWorst, s.detMedian, s.flatnessWorst, s.rulingWorst,
                s.rulingMedian, s.speedWorst, s.speedMedian, s.foldOverStartWorst,
                s.foldOverStartMedian, s.foldedOverSeeds, s.foldOverPlacesWorst,
                s.overlappingSeeds);
    return 0;
}

} // namespace

int main(int argc, char** argv) {
    // Before anything else: it may re-execute the program with a better BLAS kernel.
    devsurf::solver::useBestBlasKernel(argv);
    devsurf::bench::BenchmarkOptions options;
    std::string study;
    bool drag = false;
    bool coldPress = false;
    bool inSheet = false;
    bool paper = false;
    bool haveStart = false;
    bool haveIterations = false;
    devsurf::bench::PaperBenchOptions paperOptions;
    devsurf::bench::StudyStart start;
    devsurf::bench::StudyOptions studyOptions;
    bool trace = false;
    devsurf::bench::ApproximationBenchOptions approximation;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        if (arg == "--json") {
            options.json = true;
        } else if (arg == "--model" && i + 1 < argc) {
            options.models.push_back(argv[++i]);
        } else if (arg == "--drag") {
            drag = true;
        } else if (arg == "--cold-press") {
            coldPress = true;
        } else if (arg == "--in-sheet") {
            inSheet = true;
        } else if (arg == "--paper") {
            paper = true;
        } else if (arg == "--paper-size-cap" && i + 1 < argc) {
            paperOptions.sizeCap = std::atoi(argv[++i]);
        } else if (arg == "--no-ceres") {
            options.runCeres = false;
        } else if (arg == "--blas") {
            // The timing, the kernel, the flop bound and the threads only.
            options.runCeres = false;
            options.runBaseline = false;
            options.compareAuxiliary = false;
            options.smallNoise = 0.0;
            options.studySeeds = 0;
        } else if (arg == "--approximation" && i + 1 < argc) {
            approximation.target = argv[++i];
        } else if (arg == "--strips" && i + 1 < argc) {
            approximation.strips = std::atoi(argv[++i]);
        } else if (arg == "--intervals" && i + 1 < argc) {
            approximation.intervals = std::atoi(argv[++i]);
        } else if (arg == "--rho" && i + 1 < argc) {
            approximation.rho = std::atof(argv[++i]);
        } else if (arg == "--study" && i + 1 < argc) {
            study = argv[++i];
        } else if (arg == "--edge-noise" && i + 1 < argc) {
            start = {devsurf::bench::NoiseScale::EdgeLength, std::atof(argv[++i])};
            haveStart = true;
        } else if (arg == "--diameter-noise" && i + 1 < argc) {
            start = {devsurf::bench::NoiseScale::Diameter, std::atof(argv[++i])};
            haveStart = true;
        } else if (arg == "--ceres") {
            studyOptions.ceres = true;
        } else if (arg == "--session") {
            studyOptions.solverKind = bench::StudySolver::Session;
        } else if (arg == "--trace") {
            trace = true;
        } else if (arg == "--seeds" && i + 1 < argc) {
            studyOptions.seeds = std::atoi(argv[++i]);
        } else if (arg == "--iterations" && i + 1 < argc) {
            studyOptions.iterations = std::atoi(argv[++i]);
            haveIterations = true;
        } else if (arg == "--set" && i + 1 < argc) {
            const std::string assignment = argv[++i];
            const auto equals = assignment.find('=');
            if (equals == std::string::npos ||
                !setOption(studyOptions, assignment.substr(0, equals),
                           std::atof(assignment.c_str() + equals + 1))) {
                std::cerr << "devsurf-bench: unknown option '" << assignment << "'.\n";
                return 1;
            }
        } else {
            std::cerr
                << "usage: devsurf-bench [--json] [--model NAME]... [--no-ceres | --blas]\n"
                   "       devsurf-bench --drag [--model NAME]... [--cold-press] [--in-sheet] "
                   "[--json]\n"
                   "       devsurf-bench --approximation TARGET [--strips K] [--intervals N] "
                   "[--iterations N] [--rho R] [--json]\n"
                   "       devsurf-bench --paper [--model ROW]... [--paper-size-cap N] "
                   "[--edge-noise F | "
                   "--diameter-noise F] [--iterations N] [--json]\n"
                   "       devsurf-bench --study MODEL [--edge-noise F | --diameter-noise F]"
                   " [--seeds N] [--iterations N] [--set NAME=VALUE]... [--session | "
                   "--ceres] [--trace]\n";
            return 1;
        }
    }
    if (paper) {
        paperOptions.models = options.models;
        if (haveStart) {
            paperOptions.noiseOfDiameter = start.scale == devsurf::bench::NoiseScale::Diameter;
            paperOptions.noise = start.fraction;
        }
        if (haveIterations) {
            paperOptions.iterations = studyOptions.iterations;
        }
        // The Fig. 17 rows like for like, then the drag benchmark's drag on the first Fig. 12
        // row's surface with its development (skipped on a capped, quick run).
        paperOptions.log = [](const std::string& line) { std::cerr << line << "\n"; };
        devsurf::bench::PaperReport report = devsurf::bench::runPaperBench(paperOptions);
        bool dragged = false;
        for (const auto& row : report.rows) {
            if (row.paper.figure != "12" || paperOptions.sizeCap != 0 || dragged) {
                continue;
            }
            dragged = true;
            auto drag = [&row](devsurf::model::CompositeSurface surface, const char* development) {
                const auto d = devsurf::bench::runSurfaceDrag(row.name, surface, {});
                return devsurf::bench::PaperDrag{true,       d.model, development,     d.variables,
                                                 d.medianMs, d.p95Ms, d.residualAfter, d.error};
            };
            std::cerr << "paper: drag of " << row.name << "\n";
            report.drag = drag(row.surface, "development on its sheet");
            devsurf::model::CompositeSurface free = row.surface;
            free.setSheetDomain({});
            report.dragReferences.push_back(drag(free, "development on a free sheet (fixed)"));
            devsurf::model::CompositeSurface without = row.surface;
            without.setKeepsDevelopment(false);
            report.dragReferences.push_back(drag(without, "without the development"));
        }
        devsurf::bench::printPaperBench(report, options.json, std::cout);
        return 0;
    }
    if (!approximation.target.empty()) {
        if (approximation.strips < 1 || approximation.intervals < 1) {
            std::cerr << "devsurf-bench: --strips and --intervals take a whole number >= 1.\n";
            return 1;
        }
        if (haveIterations) {
            approximation.iterations = studyOptions.iterations;
        }
        approximation.log = [](const std::string& line) { std::cerr << line << "\n"; };
        const auto report = devsurf::bench::runApproximationBench(approximation);
        devsurf::bench::printApproximationBench(report, options.json, std::cout);
        return report.error.empty() ? 0 : 2;
    }
    if (drag) {
        devsurf::bench::DragBenchOptions dragOptions;
        dragOptions.log = [](const std::string& line) { std::cerr << line << "\n"; };
        dragOptions.prepare = !coldPress;
        dragOptions.inSheet = inSheet;
        dragOptions.models = options.models;
        devsurf::bench::printDragBench(devsurf::bench::runDragBench(dragOptions), options.json,
                                       std::cout);
        return 0;
    }
    if (!study.empty()) {
        return runStudy(study, start, studyOptions, trace);
    }
    options.log = [](const std::string& line) { std::cerr << line << "\n"; };
    const int code = devsurf::bench::runBenchmark(options, std::cout);
    if (code != 0) {
        std::cerr << "devsurf-bench: no such model.\n";
    }
    return code;
}
