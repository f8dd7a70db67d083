#include "benchmark.h"
#include "bench_json.h"

#include "bench_models.h"
#include "blas_rates.h"
#include "ceres_peer.h"
#include "quality_study.h"

#include "solver/core/blas_info.h"
#include "solver/core/guided_projection.h"
#include "solver/formulation/perturbation.h"
#include "solver/formulation/surface_formulation.h"
#include "solver/quality/quality_measures.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <sstream>
#include <thread>
#include <vector>

namespace devsurf::bench {

namespace {

using Clock = std::chrono::steady_clock;

struct Timing {
    double assembly = 0.0;
    double factorize = 0.0;
    double solve = 0.0;
    double total = 0.0;
};

// Medians per phase over iterations 2..N (the first carries cold caches).
Timing medianTiming(const solver::Summary& summary) {
    std::vector<double> a, f, s, t;
    for (std::size_t i = 1; i < summary.iterations.size(); ++i) {
        const solver::IterationStats& it = summary.iterations[i];
        a.push_back(it.assemblyMs);
        f.push_back(it.factorizationMs);
        s.push_back(it.solveMs);
        t.push_back(it.assemblyMs + it.factorizationMs + it.solveMs);
    }
    return {median(a), median(f), median(s), median(t)};
}

struct ModelResult {
    std::string name;
    PaperRow paper;
    std::size_t controlPoints = 0;
    int strips = 0;
    int variables = 0;
    int constraints = 0;
    long long jacobianNonZeros = 0;
    double factorNonZeros = 0.0;
    double flops = 0.0;
    Timing ours;
    double oursTotalMs = 0.0;
    double analysisMs = 0.0;
    bool supernodal = false;
    double finalResidual = 0.0;
    double gflops = 0.0;
    double lowerBoundMs = 0.0;
    solver::QualityMeasures quality;
    Timing baseline;
    CeresResult ceres;
    bool auxiliaryMeasured = false;
    int auxiliaryVariables = 0;
    Timing auxiliary;
    double auxiliaryDetMax = 0.0;
    solver::QualityMeasures smallNoiseQuality; // the same 10 iterations from the smaller noise
    struct Study {
        std::string solver; // "paper" (GuidedProjection, its defaults) or "solve" (Tools ▸ Solve)
        std::string start;  // "edge" or "diameter"
        double fraction = 0.0;
        int iterations = 0;
        int seeds = 0;
        StudySummary summary;
        double msPerIteration = 0.0; // median over the seeds
    };
    std::vector<Study> studies;
    std::string status;
    // The iteration on one and on two BLAS threads (medians of three runs each); measured
    // only with a threaded BLAS (`why` says otherwise).
    struct Threads {
        bool measured = false;
        std::string why;
        Timing one;
        Timing two;
        double factorizeSpeedup() const { return one.factorize / two.factorize; }
        double iterationSpeedup() const { return one.total / two.total; }
    } threads;
};

solver::Summary solveFrom(const solver::Problem& problem, std::vector<double>& x,
                          const BenchmarkOptions& options, bool baseline) {
    solver::Options o;
    o.maxIterations = options.iterations;
    o.eps2 = options.eps2;
    // Ours: supernodal or simplicial by the calibrated switch (the default); the baseline takes
    // CHOLMOD's own choice, as a rebuild-everything implementation would.
    if (baseline) {
        o.factorization = solver::FactorizationMethod::Automatic;
    }
    solver::GuidedProjection projection;
    solver::ExperimentalOptions experimental;
    experimental.baseline = baseline;
    projection.setExperimentalOptions(experimental);
    return projection.solve(problem, x, o);
}

ModelResult::Threads measureThreads(const solver::Problem& problem,
                                    const std::vector<double>& start,
                                    const BenchmarkOptions& options) {
    ModelResult::Threads t;
    const solver::BlasInfo blas = solver::detectBlas();
    if (!blas.threaded) {
        t.why = "single-threaded BLAS";
        return t;
    }
    if (std::thread::hardware_concurrency() < 2) {
        t.why = "one CPU";
        return t;
    }
    for (const int threads : {1, 2}) {
        setBlasThreads(threads);
        std::vector<double> assembly, factorize, solve, total;
        for (int run = 0; run < 3; ++run) {
            std::vector<double> x = start;
            const Timing timing = medianTiming(solveFrom(problem, x, options, false));
            assembly.push_back(timing.assembly);
            factorize.push_back(timing.factorize);
            solve.push_back(timing.solve);
            total.push_back(timing.total);
        }
        Timing& measured = threads == 1 ? t.one : t.two;
        measured.assembly = median(assembly);
        measured.factorize = median(factorize);
        measured.solve = median(solve);
        measured.total = median(total);
    }
    setBlasThreads(blas.threads);
    t.measured = t.two.factorize > 0.0 && t.two.total > 0.0;
    return t;
}

ModelResult runModel(const BenchModel& model, const BenchmarkOptions& options, double dgemmGflops) {
    auto log = [&options](const std::string& line) {
        if (options.log) {
            options.log(line);
        }
    };
    ModelResult r;
    r.name = model.name;
    r.paper = model.paper;
    model::CompositeSurface surface = model.surface;
    r.controlPoints = surface.controlPointCount();
    const std::vector<model::VertexId> anchors = solver::spreadBoundaryVertices(surface, 3);
    solver::perturbSurface(surface, options.noise * solver::surfaceDiameter(surface), options.seed,
                           anchors);
    solver::FormulationOptions formulationOptions;
    for (model::VertexId v : anchors) {
        formulationOptions.handles.push_back({v, true, {}});
    }
    const solver::SurfaceFormulation formulation(surface, formulationOptions);
    r.strips = formulation.stripCount() + formulation.coneCount();
    const std::vector<double> start = formulation.initialState();

    // Ours: the best of three runs (the machine is shared), each from the same start.
    solver::Summary best;
    std::vector<double> bestState;
    for (int run = 0; run < 3; ++run) {
        std::vector<double> x = start;
        solver::Summary summary = solveFrom(formulation.problem(), x, options, false);
        if (run == 0 || summary.totalMs < best.totalMs) {
            best = summary;
            bestState = x;
        }
    }
    r.status = solver::toString(best.status);
    r.variables = best.variables;
    r.constraints = best.rows;
    r.jacobianNonZeros = best.jacobianNonZeros;
    if (!best.iterations.empty()) {
        r.flops = best.iterations.back().factorFlops;
        r.factorNonZeros = best.iterations.back().factorNonZeros;
    }
    r.ours = medianTiming(best);
    r.oursTotalMs = best.totalMs;
    r.analysisMs = best.analysisMs;
    r.supernodal = best.supernodal;
    r.finalResidual = best.finalMaxConstraintResidual;
    r.gflops = r.ours.factorize > 0.0 ? r.flops / (r.ours.factorize * 1e6) : 0.0;
    r.lowerBoundMs = dgemmGflops > 0.0 ? r.flops / (dgemmGflops * 1e6) : 0.0;
    model::CompositeSurface result = surface;
    std::string error;
    // measureQuality samples the surface, which needs a valid one: a result with a collapsed
    // ruling is reported by its status instead.
    if (!formulation.writeBack(bestState, result, &error)) {
        r.status = error;
    } else if (const auto problems = result.validate(); !problems.empty()) {
        r.status = "degenerate result: " + model::technicalKey(problems.front());
    } else {
        r.quality = solver::measureQuality(result);
    }
    log(r.name + ": ours " + number(r.ours.total) + " ms/iteration, residual " +
        number(r.finalResidual));

    if (options.measureThreads) {
        r.threads = measureThreads(formulation.problem(), start, options);
        if (r.threads.measured) {
            log(r.name + ": factorisation on 1 → 2 BLAS threads " +
                number(r.threads.one.factorize) + " → " + number(r.threads.two.factorize) + " ms");
        }
    }

    if (options.runBaseline) {
        std::vector<double> x = start;
        const solver::Summary baseline = solveFrom(formulation.problem(), x, options, true);
        r.baseline = medianTiming(baseline);
        log(r.name + ": baseline " + number(r.baseline.total) + " ms/iteration");
    }

    if (options.compareAuxiliary) {
        solver::FormulationOptions auxiliaryOptions = formulationOptions;
        auxiliaryOptions.auxiliaryDerivativePoints = true;
        const solver::SurfaceFormulation auxiliary(surface, auxiliaryOptions);
        std::vector<double> y = auxiliary.initialState();
        const solver::Summary summary = solveFrom(auxiliary.problem(), y, options, false);
        r.auxiliaryMeasured = true;
        r.auxiliaryVariables = summary.variables;
        r.auxiliary = medianTiming(summary);
        model::CompositeSurface auxiliaryResult = surface;
        if (auxiliary.writeBack(y, auxiliaryResult) && auxiliaryResult.validate().empty()) {
            r.auxiliaryDetMax = solver::measureQuality(auxiliaryResult).developabilityMax;
        }
        log(r.name + ": auxiliary variant " + number(r.auxiliary.total) + " ms/iteration");
    }

    if (options.smallNoise > 0.0) {
        // Quality only (no timing): the same model, anchors and seed at the smaller noise.
        model::CompositeSurface quiet = model.surface;
        solver::perturbSurface(quiet, options.smallNoise * solver::surfaceDiameter(quiet),
                               options.seed, anchors);
        const solver::SurfaceFormulation f(quiet, formulationOptions);
        std::vector<double> y = f.initialState();
        if (solveFrom(f.problem(), y, options, false).succeeded() && f.writeBack(y, quiet) &&
            quiet.validate().empty()) {
            r.smallNoiseQuality = solver::measureQuality(quiet);
        }
        log(r.name + ": from " + number(options.smallNoise) + " noise, det max " +
            number(r.smallNoiseQuality.developabilityMax));
    }

    if (options.studySeeds > 0) {
        // The ~40,000-variable model gets 20 iterations (the target for it).
        const int iterations = r.variables > 20000 ? 2 * options.iterations : options.iterations;
        const StudyStart starts[] = {{NoiseScale::EdgeLength, 0.1}, {NoiseScale::Diameter, 0.01}};
        // The paper's configuration (GuidedProjection with its defaults), then what Tools ▸
        // Solve runs on the same starts (a SolveSession, the fixed vertices pinned).
        for (const StudySolver kind : {StudySolver::Options, StudySolver::Session}) {
            for (const StudyStart& start : starts) {
                StudyOptions studyOptions;
                studyOptions.solverKind = kind;
                studyOptions.iterations = iterations;
                studyOptions.seeds = options.studySeeds;
                studyOptions.firstSeed = options.seed;
                studyOptions.solver.eps2 = options.eps2;
                const std::vector<StudyRun> runs = runStudy(model.surface, start, studyOptions);
                ModelResult::Study study;
                study.solver = kind == StudySolver::Session ? "solve" : "paper";
                study.start = start.scale == NoiseScale::EdgeLength ? "edge" : "diameter";
                study.fraction = start.fraction;
                study.iterations = iterations;
                study.seeds = options.studySeeds;
                study.summary = summarize(runs);
                std::vector<double> times;
                for (const StudyRun& run : runs) {
                    times.push_back(run.msPerIteration);
                }
                study.msPerIteration = median(times);
                r.studies.push_back(study);
                log(r.name + " (" +
                    (kind == StudySolver::Session ? "Tools ▸ Solve" : "paper's configuration") +
                    "): from σ = " + number(start.fraction) + " of the " +
                    (study.start == "edge" ? "mean edge length" : "diameter") + ", det worst " +
                    number(study.summary.detWorst) + " median " + number(study.summary.detMedian));
            }
        }
    }

    if (options.runCeres) {
        r.ceres = runCeres(formulation.problem(), start, r.finalResidual, options.ceresCapSeconds);
        log(r.name + ": Ceres " + number(r.ceres.milliseconds) + " ms" +
            (r.ceres.reached ? "" : " (did not reach the residual: " + r.ceres.message + ")"));
    }
    return r;
}

double ratio(double a, double b) {
    return b > 0.0 ? a / b : 0.0;
}

// Per model: the factorisation and the iteration on 1 and 2 BLAS threads, the parallel
// fraction that the speed-up implies and Amdahl's prediction for 8 threads.
std::string threadsJson(const ModelResult::Threads& t) {
    if (!t.measured) {
        return "{ \"measured\": false, \"why\": " + quoted(t.why) + " }";
    }
    const double pf = parallelFractionFromTwo(t.factorizeSpeedup());
    const double pi = parallelFractionFromTwo(t.iterationSpeedup());
    return "{ \"measured\": true, \"factorize_ms_1\": " + number(t.one.factorize) +
           ", \"factorize_ms_2\": " + number(t.two.factorize) +
           ", \"factorize_speedup_2\": " + number(t.factorizeSpeedup()) +
           ", \"factorize_parallel_fraction\": " + number(pf) +
           ", \"factorize_predicted_speedup_8\": " + number(amdahl(pf, 8)) +
           ", \"iteration_ms_1\": " + number(t.one.total) +
           ", \"iteration_ms_2\": " + number(t.two.total) +
           ", \"iteration_speedup_2\": " + number(t.iterationSpeedup()) +
           ", \"iteration_parallel_fraction\": " + number(pi) +
           ", \"iteration_predicted_speedup_8\": " + number(amdahl(pi, 8)) + " }";
}

void writeJson(const std::vector<ModelResult>& results, const solver::BlasInfo& blas, double dgemm,
               double dgemmTwo, const BenchmarkOptions& options, std::ostream& out) {
    out << "{\n  \"blas\": " << quoted(blas.describe())
        << ",\n  \"blas_kernel\": " << quoted(blas.kernel)
        << ",\n  \"blas_kernel_chosen_by\": " << quoted(blas.kernelChosenBy)
        << ",\n  \"blas_kernel_requested\": " << quoted(blas.kernelRequested)
        << ",\n  \"blas_threaded\": " << (blas.threaded ? "true" : "false")
        << ",\n  \"dgemm_gflops\": " << number(dgemm) << ",\n  \"dgemm_size\": " << kDgemmSize
        << ",\n  \"dgemm_gflops_2_threads\": " << (dgemmTwo > 0.0 ? number(dgemmTwo) : "null")
        << ",\n  \"iterations\": " << options.iterations
        << ",\n  \"noise_fraction_of_diameter\": " << number(options.noise)
        << ",\n  \"small_noise_fraction_of_diameter\": " << number(options.smallNoise)
        << ",\n  \"seed\": " << options.seed << ",\n  \"eps2\": " << number(options.eps2)
        << ",\n  \"ceres_available\": " << (ceresAvailable() ? "true" : "false")
        << ",\n  \"models\": [";
    for (std::size_t i = 0; i < results.size(); ++i) {
        const ModelResult& r = results[i];
        const double paperMs = 1000.0 * r.paper.secondsPerIteration;
        out << (i == 0 ? "\n" : ",\n") << "    {\n"
            << "      \"model\": " << quoted(r.name) << ",\n"
            << "      \"status\": " << quoted(r.status) << ",\n"
            << "      \"control_points\": " << r.controlPoints << ",\n"
            << "      \"strips\": " << r.strips << ",\n"
            << "      \"variables\": " << r.variables << ",\n"
            << "      \"constraints\": " << r.constraints << ",\n"
            << "      \"jacobian_nnz\": " << r.jacobianNonZeros << ",\n"
            << "      \"factor_nnz\": " << number(r.factorNonZeros) << ",\n"
            << "      \"flops\": " << number(r.flops) << ",\n"
            << "      \"ms_per_iter\": { \"assembly\": " << number(r.ours.assembly)
            << ", \"factorize\": " << number(r.ours.factorize)
            << ", \"solve\": " << number(r.ours.solve) << ", \"total\": " << number(r.ours.total)
            << " },\n"
            << "      \"factorization\": " << quoted(r.supernodal ? "supernodal" : "simplicial")
            << ",\n"
            << "      \"analysis_ms\": " << number(r.analysisMs) << ",\n"
            << "      \"factorize_gflops\": " << number(r.gflops) << ",\n"
            << "      \"lower_bound_ms\": " << number(r.lowerBoundMs) << ",\n"
            << "      \"factorize_over_lower_bound\": "
            << number(ratio(r.ours.factorize, r.lowerBoundMs)) << ",\n"
            << "      \"assembly_share\": " << number(ratio(r.ours.assembly, r.ours.total)) << ",\n"
            << "      \"threads\": " << threadsJson(r.threads) << ",\n"
            << "      \"paper_figure\": " << quoted(r.paper.figure) << ",\n"
            << "      \"paper_control_points\": " << r.paper.controlPoints << ",\n"
            << "      \"paper_strips\": " << r.paper.strips << ",\n"
            << "      \"paper_variables\": " << r.paper.variables << ",\n"
            << "      \"paper_s_per_iter\": " << number(r.paper.secondsPerIteration) << ",\n"
            << "      \"paper_over_ours\": " << number(ratio(paperMs, r.ours.total)) << ",\n"
            << "      \"baseline_ms_per_iter\": " << number(r.baseline.total) << ",\n"
            << "      \"baseline_over_ours\": " << number(ratio(r.baseline.total, r.ours.total))
            << ",\n"
            << "      \"final_max_constraint_residual\": " << number(r.finalResidual) << ",\n"
            << "      \"ours_ms_to_residual\": " << number(r.oursTotalMs) << ",\n"
            << "      \"ceres_ms_to_residual\": "
            << (r.ceres.available ? number(r.ceres.milliseconds) : "null") << ",\n"
            << "      \"ceres_reached_residual\": " << (r.ceres.reached ? "true" : "false") << ",\n"
            << "      \"ceres_hit_time_cap\": " << (r.ceres.hitTimeCap ? "true" : "false") << ",\n"
            << "      \"ceres_iterations\": " << r.ceres.iterations << ",\n"
            << "      \"ceres_final_residual\": " << number(r.ceres.finalResidual) << ",\n"
            << "      \"ceres_over_ours\": " << number(ratio(r.ceres.milliseconds, r.oursTotalMs))
            << ",\n"
            << "      \"ours_over_ceres\": " << number(ratio(r.oursTotalMs, r.ceres.milliseconds))
            << ",\n"
            << "      \"ours_over_baseline\": " << number(ratio(r.ours.total, r.baseline.total))
            << ",\n";
        if (r.auxiliaryMeasured) {
            out << "      \"auxiliary_variables\": " << r.auxiliaryVariables << ",\n"
                << "      \"auxiliary_ms_per_iter\": " << number(r.auxiliary.total) << ",\n"
                << "      \"auxiliary_det_residual_max\": " << number(r.auxiliaryDetMax) << ",\n";
        }
        out << "      \"det_residual_max\": " << number(r.quality.developabilityMax) << ",\n"
            << "      \"det_residual_mean\": " << number(r.quality.developabilityMean) << ",\n"
            << "      \"flatness_mean\": " << number(r.quality.flatnessMean) << ",\n"
            << "      \"flatness_max\": " << number(r.quality.flatnessMax) << ",\n"
            << "      \"paper_flatness_mean\": " << number(r.paper.flatnessMean) << ",\n"
            << "      \"paper_flatness_max\": " << number(r.paper.flatnessMax) << ",\n"
            << "      \"gauss_curvature_mean\": " << number(r.quality.curvatureMean) << ",\n"
            << "      \"gauss_curvature_max\": " << number(r.quality.curvatureMax) << ",\n"
            << "      \"small_noise_det_residual_max\": "
            << number(r.smallNoiseQuality.developabilityMax) << ",\n"
            << "      \"small_noise_flatness_mean\": " << number(r.smallNoiseQuality.flatnessMean);
        if (!r.studies.empty()) {
            out << ",\n      \"quality_over_seeds\": [";
            for (std::size_t k = 0; k < r.studies.size(); ++k) {
                const ModelResult::Study& q = r.studies[k];
                const StudySummary& m = q.summary;
                constexpr double kDegrees = 57.29577951308232;
                out << (k == 0 ? "\n" : ",\n") << "        { \"solver\": " << quoted(q.solver)
                    << ", \"start\": " << quoted(q.start)
                    << ", \"sigma_fraction\": " << number(q.fraction)
                    << ", \"iterations\": " << q.iterations << ", \"seeds\": " << q.seeds
                    << ", \"det_residual_max_worst\": " << number(m.detWorst)
                    << ", \"det_residual_max_median\": " << number(m.detMedian)
                    << ", \"flatness_mean_worst\": " << number(m.flatnessWorst)
                    << ", \"flatness_mean_median\": " << number(m.flatnessMedian)
                    << ", \"shortest_ruling_over_start_worst\": " << number(m.rulingWorst)
                    << ", \"shortest_ruling_over_start_median\": " << number(m.rulingMedian)
                    << ", \"slowest_speed_over_start_mean_worst\": " << number(m.speedWorst)
                    << ", \"slowest_speed_over_start_mean_median\": " << number(m.speedMedian)
                    << ", \"crease_fold_deg_median\": " << number(m.foldMedian * kDegrees)
                    << ", \"start_normal_angle_deg_median\": "
                    << number(m.startAngleMedian * kDegrees)
                    << ", \"fold_over_start_angle_worst\": " << number(m.foldOverStartWorst)
                    << ", \"fold_over_start_angle_median\": " << number(m.foldOverStartMedian)
                    << ", \"seeds_folded_over_onto_themselves\": " << m.foldedOverSeeds
                    << ", \"fold_over_places_worst\": " << m.foldOverPlacesWorst
                    << ", \"seeds_whose_development_overlaps_itself\": " << m.overlappingSeeds
                    << ", \"ms_per_iter_median\": " << number(q.msPerIteration) << " }";
            }
            out << "\n      ]";
        }
        out << "\n"
            << "    }";
    }
    out << "\n  ]\n}\n";
}

void writeTable(const std::vector<ModelResult>& results, const solver::BlasInfo& blas, double dgemm,
                double dgemmTwo, std::ostream& out) {
    out << "BLAS: " << blas.describe() << "\n";
    if (!blas.kernel.empty()) {
        out << "BLAS kernel: " << blas.kernel << ", chosen by " << blas.kernelChosenBy;
        if (blas.kernelChosenBy == "OPENBLAS_CORETYPE") {
            out << "=" << blas.kernelRequested;
        } else if (!blas.kernelRequested.empty()) {
            out << " (OPENBLAS_CORETYPE=" << blas.kernelRequested << ")";
        }
        out << "\n";
    }
    out << "DGEMM " << kDgemmSize << "×" << kDgemmSize
        << ", one thread, best of 3: " << number(dgemm) << " GFLOP/s";
    if (dgemmTwo > 0.0) {
        out << "; two threads " << number(dgemmTwo) << " GFLOP/s";
    }
    out << "\n";
    char line[512];
    std::snprintf(line, sizeof line, "%-18s %7s %7s %9s %9s %9s %9s %9s %9s %9s %9s\n", "model",
                  "vars", "rows", "ours ms", "fact ms", "bound ms", "paper ms", "base ms",
                  "ours→res", "ceres ms", "det max");
    out << line;
    for (const ModelResult& r : results) {
        std::snprintf(line, sizeof line,
                      "%-18s %7d %7d %9.3f %9.3f %9.3f %9.0f %9.3f %9.1f %9.1f %9.2e\n",
                      r.name.c_str(), r.variables, r.constraints, r.ours.total, r.ours.factorize,
                      r.lowerBoundMs, 1000.0 * r.paper.secondsPerIteration, r.baseline.total,
                      r.oursTotalMs, r.ceres.milliseconds, r.quality.developabilityMax);
        out << line;
    }
    if (!ceresAvailable()) {
        out << runCeres(solver::Problem(), {}, 0.0, 0.0).message << "\n";
    }
    // The factorisation against its flop bound at the DGEMM rate, and on two BLAS threads.
    out << "\nFactorisation (medians per iteration; bound = CHOLMOD's flops at the DGEMM rate)\n";
    std::snprintf(line, sizeof line, "%-18s %11s %9s %8s %9s %10s %9s %7s %7s %7s\n", "model",
                  "method", "Mflop", "fact ms", "GFLOP/s", "fact/bound", "assembly", "1→2 thr",
                  "par", "8 thr");
    out << line;
    for (const ModelResult& r : results) {
        char threads[64] = "      -       -       -";
        if (r.threads.measured) {
            const double p = parallelFractionFromTwo(r.threads.factorizeSpeedup());
            std::snprintf(threads, sizeof threads, "%7.2f %7.2f %7.2f",
                          r.threads.factorizeSpeedup(), p, amdahl(p, 8));
        }
        std::snprintf(line, sizeof line, "%-18s %11s %9.1f %8.3f %9.2f %10.2f %8.0f%% %s\n",
                      r.name.c_str(), r.supernodal ? "supernodal" : "simplicial", r.flops * 1e-6,
                      r.ours.factorize, r.gflops, ratio(r.ours.factorize, r.lowerBoundMs),
                      100.0 * ratio(r.ours.assembly, r.ours.total), threads);
        out << line;
    }
    if (!results.empty() && !results.front().threads.measured) {
        out << "Threads not measured (" << results.front().threads.why
            << "): run with a threaded OpenBLAS, e.g. "
               "LD_LIBRARY_PATH=/usr/lib/x86_64-linux-gnu/openblas-pthread\n";
    }
}

} // namespace

bool ceresAvailable() {
#ifdef DEVSURF_HAVE_CERES
    return true;
#else
    return false;
#endif
}

int runBenchmark(const BenchmarkOptions& options, std::ostream& out) {
    const std::vector<BenchModel> models = benchModels(options.models);
    if (models.empty()) {
        return 1;
    }
    BenchmarkOptions effective = options;
    if (!ceresAvailable()) {
        effective.runCeres = false;
        if (options.log) {
            options.log(runCeres(solver::Problem(), {}, 0.0, 0.0).message);
        }
    }
    const solver::BlasInfo blas = solver::detectBlas();
    setBlasThreads(1);
    const double dgemm = measureDgemmGflops();
    // With a threaded BLAS, DGEMM on two threads too: how much of a second core the machine
    // gave during the run (the ceiling for the factorisation's speed-up on two threads).
    double dgemmTwo = 0.0;
    if (blas.threaded && setBlasThreads(2)) {
        dgemmTwo = measureDgemmGflops();
    }
    setBlasThreads(blas.threads);
    std::vector<ModelResult> results;
    for (const BenchModel& model : models) {
        results.push_back(runModel(model, effective, dgemm));
    }
    if (options.json) {
        writeJson(results, blas, dgemm, dgemmTwo, effective, out);
    } else {
        writeTable(results, blas, dgemm, dgemmTwo, out);
    }
    return 0;
}

} // namespace devsurf::bench
