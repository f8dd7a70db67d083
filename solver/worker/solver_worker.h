#pragma once

#include "solver/session/solve_job.h"

#include <QMetaType>
#include <QObject>

#include <memory>
#include <thread>

namespace devsurf::solver {

// A job request with the document revision its snapshot was taken at.
// `ticket` is the submitter's own mark (a drag's id, a solve's number), returned with the result.
struct SolveRequest {
    quint64 revision = 0;
    quint64 ticket = 0;
    JobRequest job;
};

// The job's outcome for one request, with the request's revision.
struct SolveResult {
    quint64 revision = 0;
    quint64 ticket = 0;
    JobOutcome outcome;
};

// The solver on its own thread; it runs SolveJob and decides nothing itself. submit() hands
// over a snapshot; the worker reports progress per iteration and one result per request it
// ran, by signals queued to the receiver's thread. A request submitted while another one waits
// replaces it (only the newest is solved, the replaced one gets no result); cancellation is an
// atomic flag checked between iterations. The caller never waits on the worker.
class SolverWorker : public QObject {
    Q_OBJECT
public:
    explicit SolverWorker(QObject* parent = nullptr); // starts its own thread
    ~SolverWorker() override;                         // cancels, quits and joins the thread

    // Thread-safe. Replaces any request not yet started (coalescing); a request already
    // running finishes its current iteration(s) unless cancel() is called.
    void submit(SolveRequest request);
    // Raises the cancel flag of the running request and drops the pending one.
    void cancel();
    // A request is running or waiting.
    bool isBusy() const;
    // Requests actually solved since construction (the others were coalesced away).
    quint64 solvedCount() const;

signals:
    // Both are emitted on the thread this object lives in (normally the GUI thread), from
    // records the worker thread hands over under a mutex.
    void progress(quint64 revision, int iteration, int iterations, double residual);
    void finished(const devsurf::solver::SolveResult& result);

private:
    struct Impl;
    void run();
    // On the thread this object lives in: progress, then results. Posted by name, so that the
    // worker thread hands over no data but what deliverResults() takes under the mutex.
    Q_INVOKABLE void deliverResults();
    std::unique_ptr<Impl> m_impl;
    std::thread m_thread;
};

} // namespace devsurf::solver

Q_DECLARE_METATYPE(devsurf::solver::SolveResult)
