#pragma once

#include "model/composite_surface.h"
#include "model/held_by_pins.h"
#include "panels/solver_panel.h"
#include "solver/session/drag_lengths.h"

#include <QObject>
#include <QString>
#include <QUndoCommand>

#include <map>
#include <memory>
#include <set>
#include <vector>

namespace devsurf::solver {
class SolverWorker;
struct SolveResult;
struct JobFailure;
struct JobRequest;
} // namespace devsurf::solver

namespace devsurf::app {

class Workspace;

// Tools ▸ Solve and what it shares with the Drag tool: the background solver worker. A solve
// takes a snapshot of every surface and runs a Solve job on the worker (at most the setting
// "solver/iterations", default solver::kSolveIterations); the result becomes one undo step
// ("Solve") if the design did not change meanwhile and the result differs from it. Any edit while
// solving cancels the solve; a cancelled or failed solve changes nothing and says why. solveEdit()
// does the same for an edit of one surface not yet applied (Tools ▸ Move or Rotate Vertices with
// Keep developable): the edit and its solve become one undo step, or nothing changes.
class SolveController : public QObject {
    Q_OBJECT
public:
    explicit SolveController(Workspace* workspace, QObject* parent = nullptr);
    ~SolveController() override;

    solver::SolverWorker* worker() const { return m_worker; }
    bool isSolving() const { return m_solving; }
    // How the last solve or edit ended (what finished() worded).
    enum class Ending {
        None,
        Solved,
        LeftAsItWas,
        Cancelled,
        CancelledByChange,
        Failed,
        Discarded
    };
    Ending lastEnding() const { return m_ending; }
    static int iterationsSetting();
    // Tools ▸ Lengths While Dragging: whether vertex drags damp stretching of the sheet.
    enum class LengthsMode { Automatic = 0, Keep = 1, Stretch = 2 };
    static LengthsMode lengthsSetting();
    static void setLengthsSetting(LengthsMode mode);
    // Whether vertex drags keep lengths under the setting (Automatic and Keep Lengths), and
    // whether one that fails keeping them is replayed letting the sheet stretch (Automatic;
    // solver::DragLengths).
    static bool keepsLengths();
    static bool stretchesWhereLengthsFail();
    // Builds a report of a result for the Solver panel (worst patches when the tolerance was
    // not reached).
    static SolveReport reportOf(const solver::SolveResult& result, const QString& title);
    // Why a job failed, as a sentence.
    static QString failureText(const solver::JobFailure& failure);
    // What went wrong keeping lengths, for the report: "folded over in 2 places, a development
    // overlapping itself".
    static QString problemsText(const solver::DragOutcome& outcome);
    // Why a drag's release was taken back (SurfaceAssessment::takenBack): "did not reach the
    // tolerance (residual 8.8e-02; patch 7 sampled 3.1e-02 from developable), folded over in
    // 38 places, …".
    static QString takenBackText(const solver::SurfaceAssessment& refused);
    // A lag in mm as a designer reads it: two significant digits below 1 mm, else one decimal.
    static QString lagText(double mm);
    // Why keeping lengths could not follow a drag (model::findVertexHeldByPins), continuing a
    // status sentence: "; vertex 5 lies inside the triangle of the pinned vertices 0, 3 and 12,
    // …".
    static QString heldText(const model::HeldVertex& held);
    // "1, 2, 6" for the patches a report names.
    static QString patchList(const QList<int>& faces);
    // Runs a job whose result its caller applies (Tools ▸ Approximate Reference Shape…): busy,
    // progress, Cancel and cancelling on any edit as for a solve, every sentence naming `title`.
    // A successful outcome of the design as it still is goes to jobDone(); the controller stays
    // busy (an edit still cancels) until the caller ends it with finishJob(). Returns the
    // request's ticket.
    quint64 runJob(solver::JobRequest job, const QString& title);
    // The ticket of the running solve or job (0 when idle).
    quint64 runningTicket() const { return m_solving ? m_ticket : 0; }
    // Ends the job of runJob(): pushes `commands` as one undo step named by its title (none:
    // no step), shows `report` in the Solver panel and says `sentence`.
    void finishJob(Ending ending, const SolveReport& report, const QString& sentence,
                   std::vector<std::unique_ptr<QUndoCommand>> commands = {});

public slots:
    void solve();
    // Solves an edit of surface surfaceIndex not yet applied (`edited`): from the current
    // surface, the held vertices are pulled to their positions in `edited` (an Edit job, which
    // decides the iterations; pins respected), and the result, with the held vertices exactly
    // where the edit put them (where the surface holds its sheet: where the sheet let them),
    // replaces the current surface as one undo step named title, whose undo returns the state
    // before the edit. A result the job refuses (it would end broken) changes nothing.
    void solveEdit(int surfaceIndex, model::CompositeSurface edited,
                   const std::set<model::VertexId>& held, const QString& title);
    // Stops a running solve; the design stays as it is. reason completes "Solve cancelled: …".
    void cancel(const QString& reason = QString());

signals:
    void busyChanged(bool solving);
    void progress(int iteration, int iterations, double residual);
    // A solve ended (applied, cancelled, failed or discarded): the sentence says which.
    void finished(const QString& sentence);
    void reportReady(const devsurf::app::SolveReport& report);
    // runJob()'s outcome, not applied yet (see there).
    void jobDone(const devsurf::solver::SolveResult& result);

private:
    void onResult(const solver::SolveResult& result);
    void onDocumentChanged();
    // Ends the solve; shows `report` (if any) in the Solver panel, then says `sentence`.
    void stop(const SolveReport* report, Ending ending, const QString& sentence);
    void applyEdit(const solver::SolveResult& result, const SolveReport& report);
    // The sentences of a solve or of an edit's solve.
    QString cancelledSentence(const QString& reason) const;
    QString failedSentence(const QString& error) const;
    // Names the patches of `report` that fold over onto themselves or, if none does, those at
    // which the development overlaps itself (empty if neither).
    QString checkShapeSentence(const SolveReport& report) const;

    Workspace* m_workspace;
    solver::SolverWorker* m_worker;
    bool m_solving = false;
    Ending m_ending = Ending::None;
    bool m_cancelledByChange = false;
    bool m_applying = false;
    quint64 m_revision = 0;
    // The running request's ticket; the edited surface (-1: Solve).
    quint64 m_ticket = 0;
    int m_editSurface = -1;
    QString m_editTitle;
    // A job of runJob() (its title is m_editTitle).
    bool m_job = false;
    // The held vertices that the edit's snapshot pinned and its result must release.
    std::map<model::VertexId, model::Vec3> m_heldTargets;
};

} // namespace devsurf::app
