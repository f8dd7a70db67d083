#include "drag_bench.h"

#include "bench_models.h"
#include "model/document/commands/apply_surface_command.h"
#include "model/document/commands/command_or_error.h"
#include "model/document/document.h"
#include "model/examples.h"
#include "solver/core/blas_info.h"
#include "solver/formulation/perturbation.h"
#include "solver/quality/shape_change.h"
#include "solver/worker/solver_worker.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QTimer>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>

namespace devsurf::bench {

namespace {

// Pushes the edit; empty when pushed, otherwise why it was refused (technical).
QString pushEdit(devsurf::document::Document& document, devsurf::document::CommandOrError edit) {
    if (devsurf::document::push(document, edit)) {
        return QString();
    }
    return edit.error() +
           (edit.problem()
                ? QStringLiteral(": ") +
                      QString::fromStdString(devsurf::model::technicalKey(*edit.problem()))
                : QString());
}

// Watches the event loop of the calling thread: the largest gap between ticks of a 1 ms timer.
// A run ends through quitOnNextTick(), so the handler of the last result is always inside a
// measured gap (a plain quit() leaves it out or in, depending on the order of pending events).
class StallWatch {
public:
    StallWatch() {
        m_timer.setTimerType(Qt::PreciseTimer);
        m_timer.setInterval(1);
        QObject::connect(&m_timer, &QTimer::timeout, [this] {
            const double now = m_clock.nsecsElapsed() / 1e6;
            m_largest = std::max(m_largest, now - m_last);
            m_last = now;
            if (m_quit != nullptr) {
                m_quit->quit();
                m_quit = nullptr;
            }
        });
        m_clock.start();
        m_timer.start();
    }
    double largestGapMs() const { return m_largest; }
    void quitOnNextTick(QEventLoop& loop) { m_quit = &loop; }

private:
    QTimer m_timer;
    QElapsedTimer m_clock;
    double m_last = 0.0;
    double m_largest = 0.0;
    QEventLoop* m_quit = nullptr;
};

double percentile(std::vector<double> values, double p) {
    if (values.empty()) {
        return 0.0;
    }
    std::sort(values.begin(), values.end());
    const auto index = static_cast<std::size_t>(std::ceil(p * static_cast<double>(values.size())));
    return values[std::min(values.size() - 1, index == 0 ? 0 : index - 1)];
}

// The vertex dragged: the one nearest the centre of the bounding box that is not pinned.
model::VertexId draggedVertex(const model::CompositeSurface& surface) {
    model::Vec3 low{std::numeric_limits<double>::max(), std::numeric_limits<double>::max(),
                    std::numeric_limits<double>::max()};
    model::Vec3 high = -low;
    for (const auto& [id, p] : surface.vertices()) {
        low = {std::min(low.x, p.x), std::min(low.y, p.y), std::min(low.z, p.z)};
        high = {std::max(high.x, p.x), std::max(high.y, p.y), std::max(high.z, p.z)};
    }
    const model::Vec3 centre = (low + high) * 0.5;
    model::VertexId best = model::kInvalidId;
    double bestDistance = std::numeric_limits<double>::max();
    for (const auto& [id, p] : surface.vertices()) {
        if (!surface.isPinned(id) && model::distance(p, centre) < bestDistance) {
            bestDistance = model::distance(p, centre);
            best = id;
        }
    }
    return best;
}

DragBenchRow runDrag(const std::string& name, model::CompositeSurface surface,
                     const DragBenchOptions& options) {
    DragBenchRow row;
    row.model = name;
    row.moves = options.moves;
    for (model::VertexId id : solver::spreadBoundaryVertices(surface, 6)) {
        surface.setPinned(id, true);
    }
    const model::VertexId dragged = draggedVertex(surface);
    const model::Vec3 from = surface.position(dragged);
    const model::Vec3 lift{0.0, 0.0, options.liftFraction * solver::surfaceDiameter(surface)};
    std::optional<model::Vec2> place; // --in-sheet: the dragged vertex's place, and its slide
    model::Vec2 slide;
    if (options.inSheet && surface.keepsDevelopment() && !surface.development().empty()) {
        const std::vector<model::Vec2>& sheet = surface.development();
        // The development lists the coarse vertices first, in id order.
        std::size_t index = 0;
        for (const auto& [id, p] : surface.vertices()) {
            (void)p;
            if (id == dragged) {
                break;
            }
            ++index;
        }
        model::Vec2 centroid;
        for (const model::Vec2& p : sheet) {
            centroid = centroid + p * (1.0 / static_cast<double>(sheet.size()));
        }
        if (index < sheet.size()) {
            row.model += " (sheet)";
            place = sheet[index];
            const model::Vec2 out = *place - centroid;
            const double length = out.norm() > 0.0 ? out.norm() : 1.0;
            slide = model::Vec2(-out.y, out.x) * (lift.z / length);
        }
    }
    document::Document document;
    model::Project project;
    project.surfaces = {surface};
    document.resetProject(project);
    const model::CompositeSurface press = document.surface(0);
    const solver::SharedSurfaces pressSurfaces{press};

    solver::SolverWorker worker;
    QEventLoop loop;
    QElapsedTimer clock;
    StallWatch stalls;
    std::vector<double> movedAt(static_cast<std::size_t>(options.moves) + 1, 0.0);
    std::vector<double> latency;
    int covered = 0; // moves 1..covered have had a result applied
    double releasedAt = 0.0;
    const quint64 release = static_cast<quint64>(options.moves) + 1;
    constexpr quint64 kDragKey = 1;

    const bool keepLengths = options.keepLengths.value_or(true);
    const int after = options.afterIterations > 0 ? options.afterIterations
                                                  : solver::iterationsAfterDrag(keepLengths);
    auto request = [&](quint64 tag, double t, int iterations, bool settle, bool prepare = false) {
        solver::SolveRequest r;
        // The bench tags each request with its move number (the application sends the
        // document's revision at the press and tracks the revisions it produced itself).
        r.revision = tag;
        r.ticket = kDragKey;
        r.job.kind = solver::JobKind::VertexDrag;
        r.job.drag = kDragKey;
        r.job.iterations = iterations;
        r.job.lengths = !options.keepLengths.has_value() ? solver::DragLengths::Automatic
                        : keepLengths                    ? solver::DragLengths::Keep
                                                         : solver::DragLengths::Stretch;
        r.job.settle = settle;
        r.job.prepare = prepare;
        r.job.surfaces = pressSurfaces; // shared, as the Drag tool sends it
        if (place) {
            r.job.pulledSheet[0] = {{dragged, *place + slide * t}};
        } else {
            r.job.pulled[0] = {{dragged, false, from + lift * t}};
        }
        worker.submit(std::move(r));
    };
    QObject::connect(
        &worker, &solver::SolverWorker::finished, &loop, [&](const solver::SolveResult& result) {
            const solver::JobOutcome& outcome = result.outcome;
            if (!outcome.ok) {
                row.error = "the solve job failed: " + outcome.failure.detail;
                loop.quit();
                return;
            }
            if (outcome.prepared) {
                row.prepareMs = clock.nsecsElapsed() / 1e6;
                loop.quit();
                return;
            }
            // As the application's Drag tool: a move is shown outside the undo history, the
            // release becomes one undo step from the press.
            document.previewSurface(0, outcome.surfaces.front());
            if (result.revision == release) {
                const QString refused =
                    pushEdit(document, document::ApplySurfaceCommand::createShown(
                                           document, 0, press, QStringLiteral("Drag vertex")));
                if (!refused.isEmpty()) {
                    row.error = refused.toStdString();
                    loop.quit();
                    return;
                }
            }
            const double now = clock.nsecsElapsed() / 1e6;
            const solver::SurfaceAssessment& assessment = outcome.assessments.front();
            if (result.revision == release) {
                row.releaseMs = now - releasedAt;
                // A release taken back: what the drag reached, which the design did not keep.
                const solver::SurfaceAssessment& reached =
                    assessment.takenBack ? *assessment.takenBack : assessment;
                row.takenBack = assessment.takenBack != nullptr;
                row.followed = assessment.takenBack ? assessment.followed : 1.0;
                row.heldBackMm = assessment.largestHandleGap;
                row.keptResidual = assessment.summary.finalMaxConstraintResidual;
                row.keptOverlappingPatches = static_cast<int>(assessment.overlapping.size());
                row.residualAfter = reached.summary.finalMaxConstraintResidual;
                for (const auto& [face, places] : reached.foldOvers) {
                    (void)face;
                    row.foldOvers += places;
                }
                row.replayedStretching = reached.replay && reached.replay->taken;
                row.overlappingPatches = static_cast<int>(reached.overlapping.size());
                stalls.quitOnNextTick(loop);
                return;
            }
            ++row.applied;
            row.variables = assessment.summary.variables;
            for (int m = covered + 1; m <= static_cast<int>(result.revision); ++m) {
                latency.push_back(now - movedAt[static_cast<std::size_t>(m)]);
            }
            covered = std::max(covered, static_cast<int>(result.revision));
            if (covered == options.moves) {
                releasedAt = now;
                request(release, 1.0, after, true);
            }
        });
    QTimer mouse;
    mouse.setTimerType(Qt::PreciseTimer);
    mouse.setInterval(static_cast<int>(std::lround(options.moveIntervalMs)));
    int moved = 0;
    QObject::connect(&mouse, &QTimer::timeout, [&] {
        ++moved;
        movedAt[static_cast<std::size_t>(moved)] = clock.nsecsElapsed() / 1e6;
        request(static_cast<quint64>(moved), static_cast<double>(moved) / options.moves, 1, false);
        if (moved == options.moves) {
            mouse.stop();
        }
    });
    if (options.prepare) {
        // The pointer rests on the vertex: the drag is prepared before the press.
        clock.start();
        request(0, 0.0, 0, false, true);
        loop.exec();
        if (!row.error.empty()) {
            return row;
        }
    }
    clock.start();
    mouse.start();
    loop.exec();
    mouse.stop();
    worker.cancel();
    row.largestStallMs = stalls.largestGapMs();
    row.solved = static_cast<int>(worker.solvedCount()) - (options.prepare ? 1 : 0);
    if (!latency.empty()) {
        row.firstResultMs = latency.front();
        row.medianMs = percentile(latency, 0.5);
        row.p95Ms = percentile(latency, 0.95);
        const double span = releasedAt - movedAt[1];
        row.appliedPerSecond = span > 0.0 ? 1000.0 * row.applied / span : 0.0;
    }
    return row;
}

SolveStallRow runSolve(const std::string& name, model::CompositeSurface surface,
                       const DragBenchOptions& options) {
    SolveStallRow row;
    row.model = name;
    row.iterations = options.solveIterations;
    solver::perturbSurface(surface, 1e-3 * solver::surfaceDiameter(surface), 20150801u);
    document::Document document;
    model::Project project;
    project.surfaces = {surface};
    document.resetProject(project);
    solver::SolverWorker worker;
    QEventLoop loop;
    QElapsedTimer clock;
    StallWatch stalls;
    QObject::connect(
        &worker, &solver::SolverWorker::finished, &loop, [&](const solver::SolveResult& result) {
            const solver::JobOutcome& outcome = result.outcome;
            if (!outcome.ok) {
                row.error = "the solve job failed: " + outcome.failure.detail;
            } else {
                row.variables = outcome.assessments.front().summary.variables;
                const QString refused = pushEdit(
                    document, document::ApplySurfaceCommand::createValidated(
                                  document, 0, outcome.surfaces.front(), QStringLiteral("Solve")));
                row.error = refused.toStdString();
            }
            row.solveMs = clock.nsecsElapsed() / 1e6;
            stalls.quitOnNextTick(loop);
        });
    solver::SolveRequest request;
    request.revision = document.revision();
    request.job.iterations = options.solveIterations;
    request.job.surfaces = {document.surface(0)};
    clock.start();
    worker.submit(std::move(request));
    loop.exec();
    row.largestStallMs = stalls.largestGapMs();
    return row;
}

} // namespace

namespace {

// A QCoreApplication for the drags' event loops if the process has none yet.
std::unique_ptr<QCoreApplication> ensureApplication() {
    if (QCoreApplication::instance()) {
        return nullptr;
    }
    static int argc = 1;
    static char name[] = "devsurf-bench";
    static char* argv[] = {name, nullptr};
    return std::make_unique<QCoreApplication>(argc, argv);
}

} // namespace

DragBenchRow runSurfaceDrag(const std::string& name, const model::CompositeSurface& surface,
                            const DragBenchOptions& options) {
    const std::unique_ptr<QCoreApplication> application = ensureApplication();
    return runDrag(name, surface, options);
}

DragBenchReport runDragBench(const DragBenchOptions& options) {
    const std::unique_ptr<QCoreApplication> application = ensureApplication();
    auto log = [&options](const std::string& line) {
        if (options.log) {
            options.log(line);
        }
    };
    DragBenchReport report;
    // The annuli as they come, and as File ▸ New from Example makes them: holding their sheet.
    const auto held = model::ExampleSheet::Held;
    const std::vector<std::pair<std::string, model::CompositeSurface>> drags = {
        {"fig12-annulus", model::makeExample("annulus", 6).surfaces.front()},
        {"annulus-14", model::makeExample("annulus", 14).surfaces.front()},
        {"fig12-annulus-held", model::makeExample("annulus", 6, held).surfaces.front()},
        {"annulus-14-held", model::makeExample("annulus", 14, held).surfaces.front()},
    };
    auto wanted = [&options](const std::string& name) {
        return options.models.empty() || std::find(options.models.begin(), options.models.end(),
                                                   name) != options.models.end();
    };
    for (const auto& [name, surface] : drags) {
        if (!wanted(name)) {
            continue;
        }
        log("drag: " + name);
        report.drags.push_back(runDrag(name, surface, options));
    }
    const std::vector<BenchModel> largest =
        wanted("large-annulus") ? benchModels({"large-annulus"}) : std::vector<BenchModel>{};
    if (!largest.empty()) {
        log("drag: " + largest.front().name);
        report.drags.push_back(runDrag(largest.front().name, largest.front().surface, options));
        log("drag: solve stall on " + largest.front().name);
        report.solve = runSolve(largest.front().name, largest.front().surface, options);
    }
    return report;
}

void printDragBench(const DragBenchReport& report, bool json, std::ostream& out) {
    char line[512];
    // The BLAS kernel the drags' factorisations ran (names without quotes or escapes).
    const solver::BlasInfo blas = solver::detectBlas();
    if (json) {
        out << "{\"drag\": {\"blas_kernel\": \"" << blas.kernel
            << "\", \"blas_kernel_chosen_by\": \"" << blas.kernelChosenBy << "\", \"drags\": [";
        for (std::size_t i = 0; i < report.drags.size(); ++i) {
            const DragBenchRow& r = report.drags[i];
            std::snprintf(
                line, sizeof line,
                "%s{\"model\": \"%s\", \"variables\": %d, \"moves\": %d, \"solved\": %d, "
                "\"applied\": %d, \"prepare_ms\": %.3f, \"first_result_ms\": %.3f, "
                "\"median_ms\": %.3f, "
                "\"p95_ms\": %.3f, \"applied_per_second\": %.2f, "
                "\"largest_stall_ms\": %.3f, \"release_ms\": %.3f, "
                "\"residual_after\": %.3e, \"fold_overs\": %d, "
                "\"development_overlap_patches\": %d, \"replayed_stretching\": %s, "
                "\"taken_back\": %s, \"followed\": %.3f, \"held_back_mm\": %.3f, "
                "\"kept_residual\": %.3e, \"kept_overlap_patches\": %d, \"error\": \"%s\"}",
                i == 0 ? "" : ", ", r.model.c_str(), r.variables, r.moves, r.solved, r.applied,
                r.prepareMs, r.firstResultMs, r.medianMs, r.p95Ms, r.appliedPerSecond,
                r.largestStallMs, r.releaseMs, r.residualAfter, r.foldOvers, r.overlappingPatches,
                r.replayedStretching ? "true" : "false", r.takenBack ? "true" : "false", r.followed,
                r.heldBackMm, r.keptResidual, r.keptOverlappingPatches, r.error.c_str());
            out << line;
        }
        const SolveStallRow& s = report.solve;
        std::snprintf(line, sizeof line,
                      "], \"solve\": {\"model\": \"%s\", \"variables\": %d, \"iterations\": %d, "
                      "\"solve_ms\": %.3f, \"largest_stall_ms\": %.3f, \"error\": \"%s\"}}}\n",
                      s.model.c_str(), s.variables, s.iterations, s.solveMs, s.largestStallMs,
                      s.error.c_str());
        out << line;
        return;
    }
    if (!blas.kernel.empty()) {
        out << "BLAS kernel: " << blas.kernel << ", chosen by " << blas.kernelChosenBy << "\n";
    }
    out << "Drag through the worker (move to result applied; targets: median <= 16 ms, stall "
           "<= 20 ms)\n";
    std::snprintf(line, sizeof line,
                  "%-18s %9s %6s %6s %7s %10s %9s %9s %9s %9s %9s %10s %9s %6s %8s\n", "model",
                  "variables", "moves", "solved", "applied", "prepare ms", "first ms", "median ms",
                  "p95 ms", "applied/s", "stall ms", "release ms", "residual", "folds", "overlaps");
    out << line;
    for (const DragBenchRow& r : report.drags) {
        char taken[160] = "";
        if (r.takenBack && r.followed > 0.0) {
            std::snprintf(taken, sizeof taken,
                          "  followed %.0f %% (held back %.1f mm, residual %.1e, overlaps %d)",
                          100.0 * r.followed, r.heldBackMm, r.keptResidual,
                          r.keptOverlappingPatches);
        } else if (r.takenBack) {
            std::snprintf(taken, sizeof taken, "  taken back to the press");
        }
        char prepared[32] = "-";
        if (r.prepareMs >= 0.0) {
            std::snprintf(prepared, sizeof prepared, "%.1f", r.prepareMs);
        }
        std::snprintf(line, sizeof line,
                      "%-18s %9d %6d %6d %7d %10s %9.1f %9.1f %9.1f %9.1f %9.1f %10.1f %9.2e %6d "
                      "%8d%s%s%s%s\n",
                      r.model.c_str(), r.variables, r.moves, r.solved, r.applied, prepared,
                      r.firstResultMs, r.medianMs, r.p95Ms, r.appliedPerSecond, r.largestStallMs,
                      r.releaseMs, r.residualAfter, r.foldOvers, r.overlappingPatches,
                      r.replayedStretching ? "  replayed stretching" : "", taken,
                      r.error.empty() ? "" : "  failed: ", r.error.c_str());
        out << line;
    }
    const SolveStallRow& s = report.solve;
    if (s.model.empty()) {
        return; // not asked for (DragBenchOptions::models)
    }
    std::snprintf(line, sizeof line,
                  "Solve of %s (%d variables, %d iterations): %.1f ms, largest stall %.1f ms%s%s\n",
                  s.model.c_str(), s.variables, s.iterations, s.solveMs, s.largestStallMs,
                  s.error.empty() ? "" : "; failed: ", s.error.c_str());
    out << line;
}

} // namespace devsurf::bench
