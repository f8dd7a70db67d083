#pragma once

#include "model/held_by_pins.h"
#include "solver/session/drag_lengths.h"
#include "solver/session/solve_session.h"

#include <QMetaType>
#include <QObject>
#include <QString>

#include <map>
#include <memory>
#include <thread>
#include <vector>

namespace devsurf::solver {

// An immutable snapshot of what to solve.
struct SolveRequest {
    quint64 revision = 0;                            // Document::revision() of the snapshot
    std::vector<model::CompositeSurface> surfaces;   // the whole project's surfaces (pins inside)
    std::map<int, std::vector<VertexHandle>> pulled; // per surface index: drag targets
    // Per surface index: pulled interior control points of S-edges (a dragged crease).
    std::map<int, std::vector<ControlPointHandle>> pulledControlPoints;
    int iterations = 10;
    // Damp stretching of every strip's control net (kKeepLengthsWeight): the sheet bends.
    bool keepLengths = false;
    // With keepLengths, a vertex drag's settling request (settle) whose result fails
    // (judgeDrag) replays the drag from the press letting the sheet stretch, along the moves
    // this worker solved, and returns whichever ends with fewer problems
    // (DragLengths::Automatic).
    bool stretchIfLengthsFail = false;
    // The iterations after a drag's release (SolveSession::settle()).
    bool settle = false;
    // Non-zero: a drag. Requests with the same key reuse the worker's sessions of the previous
    // request when the surfaces' structure is unchanged, only moving the handle targets and
    // continuing from the session's own last state (the snapshot's geometry is then ignored
    // except for surfaces without a session). Surfaces without pulled handles are returned
    // as they are in a drag (with an empty summary). 0: fresh sessions from the snapshot for
    // every surface (Solve).
    quint64 sessionKey = 0;
};

struct SolveResult {
    quint64 revision = 0;
    quint64 sessionKey = 0;
    bool ok = false;        // false: error says why (one sentence), surfaces is empty
    bool cancelled = false; // cancelled results are still emitted, with ok == false
    QString error;
    std::vector<model::CompositeSurface> surfaces; // every surface, solved (finite values only)
    std::vector<Summary> summaries;                // per surface
    // A Solve (not a drag or an edit) never returns a surface less developable than it was
    // given: one whose solved shape samples a larger normalised developability residual than
    // kLessDevelopableFactor times the start's (and above kNegligibleDevelopability) is
    // returned as it was, and listed here with both residuals.
    struct Kept {
        int surface = 0;
        double before = 0.0; // largest sampled |det(a−b, a′, b′)| / (|a−b| |a′| |b′|)
        double after = 0.0;
    };
    std::vector<Kept> kept;
    // Per surface, for the final result of a Solve or an edit and of a drag's settling request
    // (SolveRequest::settle): the patches at which its development overlaps itself
    // (model::selfOverlappingPatches), so that it cannot be cut from one sheet. Measured on
    // the worker's thread, since it costs about a development (50 ms on an annulus of 18,000
    // solver variables); empty for the results of a drag's moves and surfaces not solved.
    std::vector<std::vector<model::FaceId>> selfOverlaps;
    // Per surface, alongside selfOverlaps: the largest residual of its crease conditions,
    // sampled densely along every crease with the strips' unit normals
    // (CreaseQuality::residualMax), or −1 where no crease has a condition. The solver's residual
    // does not bound it: its rows hold at collocation values with the normal splines, whose
    // lengths may differ (measured: fig6 lifted 60 mm keeping lengths ends at 3.4e-12 with the
    // sampled curved-fold residual at 1.1e-7).
    std::vector<double> creaseResiduals;
    // The surfaces (indices) of a drag with SolveRequest::stretchIfLengthsFail whose result
    // is the replay letting the sheet stretch, and what went wrong keeping lengths.
    struct Stretched {
        int surface = 0;
        DragOutcome keepingLengths;
    };
    std::vector<Stretched> stretched;
    // The surfaces (indices) of a drag keeping lengths, in its settling request, where pinned
    // vertices hold a dragged one where the sheet cannot bend (model::findVertexHeldByPins):
    // the result then had to stretch, whatever keeping lengths damped.
    struct Held {
        int surface = 0;
        model::HeldVertex held;
    };
    std::vector<Held> held;
    double elapsedMs = 0.0;
};

// A solve whose result is this many times less developable than its start made it worse.
inline constexpr double kLessDevelopableFactor = 10.0;
// Below this normalised developability residual a surface counts as developable either way.
inline constexpr double kNegligibleDevelopability = 1e-8;

// The solver on its own thread. submit() hands over a snapshot; the worker reports progress
// per iteration and one result per request it ran, by signals queued to the receiver's
// thread. A request submitted while another one waits replaces it (only the newest is
// solved, the replaced one gets no result); cancellation is an atomic flag checked between
// iterations. The caller never waits on the worker.
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
    SolveResult solve(const SolveRequest& request);
    std::unique_ptr<Impl> m_impl;
    std::thread m_thread;
};

} // namespace devsurf::solver

Q_DECLARE_METATYPE(devsurf::solver::SolveResult)
