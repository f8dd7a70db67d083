#include "solver/session/solve_job.h"
#include "solver/session/join_job.h"

#include "solver/session/approximation_recipe.h"
#include "solver/session/drag_partway.h"
#include "solver/session/job_assessment.h"
#include "solver/session/job_options.h"

#include "model/geometry_checks.h"
#include "model/model_error.h"
#include "solver/quality/quality_measures.h"
#include "solver/session/drag_lengths.h"
#include "solver/session/solve_session.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <exception>
#include <limits>
#include <memory>
#include <optional>
#include <set>
#include <stdexcept>

namespace devsurf::solver {

namespace {

bool allFinite(const model::CompositeSurface& surface) {
    return model::allCoordinatesFinite(surface);
}

// Same combinatorics, labels, spline spaces and pins: a session built from `a` can continue
// on `b` (positions may differ).
bool sameStructure(const model::CompositeSurface& a, const model::CompositeSurface& b) {
    if (a.faces() != b.faces() || a.pinnedVertices() != b.pinnedVertices() ||
        a.vertices().size() != b.vertices().size() || a.edges().size() != b.edges().size()) {
        return false;
    }
    for (auto i = a.vertices().begin(), j = b.vertices().begin(); i != a.vertices().end();
         ++i, ++j) {
        if (i->first != j->first) {
            return false;
        }
    }
    for (auto i = a.edges().begin(), j = b.edges().begin(); i != a.edges().end(); ++i, ++j) {
        const model::EdgeRecord& e = i->second;
        const model::EdgeRecord& f = j->second;
        if (i->first != j->first || e.from != f.from || e.to != f.to || e.label != f.label ||
            e.condition != f.condition || e.controlPoints.size() != f.controlPoints.size() ||
            (e.isSpline() && !(e.space == f.space))) {
            return false;
        }
    }
    return true;
}

std::set<model::VertexId> vertexSet(const std::vector<VertexHandle>& handles) {
    std::set<model::VertexId> vertices;
    for (const VertexHandle& handle : handles) {
        vertices.insert(handle.vertex);
    }
    return vertices;
}

std::set<std::pair<model::EdgeId, int>> pointSet(const std::vector<ControlPointHandle>& handles) {
    std::set<std::pair<model::EdgeId, int>> points;
    for (const ControlPointHandle& handle : handles) {
        points.insert({handle.edge, handle.index});
    }
    return points;
}

bool sameTargets(const DragMove& move, const std::vector<VertexHandle>& handles,
                 const std::vector<ControlPointHandle>& points,
                 const std::vector<SheetHandle>& sheet) {
    auto samePoint = [](const model::Vec3& a, const model::Vec3& b) {
        return a.x == b.x && a.y == b.y && a.z == b.z;
    };
    auto samePlace = [](const model::Vec2& a, const model::Vec2& b) {
        return a.x == b.x && a.y == b.y;
    };
    if (move.vertices.size() != handles.size() || move.controlPoints.size() != points.size() ||
        move.sheet.size() != sheet.size()) {
        return false;
    }
    for (std::size_t i = 0; i < sheet.size(); ++i) {
        if (move.sheet[i].vertex != sheet[i].vertex ||
            !samePlace(move.sheet[i].target, sheet[i].target)) {
            return false;
        }
    }
    for (std::size_t i = 0; i < handles.size(); ++i) {
        if (move.vertices[i].vertex != handles[i].vertex ||
            !samePoint(move.vertices[i].target, handles[i].target)) {
            return false;
        }
    }
    for (std::size_t i = 0; i < points.size(); ++i) {
        if (move.controlPoints[i].edge != points[i].edge ||
            move.controlPoints[i].index != points[i].index ||
            !samePoint(move.controlPoints[i].target, points[i].target)) {
            return false;
        }
    }
    return true;
}

JobFailure failureOf(JobError error, int surface, Status status = Status::IterationLimit,
                     std::string detail = {}) {
    JobFailure failure;
    failure.error = error;
    failure.surface = surface;
    failure.status = status;
    failure.detail = std::move(detail);
    return failure;
}

// A surface that cannot be set up: the model's problem where it named one.
JobFailure cannotSolve(int surface, const std::exception& error) {
    JobFailure failure = failureOf(JobError::CannotSolve, surface, Status::InvalidProblem);
    if (const auto* model = dynamic_cast<const model::ModelError*>(&error)) {
        failure.problem = model->problem();
    } else {
        failure.detail = error.what();
    }
    return failure;
}

JobFailure targetFailure(int surface, model::VertexId vertex, model::EdgeId edge, int index) {
    JobFailure failure = failureOf(JobError::TargetNotFinite, surface);
    failure.vertex = vertex;
    failure.edge = edge;
    failure.index = index;
    return failure;
}

} // namespace

int defaultIterations(JobKind kind, bool settle, DragLengths lengths, bool holdsSheet) {
    switch (kind) {
    case JobKind::Solve:
        return kSolveIterations;
    case JobKind::Edit:
        // The step to the targets, then as many as after a drag that does not keep lengths; a
        // held sheet needs the iterations of a drag holding it (at 11 the annulus turned
        // against its sheet stopped at residual 1.3e-6 with its development overlapping).
        return 1 + iterationsAfterDrag(false, holdsSheet);
    case JobKind::Approximate:
    case JobKind::Join:
        return kApproximationIterations;
    case JobKind::CreaseDrag:
        return settle ? iterationsAfterDrag(false) : 1;
    case JobKind::VertexDrag:
    case JobKind::Rotate:
        break;
    }
    return settle ? iterationsAfterDrag(lengths != DragLengths::Stretch, holdsSheet) : 1;
}

double JobOutcome::largestResidual() const {
    double residual = 0.0;
    for (const SurfaceAssessment& a : assessments) {
        if (a.solved) {
            residual = std::max(residual, a.summary.finalMaxConstraintResidual);
        }
    }
    return residual;
}

int JobOutcome::largestIterationCount() const {
    int count = 0;
    for (const SurfaceAssessment& a : assessments) {
        count = std::max(count, a.summary.iterationsCompleted);
    }
    return count;
}

// A drag's state between its requests, per surface index: the sessions, the surfaces they
// were built from (the press), their pulled handles and every move's targets (for the replay).
struct SolveJob::Drag {
    std::uint64_t id = 0;
    std::vector<std::unique_ptr<SolveSession>> sessions;
    std::vector<model::CompositeSurface> built;
    std::vector<std::set<model::VertexId>> pulled;
    std::vector<std::set<std::pair<model::EdgeId, int>>> pulledPoints;
    std::vector<std::set<model::VertexId>> pulledSheet;
    std::vector<std::vector<DragMove>> moves;
    std::vector<PassedThrough> reached; // states passed through, for followPartway

    explicit Drag(std::size_t count)
        : sessions(count), built(count), pulled(count), pulledPoints(count), pulledSheet(count),
          moves(count), reached(count) {}
};

SolveJob::SolveJob() = default;
SolveJob::~SolveJob() = default;

void SolveJob::reset() {
    m_drag.reset();
}

JobOutcome SolveJob::run(const JobRequest& request, const std::atomic<bool>* cancel,
                         const JobProgressFn& progress) {
    if (request.kind == JobKind::Join) {
        m_drag.reset();
        return runJoinJob(*this, request, cancel, progress);
    }
    const auto start = std::chrono::steady_clock::now();
    const bool drag = isDrag(request.kind);
    const bool settle = !drag || (request.settle && !request.prepare);
    const std::size_t count = request.surfaces.size();
    JobOutcome outcome;
    outcome.kind = request.kind;
    outcome.drag = request.drag;
    outcome.settled = settle;
    outcome.prepared = drag && request.prepare;

    if (!drag || request.drag == 0 || !m_drag || m_drag->id != request.drag ||
        m_drag->sessions.size() != count) {
        m_drag = std::make_unique<Drag>(count);
        m_drag->id = drag ? request.drag : 0;
    }
    Drag& d = *m_drag;

    auto finish = [&]() {
        outcome.elapsedMs =
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
                .count();
        if (!outcome.ok || !drag || settle) {
            // A Solve, an edit, a release or a failure ends what a drag continues.
            m_drag.reset();
        }
        return outcome;
    };
    auto fail = [&](JobFailure failure) {
        outcome.ok = false;
        outcome.failure = std::move(failure);
        outcome.surfaces.clear();
        outcome.assessments.clear();
        return finish();
    };

    const int iterations = std::max(
        0,
        request.iterations.value_or(defaultIterations(
            request.kind, settle, request.lengths,
            std::any_of(request.surfaces.begin(), request.surfaces.end(),
                        [](const model::CompositeSurface& s) { return s.keepsDevelopment(); }))));
    int solvedSurfaces = 0;
    for (std::size_t s = 0; s < count; ++s) {
        const int key = static_cast<int>(s);
        if (request.kind == JobKind::Solve || entryOf(request.targets, key) ||
            !entryOf(request.curvePairs, key).empty() || !entryOf(request.pulled, key).empty() ||
            !entryOf(request.pulledControlPoints, key).empty() ||
            !entryOf(request.pulledSheet, key).empty()) {
            ++solvedSurfaces;
        }
    }
    // An approximation fades its pull in iterations of its own after those asked for.
    const bool approximate = request.kind == JobKind::Approximate;
    const int steps = iterations + (approximate ? kApproximationFadeIterations : 0);
    int total = steps * solvedSurfaces;
    int done = 0;

    for (std::size_t s = 0; s < count; ++s) {
        const int key = static_cast<int>(s);
        const model::CompositeSurface& snapshot = request.surfaces[s];
        const std::vector<VertexHandle> handles = entryOf(request.pulled, key);
        const std::vector<ControlPointHandle> points = entryOf(request.pulledControlPoints, key);
        const std::vector<SheetHandle> sheet = entryOf(request.pulledSheet, key);
        std::set<model::VertexId> sheetVertices;
        for (const SheetHandle& handle : sheet) {
            sheetVertices.insert(handle.vertex);
        }
        SurfaceAssessment assessment;
        const std::shared_ptr<const ApproximationTarget> target = entryOf(request.targets, key);
        if (request.kind != JobKind::Solve && handles.empty() && points.empty() && sheet.empty() &&
            !target && entryOf(request.curvePairs, key).empty()) {
            // Nothing pulled on this surface: it stays as it is.
            if (!allFinite(snapshot)) {
                return fail(failureOf(JobError::NotFinite, key));
            }
            outcome.surfaces.push_back(snapshot);
            outcome.assessments.push_back(std::move(assessment));
            continue;
        }
        assessment.solved = true;
        std::unique_ptr<SolveSession>& session = d.sessions[s];
        const bool continues = drag && session && sameStructure(d.built[s], snapshot) &&
                               d.pulled[s] == vertexSet(handles) &&
                               d.pulledPoints[s] == pointSet(points) &&
                               d.pulledSheet[s] == sheetVertices;
        if (continues) {
            for (const SheetHandle& handle : sheet) {
                if (!session->setSheetHandleTarget(handle.vertex, handle.target)) {
                    return fail(targetFailure(key, handle.vertex, model::kInvalidId, -1));
                }
            }
            for (const VertexHandle& handle : handles) {
                if (!handle.target.isFinite()) {
                    return fail(targetFailure(key, handle.vertex, model::kInvalidId, -1));
                }
                session->setHandleTarget(handle.vertex, handle.target);
            }
            for (const ControlPointHandle& point : points) {
                if (!session->setControlPointTarget(point.edge, point.index, point.target)) {
                    return fail(targetFailure(key, model::kInvalidId, point.edge, point.index));
                }
            }
        } else {
            try {
                SessionOptions options = optionsFor(request, key);
                options.formulation.sheetHandles = sheet;
                if (target) {
                    options.approximationFadeAfter = iterations;
                }
                session = std::make_unique<SolveSession>(snapshot, handles, points, options);
            } catch (const std::exception& error) {
                return fail(cannotSolve(key, error));
            }
            d.built[s] = snapshot;
            d.pulled[s] = vertexSet(handles);
            d.pulledPoints[s] = pointSet(points);
            d.pulledSheet[s] = sheetVertices;
            d.moves[s].clear();
            d.reached[s].clear();
        }
        if (outcome.prepared) {
            const Summary prepared = session->prepare();
            if (!prepared.succeeded()) {
                return fail(
                    failureOf(JobError::SolverFailed, key, prepared.status, prepared.detail));
            }
            assessment.summary = prepared;
            outcome.surfaces.push_back(snapshot);
            outcome.assessments.push_back(std::move(assessment));
            continue;
        }
        if (drag) {
            // The release at the last move's position is no move of its own: the replay then
            // runs the moves a drag of the same steps runs.
            const bool same =
                !d.moves[s].empty() && sameTargets(d.moves[s].back(), handles, points, sheet);
            if (!same) {
                d.moves[s].push_back({handles, points, sheet});
            }
            if (request.settle) {
                // The session is still as the last move left it: the latest state passed
                // through, for the partway search.
                d.reached[s].keepLatest(session->surface());
                // A vertex drag keeping lengths gives up a hopeless settling: the second
                // settling and the partway search follow (kHopelessSettlingResidual, on a held
                // sheet kHopelessHeldSettlingResidual).
                session->settle(keepsLengths(request) && points.empty());
            }
        }
        bool replaying = false;
        auto perIteration = [&](const IterationStats& stats) {
            ++outcome.iterationsRun;
            if (progress) {
                ++done;
                const Problem& problem = session->formulation().problem();
                progress({key, done, std::max(done, total), replaying, false,
                          problem.variableCount(), problem.rowCount(), &stats,
                          replaying ? nullptr : &session->surface()});
            }
        };
        const auto stepped = std::chrono::steady_clock::now();
        Summary summary = session->step(steps, cancel, perIteration);
        if (target && !target->points.empty()) {
            try {
                const ApproximationSteps run{request, key,    iterations, steps,
                                             handles, points, cancel,     perIteration};
                summary = continueApproximation(run, *target, snapshot, session, summary,
                                                assessment, total);
            } catch (const std::exception& error) {
                return fail(cannotSolve(key, error));
            }
        }
        auto stepTime = std::chrono::steady_clock::now() - stepped;
        if (session->gaveUp() && summary.iterationsCompleted > 0) {
            // What the whole release would have taken (partwayFits).
            stepTime = stepTime * steps / summary.iterationsCompleted;
        }
        if (drag && !request.settle && summary.succeeded() && !d.moves[s].empty()) {
            d.reached[s].moved(d.moves[s].size(), session->surface(),
                               summary.finalMaxConstraintResidual);
        }
        if (request.kind == JobKind::Solve && summary.succeeded()) {
            assessment.bestIteration = session->returnToBestIterate(&summary).iteration;
        }
        const bool vertexDragSettles =
            drag && request.settle && keepsLengths(request) && points.empty();
        if (vertexDragSettles) {
            const std::vector<model::VertexId> dragged(d.pulled[s].begin(), d.pulled[s].end());
            assessment.held = model::findVertexHeldByPins(d.built[s], dragged);
        }
        // The release keeping lengths, judged (finalMaxConstraintResidual is the start's when
        // no iteration completed).
        std::optional<DragOutcome> judged;
        if (vertexDragSettles && summary.succeeded()) {
            judged = judgeDrag(d.built[s], session->surface(), summary.finalMaxConstraintResidual,
                               summary.status == Status::StoppedBeforeDegenerate);
        }
        if (judged && judged->problems() > 0 && !d.reached[s].states().empty()) {
            // On a fine model the release can alternate as the keep-lengths energy fades, and
            // fold over (docs/tuning.md, "Settled again"): the drag's last state settles once
            // more, the energy fading only after iterations whose residual did not rise; the
            // better of the two settlings is kept.
            std::unique_ptr<SolveSession> first = std::move(session);
            try {
                SessionOptions options = optionsFor(request, key);
                options.formulation.sheetHandles = sheet;
                session = secondSettling(d.built[s], d.reached[s].states().back().surface, handles,
                                         points, options);
            } catch (const std::exception& error) {
                return fail(cannotSolve(key, error));
            }
            total += steps;
            const Summary again = session->step(steps, cancel, perIteration);
            if (again.status == Status::Cancelled) {
                return fail(failureOf(JobError::Cancelled, key));
            }
            std::optional<DragOutcome> second;
            if (again.succeeded() && allFinite(session->surface())) {
                second = judgeDrag(d.built[s], session->surface(), again.finalMaxConstraintResidual,
                                   again.status == Status::StoppedBeforeDegenerate);
            }
            if (second && second->problems() < judged->problems()) {
                assessment.firstSettlingIterations = summary.iterationsCompleted;
                summary = again;
                judged = second;
                assessment.settledAgain = true;
            } else {
                session = std::move(first);
            }
        }
        if (drag && request.settle && session->stalled()) {
            assessment.stalledAfter = summary.iterationsCompleted;
        }
        std::optional<std::vector<model::FaceId>> knownOverlaps;
        if (judged && judged->measurable) {
            knownOverlaps = judged->overlapping; // measured once
        }
        // A surface that keeps its development is never replayed stretching: its sheet holds.
        if (vertexDragSettles && request.lengths == DragLengths::Automatic &&
            !snapshot.keepsDevelopment() && judged) {
            // Keeping lengths failed? Then the same drag from the press, stretching.
            const DragOutcome kept = *judged;
            if (kept.problems() > 0) {
                replaying = true;
                ReplayedDrag replay;
                try {
                    replay = replayStretching(d.built[s], d.moves[s], kIterationsAfterDrag, cancel,
                                              perIteration);
                } catch (const std::exception& error) {
                    return fail(cannotSolve(key, error));
                }
                if (replay.settling.status == Status::Cancelled) {
                    summary = replay.settling;
                } else if (replay.settling.succeeded() && allFinite(replay.session->surface())) {
                    LengthsReplay record;
                    record.keepingLengths = kept;
                    record.stretching =
                        judgeDrag(d.built[s], replay.session->surface(),
                                  replay.settling.finalMaxConstraintResidual, replay.stopped);
                    record.taken = prefersStretched(kept, record.stretching);
                    if (record.taken) {
                        session = std::move(replay.session);
                        summary = replay.settling;
                        knownOverlaps.reset();
                        if (record.stretching.measurable) {
                            knownOverlaps = record.stretching.overlapping;
                        }
                    }
                    assessment.replay = record;
                }
            }
        }
        if (summary.status == Status::Cancelled) {
            return fail(failureOf(JobError::Cancelled, key));
        }
        if (!summary.succeeded()) {
            return fail(failureOf(JobError::SolverFailed, key, summary.status, summary.detail));
        }
        if (!allFinite(session->surface())) {
            return fail(failureOf(JobError::NotFinite, key));
        }
        assessment.summary = summary;
        if (summary.status == Status::StoppedBeforeDegenerate) {
            assessment.refusedIterate = session->refusedIterate();
        }
        const model::CompositeSurface* result = &session->surface();
        if (request.kind == JobKind::Solve) {
            // Solve never spoils a design: the fairness of a fresh solve may pull a nearly
            // valid fold through a crumpled shape (docs/tuning.md, "Solve's guard").
            const double before = worstDevelopability(snapshot);
            const double after = worstDevelopability(session->surface());
            if (after > std::max(kLessDevelopableFactor * before, kNegligibleDevelopability)) {
                assessment.keptAsItWas = SurfaceAssessment::LessDevelopable{before, after};
                result = &snapshot;
                knownOverlaps.reset();
            }
        }
        measureHandleGaps(assessment, *result, handles, points);
        measureSheetGaps(assessment, *result, sheet);
        assessment.sheetHeld = result->keepsDevelopment();
        if (settle) {
            measureSettled(assessment, *result, drag ? &d.built[s] : nullptr, knownOverlaps);
        }
        if ((drag || request.kind == JobKind::Edit) && settle && refusable(assessment)) {
            // A drag never ends broken: where the sheet cannot follow, the result is refused
            // and the design follows the drag only as far as it ends well, or stays as at the
            // press, if that was not broken. An exact move or rotation (Edit) that ends broken
            // is refused as a whole: the design stays as it was before it.
            SurfaceAssessment press = assessPress(d.built[s], summary);
            if (!refusable(press)) {
                auto refused = std::make_shared<const SurfaceAssessment>(std::move(assessment));
                std::optional<Partway> partway;
                // A thorough search where it fits its budget (partwayFits), else a brief one.
                if (!d.reached[s].states().empty()) {
                    const PartwaySearch search =
                        request.untimedPartway ? PartwaySearch::Untimed
                                               : (partwayFits(stepTime) ? PartwaySearch::Thorough
                                                                        : PartwaySearch::Brief);
                    total += partwayIterationLimit(search, steps);
                    partway =
                        followPartway(d.built[s], press, d.reached[s].states(), d.moves[s],
                                      optionsFor(request, key), steps, {handles, points, sheet},
                                      cancel, search, [&](const IterationStats& stats) {
                                          ++outcome.iterationsRun;
                                          if (progress) {
                                              ++done;
                                              progress({key, done, std::max(done, total), false,
                                                        true, 0, 0, &stats, nullptr});
                                          }
                                      });
                }
                if (partway) {
                    session = std::move(partway->session);
                    assessment = std::move(partway->assessment);
                    result = &session->surface();
                } else {
                    measureHandleGaps(press, d.built[s], handles, points);
                    measureSheetGaps(press, d.built[s], sheet);
                    assessment = std::move(press);
                    result = &d.built[s];
                }
                assessment.takenBack = std::move(refused);
            }
        }
        if (drag && settle && assessment.sheetHeld &&
            assessment.largestHandleGap > kNegligibleLag) {
            assessment.tautPins = model::findTautPinLines(*result);
        }
        outcome.surfaces.push_back(*result);
        outcome.assessments.push_back(std::move(assessment));
    }
    outcome.ok = true;
    return finish();
}

} // namespace devsurf::solver
