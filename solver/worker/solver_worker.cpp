#include "solver/worker/solver_worker.h"

#include <algorithm>
#include <atomic>
#include <condition_variable>
#include <deque>
#include <mutex>
#include <optional>

namespace devsurf::solver {

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

    // The worker thread's own.
    SolveJob job;
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
        // Interactive drags: their moves factorise beside the steps, on a core of their own.
        request.job.backgroundFactorization = true;
        SolveResult result;
        result.revision = request.revision;
        result.ticket = request.ticket;
        result.outcome =
            m_impl->job.run(request.job, &m_impl->cancel, [&](const JobProgress& step) {
                {
                    std::lock_guard lock(m_impl->mutex);
                    m_impl->progressOutbox.push_back({request.revision, step.done, step.total,
                                                      step.stats->maxConstraintResidual});
                }
                QMetaObject::invokeMethod(this, "deliverResults", Qt::QueuedConnection);
            });
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

} // namespace devsurf::solver
