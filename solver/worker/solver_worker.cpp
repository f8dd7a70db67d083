#include "solver/worker/solver_worker.h"

#include "model/pattern/cutting_pattern.h"
#include "solver/quality/crease_quality.h"
#include "solver/quality/quality_measures.h"

#include <atomic>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <deque>
#include <map>
#include <mutex>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>

namespace devsurf::solver {

namespace {

bool isFinite(const model::Vec3& p) {
    return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
}

bool allFinite(const model::CompositeSurface& surface) {
    for (const auto& [id, position] : surface.vertices()) {
        if (!isFinite(position)) {
            return false;
        }
    }
    for (const auto& [id, edge] : surface.edges()) {
        for (const model::Vec3& point : edge.controlPoints) {
            if (!isFinite(point)) {
                return false;
            }
        }
    }
    return true;
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

QString surfaceLabel(const model::CompositeSurface& surface, std::size_t index) {
    QString label = QStringLiteral("Surface %1").arg(index + 1);
    if (!surface.name().empty()) {
        label += QStringLiteral(" (%1)").arg(QString::fromStdString(surface.name()));
    }
    return label;
}

// A sentence: capital first letter, final period.
QString sentence(QString text) {
    if (!text.isEmpty()) {
        text[0] = text[0].toUpper();
        if (!text.endsWith(QLatin1Char('.'))) {
            text += QLatin1Char('.');
        }
    }
    return text;
}

// The largest normalised developability residual sampled over the surface's strips (0 for a
// surface without strips).
double worstDevelopability(const model::CompositeSurface& surface) {
    const auto faces = developabilityByFace(surface);
    return faces.empty() ? 0.0 : faces.front().second;
}

// The options of a session: a drag's (of a crease if `crease`), or Tools ▸ Solve's, which stops
// once converged.
SessionOptions sessionOptions(bool keepLengths, bool drag, bool crease) {
    SessionOptions options = keepLengths ? keepLengthsSessionOptions()
                             : crease    ? creaseDragSessionOptions()
                                         : SessionOptions{};
    if (!drag) {
        options.stopResidual = kSolveStopResidual;
    }
    return options;
}

} // namespace

struct SolverWorker::Impl {
    // Shared between the caller's thread and the worker thread (under mutex). Standard
    // mutexes rather than Qt's: ThreadSanitizer sees them, so the test command can check
    // that every hand-over between the threads is synchronised.
    mutable std::mutex mutex;
    std::condition_variable wake;
    std::optional<SolveRequest> pending;
    // Results on their way to the caller's thread: the worker puts them here under the
    // mutex and posts deliverResults(), which takes them under the mutex and emits them there.
    std::deque<SolveResult> outbox;
    struct Progress {
        quint64 revision;
        int iteration;
        int iterations;
        double residual;
    };
    std::deque<Progress> progressOutbox;
    bool running = false;
    bool quit = false;
    quint64 solved = 0;
    std::atomic<bool> cancel{false};

    // The worker thread's own: the sessions of the last drag (per surface index), the
    // surfaces they were built from and their pulled vertices.
    quint64 sessionKey = 0;
    std::vector<std::unique_ptr<SolveSession>> sessions;
    std::vector<model::CompositeSurface> built;
    std::vector<std::set<model::VertexId>> pulled;
    std::vector<std::set<std::pair<model::EdgeId, int>>> pulledPoints;
    // Per surface index: the handles' targets of every move of the drag solved so far.
    std::vector<std::vector<DragMove>> moves;

    void dropSessions() {
        sessionKey = 0;
        sessions.clear();
        built.clear();
        pulled.clear();
        pulledPoints.clear();
        moves.clear();
    }
};

SolverWorker::SolverWorker(QObject* parent) : QObject(parent), m_impl(std::make_unique<Impl>()) {
    qRegisterMetaType<devsurf::solver::SolveResult>();
    // A standard thread (no event loop needed): its start and join are visible to
    // ThreadSanitizer. Results reach this object's thread through deliverResults().
    m_thread = std::thread([this] { run(); });
}

SolverWorker::~SolverWorker() {
    if (Impl* d = m_impl.get()) {
        std::lock_guard lock(d->mutex);
        d->quit = true;
        d->pending.reset();
        d->cancel.store(true);
        d->wake.notify_all();
    }
    m_thread.join();
}

void SolverWorker::submit(SolveRequest request) {
    std::lock_guard lock(m_impl->mutex);
    m_impl->pending = std::move(request);
    m_impl->wake.notify_all();
}

void SolverWorker::cancel() {
    std::lock_guard lock(m_impl->mutex);
    m_impl->pending.reset();
    if (m_impl->running) {
        m_impl->cancel = true;
    }
}

bool SolverWorker::isBusy() const {
    std::lock_guard lock(m_impl->mutex);
    return m_impl->running || m_impl->pending.has_value();
}

quint64 SolverWorker::solvedCount() const {
    std::lock_guard lock(m_impl->mutex);
    return m_impl->solved;
}

void SolverWorker::run() {
    for (;;) {
        SolveRequest request;
        {
            std::unique_lock lock(m_impl->mutex);
            m_impl->wake.wait(lock, [this] { return m_impl->quit || m_impl->pending; });
            if (m_impl->quit) {
                return;
            }
            request = std::move(*m_impl->pending);
            m_impl->pending.reset();
            // Reset under the lock: a cancel() from now on is meant for this request.
            m_impl->cancel = false;
            m_impl->running = true;
            ++m_impl->solved;
        }
        SolveResult result = solve(request);
        {
            // Not busy any more by the time a receiver sees the result.
            std::lock_guard lock(m_impl->mutex);
            m_impl->running = false;
            m_impl->outbox.push_back(std::move(result));
        }
        QMetaObject::invokeMethod(this, "deliverResults", Qt::QueuedConnection);
    }
}

void SolverWorker::deliverResults() {
    std::deque<Impl::Progress> steps;
    std::deque<SolveResult> results;
    {
        std::lock_guard lock(m_impl->mutex);
        steps.swap(m_impl->progressOutbox);
        results.swap(m_impl->outbox);
    }
    for (const Impl::Progress& step : steps) {
        emit progress(step.revision, step.iteration, step.iterations, step.residual);
    }
    for (const SolveResult& result : results) {
        emit finished(result);
    }
}

namespace {

// SolveResult::creaseResiduals of one surface.
double sampledCreaseResidual(const model::CompositeSurface& surface) {
    for (const auto& [id, edge] : surface.edges()) {
        if (edge.condition != model::CreaseCondition::None) {
            const CreaseQuality quality = measureCreaseQuality(surface);
            return quality.creases > 0 ? quality.residualMax : -1.0;
        }
    }
    return -1.0;
}

} // namespace

SolveResult SolverWorker::solve(const SolveRequest& request) {
    const auto start = std::chrono::steady_clock::now();
    Impl& d = *m_impl;
    SolveResult result;
    result.revision = request.revision;
    result.sessionKey = request.sessionKey;
    const bool drag = request.sessionKey != 0;
    const std::size_t count = request.surfaces.size();
    const bool reuse = drag && d.sessionKey == request.sessionKey && d.sessions.size() == count;
    if (!reuse) {
        d.dropSessions();
        d.sessions.resize(count);
        d.built.resize(count);
        d.pulled.resize(count);
        d.pulledPoints.resize(count);
        d.moves.resize(count);
    }
    d.sessionKey = request.sessionKey;

    auto fail = [&](const QString& error) {
        result.ok = false;
        result.error = sentence(error);
        result.surfaces.clear();
        result.summaries.clear();
        result.elapsedMs =
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
                .count();
        d.dropSessions();
        return result;
    };

    const int iterations = std::max(0, request.iterations);
    auto handlesOf = [&](std::size_t s) {
        const auto it = request.pulled.find(static_cast<int>(s));
        return it == request.pulled.end() ? std::vector<VertexHandle>{} : it->second;
    };
    auto pointsOf = [&](std::size_t s) {
        const auto it = request.pulledControlPoints.find(static_cast<int>(s));
        return it == request.pulledControlPoints.end() ? std::vector<ControlPointHandle>{}
                                                       : it->second;
    };
    int solvedSurfaces = 0;
    for (std::size_t s = 0; s < count; ++s) {
        if (!drag || !handlesOf(s).empty() || !pointsOf(s).empty()) {
            ++solvedSurfaces;
        }
    }
    const int total = iterations * solvedSurfaces;
    int done = 0;
    // The overlapping patches judgeDrag found already (an Automatic drag's settling).
    std::map<std::size_t, std::vector<model::FaceId>> judgedOverlaps;

    for (std::size_t s = 0; s < count; ++s) {
        const model::CompositeSurface& snapshot = request.surfaces[s];
        const std::vector<VertexHandle> handles = handlesOf(s);
        const std::vector<ControlPointHandle> points = pointsOf(s);
        if (drag && handles.empty() && points.empty()) {
            // Not dragged: stays as it is.
            if (!allFinite(snapshot)) {
                return fail(surfaceLabel(snapshot, s) + " has a coordinate that is not finite");
            }
            result.surfaces.push_back(snapshot);
            result.summaries.emplace_back();
            continue;
        }
        std::unique_ptr<SolveSession>& session = d.sessions[s];
        const bool continues = session && sameStructure(d.built[s], snapshot) &&
                               d.pulled[s] == vertexSet(handles) &&
                               d.pulledPoints[s] == pointSet(points);
        if (continues) {
            for (const VertexHandle& handle : handles) {
                if (!isFinite(handle.target)) {
                    return fail(QStringLiteral("the drag target of vertex %1 is not finite")
                                    .arg(handle.vertex));
                }
                session->setHandleTarget(handle.vertex, handle.target);
            }
            for (const ControlPointHandle& point : points) {
                if (!session->setControlPointTarget(point.edge, point.index, point.target)) {
                    return fail(QStringLiteral("the drag target of control point %1 of edge %2 "
                                               "is not finite")
                                    .arg(point.index)
                                    .arg(point.edge));
                }
            }
        } else {
            try {
                session = std::make_unique<SolveSession>(
                    snapshot, handles, points,
                    sessionOptions(request.keepLengths, drag, !points.empty()));
            } catch (const std::exception& error) {
                return fail(surfaceLabel(snapshot, s) + QStringLiteral(" cannot be solved: ") +
                            QString::fromStdString(error.what()));
            }
            d.built[s] = snapshot;
            d.pulled[s] = vertexSet(handles);
            d.pulledPoints[s] = pointSet(points);
            d.moves[s].clear();
        }
        if (drag) {
            d.moves[s].push_back({handles, points});
        }
        if (request.settle) {
            session->settle();
        }
        auto progress = [&](const IterationStats& stats) {
            {
                std::lock_guard lock(d.mutex);
                d.progressOutbox.push_back(
                    {request.revision, ++done, std::max(done, total), stats.maxConstraintResidual});
            }
            QMetaObject::invokeMethod(this, "deliverResults", Qt::QueuedConnection);
        };
        Summary summary = session->step(iterations, &d.cancel, progress);
        if (!drag && summary.succeeded()) {
            // Solve ends on its best iterate (SolveSession::returnToBestIterate).
            const SolveSession::BestIterate best = session->returnToBestIterate(&summary);
            if (best.iteration > 0) {
                summary.message += std::string(summary.message.empty() ? "" : "; ") +
                                   "ended on iteration " + std::to_string(best.iteration) +
                                   ", the one with the smallest residual";
            }
        }
        std::optional<DragOutcome> judged;
        if (drag && request.settle && request.keepLengths && points.empty()) {
            const std::vector<model::VertexId> dragged(d.pulled[s].begin(), d.pulled[s].end());
            if (auto held = model::findVertexHeldByPins(d.built[s], dragged)) {
                result.held.push_back({static_cast<int>(s), *held});
            }
        }
        if (drag && request.settle && request.keepLengths && request.stretchIfLengthsFail &&
            points.empty() && summary.succeeded()) {
            // Automatic: keeping lengths failed? Then the same drag, stretching.
            // (finalMaxConstraintResidual is the start's when no iteration completed.)
            const DragOutcome kept =
                judgeDrag(d.built[s], session->surface(), summary.finalMaxConstraintResidual,
                          summary.status == Status::StoppedBeforeDegenerate);
            judged = kept;
            if (kept.problems() > 0) {
                ReplayedDrag replay;
                try {
                    replay = replayStretching(d.built[s], d.moves[s], kIterationsAfterDrag,
                                              &d.cancel, progress);
                } catch (const std::exception& error) {
                    return fail(surfaceLabel(snapshot, s) + QStringLiteral(" cannot be solved: ") +
                                QString::fromStdString(error.what()));
                }
                if (replay.settling.status == Status::Cancelled) {
                    summary = replay.settling;
                } else if (replay.settling.succeeded() && allFinite(replay.session->surface())) {
                    const Summary& end = replay.settling;
                    const DragOutcome stretched =
                        judgeDrag(d.built[s], replay.session->surface(),
                                  end.finalMaxConstraintResidual, replay.stopped);
                    if (prefersStretched(kept, stretched)) {
                        session = std::move(replay.session);
                        summary = end;
                        judged = stretched;
                        result.stretched.push_back({static_cast<int>(s), kept});
                    }
                }
            }
        }
        if (summary.status == Status::Cancelled) {
            fail(QStringLiteral("the solve was cancelled"));
            result.cancelled = true;
            return result;
        }
        if (!summary.succeeded()) {
            return fail(surfaceLabel(snapshot, s) + QStringLiteral(" could not be solved: ") +
                        QString::fromStdString(summary.message));
        }
        if (!allFinite(session->surface())) {
            return fail(surfaceLabel(snapshot, s) +
                        QStringLiteral(" could not be solved: the solver produced a value "
                                       "that is not finite"));
        }
        if (!drag) {
            // Solve must not spoil a design: measured on the curved fold a drag keeping
            // lengths leaves on the lifted Fig. 8 (sampled residual 4e-7), the fairness of a
            // fresh solve pulls it towards flat through a crumpled shape (0.1 after 10
            // iterations).
            const double before = worstDevelopability(snapshot);
            const double after = worstDevelopability(session->surface());
            if (after > std::max(kLessDevelopableFactor * before, kNegligibleDevelopability)) {
                result.kept.push_back({static_cast<int>(s), before, after});
                result.surfaces.push_back(snapshot);
                result.summaries.push_back(summary);
                continue;
            }
        }
        if (judged && judged->measurable) {
            judgedOverlaps[s] = judged->overlapping;
        }
        result.surfaces.push_back(session->surface());
        result.summaries.push_back(summary);
    }
    if (!drag || request.settle) {
        result.creaseResiduals.assign(result.surfaces.size(), -1.0);
        result.selfOverlaps.resize(result.surfaces.size());
        for (std::size_t s = 0; s < result.surfaces.size(); ++s) {
            const auto known = judgedOverlaps.find(s);
            if (known != judgedOverlaps.end()) {
                result.selfOverlaps[s] = known->second;
            } else if (!result.summaries[s].iterations.empty()) {
                result.selfOverlaps[s] = model::selfOverlappingPatches(result.surfaces[s]);
            }
            result.creaseResiduals[s] = sampledCreaseResidual(result.surfaces[s]);
        }
    }
    if (!drag) {
        d.dropSessions();
    }
    result.ok = true;
    result.elapsedMs =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    return result;
}

} // namespace devsurf::solver
