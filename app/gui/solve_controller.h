#pragma once

#include "panels/solver_panel.h"

#include <QObject>
#include <QString>

namespace devsurf::solver {
class SolverWorker;
struct SolveResult;
} // namespace devsurf::solver

namespace devsurf::app {

class Workspace;

// Tools ▸ Solve and what it shares with the Drag tool: the background solver worker. A solve
// takes a snapshot of every surface and runs the worker (iterations from the setting
// "solver/iterations", default 10); the result becomes one undo step ("Solve") if the design
// did not change meanwhile. Any edit while solving cancels the solve; a cancelled or failed
// solve changes nothing and says why.
class SolveController : public QObject {
    Q_OBJECT
public:
    explicit SolveController(Workspace* workspace, QObject* parent = nullptr);
    ~SolveController() override;

    solver::SolverWorker* worker() const { return m_worker; }
    bool isSolving() const { return m_solving; }
    static int iterationsSetting();
    // Builds a report of a result for the Solver panel (worst patches when the tolerance was
    // not reached).
    SolveReport reportOf(const solver::SolveResult& result, const QString& title) const;

public slots:
    void solve();
    // Stops a running solve; the design stays as it is. reason completes "Solve cancelled: …".
    void cancel(const QString& reason = QString());

signals:
    void busyChanged(bool solving);
    void progress(int iteration, int iterations, double residual);
    // A solve ended (applied, cancelled, failed or discarded): the sentence says which.
    void finished(const QString& sentence);
    void reportReady(const devsurf::app::SolveReport& report);

private:
    void onResult(const solver::SolveResult& result);
    void onDocumentChanged();
    void stop(const QString& sentence);

    Workspace* m_workspace;
    solver::SolverWorker* m_worker;
    bool m_solving = false;
    bool m_applying = false;
    quint64 m_revision = 0;
};

} // namespace devsurf::app
