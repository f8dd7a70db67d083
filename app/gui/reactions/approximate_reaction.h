#pragma once

#include "../approximate_dialog.h"
#include "reaction.h"

#include <QString>

#include <functional>
#include <memory>

class QThread;

namespace devsurf::solver {
struct SolveResult;
} // namespace devsurf::solver

namespace devsurf::app {

class BackgroundRead;
class SolveController;

// Tools ▸ Approximate Reference Shape…: developable strips fitted to a reference shape (§4.2),
// as `devsurf-cli approximate` fits them (solver/session/approximation_setup.h). Three steps,
// none on the GUI thread: the setup (thinning, k-means strips, points per surface) behind a
// progress dialog that can cancel; the Approximate job on the solver worker, with the status
// bar's progress and Cancel as a solve; the distance of the result to the shape. The result is
// one undo step (new strips added, or the design's surfaces moved); a cancel, or an edit
// meanwhile, leaves the design unchanged; a failure is one sentence. Disabled, with a tooltip
// that says why, without a reference shape or while the solver is busy.
class ApproximateReaction : public Reaction {
    Q_OBJECT
public:
    ApproximateReaction(QAction* action, Workspace* workspace, SolveController* solve);
    ~ApproximateReaction() override;

    // Runs an approximation as the dialog's choice asks; finished() follows.
    void start(const ApproximationChoice& choice);
    // Preparing, solving or measuring (also a measurement whose approximation was cancelled).
    bool isBusy() const;
    // How long the steps of the last applied approximation took (ms).
    struct Timings {
        double setup = 0.0;
        double solve = 0.0;
        double measure = 0.0;
    };
    Timings lastTimings() const { return m_timings; }

signals:
    // The approximation ended: applied (one undo step) or not; `sentence` says how.
    void finished(bool applied, const QString& sentence);

protected:
    void onTriggered() override;
    void updateEnableState() override;

private:
    struct Run;
    void onPrepared();
    void onJobDone(const solver::SolveResult& result);
    void onMeasured();
    void onControllerFinished(const QString& sentence);
    void end(bool applied, const QString& sentence);

    SolveController* m_solve;
    std::shared_ptr<Run> m_run;
    BackgroundRead* m_setup = nullptr;
    QThread* m_measure = nullptr;
    Timings m_timings;
};

} // namespace devsurf::app
