#pragma once

#include "reaction.h"

#include <QString>

#include <memory>

namespace devsurf::solver {
struct SolveResult;
} // namespace devsurf::solver

namespace devsurf::app {

class BackgroundRead;
class SolveController;

// Tools ▸ Join Surfaces (Ctrl+J): the surfaces with something selected (all of them when fewer
// than two have) joined into one composite (§4.2, "Composite") by the solve job's Join
// (solver/session/join_job.h): boundary curves that face each other are paired, welded into
// shared curves and the result solved. With reference shapes in the design, the pairing also
// pulls towards them (thinned first, behind a progress dialog that can cancel). Runs on the
// solver worker with progress and Cancel as a solve; one undo step; nothing facing, a cancel
// or an edit meanwhile leaves the design unchanged and says so.
class JoinReaction : public Reaction {
    Q_OBJECT
public:
    JoinReaction(QAction* action, Workspace* workspace, SolveController* solve);
    ~JoinReaction() override;

    bool isBusy() const { return m_run != nullptr; }

signals:
    // The join ended: applied (one undo step) or not; `sentence` says how.
    void finished(bool applied, const QString& sentence);

protected:
    void onTriggered() override;
    void updateEnableState() override;

private:
    struct Run;
    void onThinned();
    void runJob();
    void onJobDone(const solver::SolveResult& result);
    void onControllerFinished(const QString& sentence);
    void end(bool applied, const QString& sentence);

    SolveController* m_solve;
    std::shared_ptr<Run> m_run;
    BackgroundRead* m_thinning = nullptr;
};

} // namespace devsurf::app
