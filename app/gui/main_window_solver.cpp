// The main window's live-solving parts: Tools ▸ Solve, the Drag tool, the solve progress in
// the status bar, the Solver panel's updates, and View ▸ Colour By.

#include "camera_actions.h"
#include "drag_tool.h"
#include "main_window.h"
#include "panels/solver_panel.h"
#include "solve_controller.h"
#include "views/surface_view.h"

#include <QAction>
#include <QActionGroup>
#include <QInputDialog>
#include <QMenu>
#include <QProgressBar>
#include <QSettings>
#include <QStatusBar>
#include <QToolButton>

namespace devsurf::app {

QList<QAction*> MainWindow::createSolverActions(QMenu* tools, QAction* selectNone) {
    QAction* solve = addAction(tools, QStringLiteral("actionSolve"), tr("&Solve"),
                               QKeySequence(tr("Ctrl+Return")));
    solve->setIcon(actionIcon(QStringLiteral("solve")));
    auto explainSolve = [solve] {
        const QString tip = tr("Make every surface developable again: %n iteration(s) of the "
                               "solver, one undo step. Pinned vertices stay where they are.",
                               nullptr, SolveController::iterationsSetting());
        solve->setToolTip(tip);
        solve->setStatusTip(tip);
    };
    explainSolve();
    QAction* iterations =
        addAction(tools, QStringLiteral("actionSolverIterations"), tr("Solver &Iterations…"));
    iterations->setToolTip(tr("How many solver iterations Tools ▸ Solve runs."));
    connect(iterations, &QAction::triggered, this, [this, explainSolve] {
        bool ok = false;
        const int value =
            QInputDialog::getInt(this, tr("Solver Iterations"), tr("Iterations of Tools ▸ Solve:"),
                                 SolveController::iterationsSetting(), 1, 1000, 1, &ok);
        if (ok) {
            QSettings().setValue(QStringLiteral("solver/iterations"), value);
            explainSolve();
        }
    });
    connect(solve, &QAction::triggered, this, [this] {
        if (m_dragTool->isDragging()) {
            statusBar()->showMessage(tr("Finish the drag first; it solves as it goes."), 5000);
            return;
        }
        m_solveController->solve();
    });

    QAction* drag = addAction(tools, QStringLiteral("actionDragTool"), tr("&Drag Vertices"),
                              QKeySequence(tr("G")));
    drag->setIcon(actionIcon(QStringLiteral("drag")));
    const QString dragTip =
        tr("Drag tool: press on a vertex in the 3D view and move it, the surface follows and "
           "stays developable. Hold X, Y or Z to move along that axis; Esc cancels the drag.");
    drag->setToolTip(dragTip);
    drag->setStatusTip(dragTip);
    m_dragTool = new DragTool(drag, m_workspace, m_surfaceView, m_solveController);
    connect(m_dragTool, &DragTool::reportReady, m_solverPanel, &SolverPanel::showReport);
    connect(m_dragTool, &DragTool::statusMessage, this,
            [this](const QString& text) { statusBar()->showMessage(text, 8000); });

    // Progress of a solve, with its Cancel (Esc); Esc selects nothing when no solve runs.
    QAction* cancel = addAction(tools, QStringLiteral("actionCancelSolve"), tr("&Cancel Solve"),
                                QKeySequence(tr("Esc")));
    cancel->setEnabled(false);
    cancel->setToolTip(tr("Stop the running solve; the design stays as it is (Esc)."));
    connect(cancel, &QAction::triggered, m_solveController,
            [this] { m_solveController->cancel(); });
    auto* progress = new QProgressBar(this);
    progress->setObjectName(QStringLiteral("solveProgress"));
    progress->setMaximumWidth(160);
    progress->hide();
    auto* cancelButton = new QToolButton(this);
    cancelButton->setDefaultAction(cancel);
    cancelButton->hide();
    statusBar()->addPermanentWidget(progress);
    statusBar()->addPermanentWidget(cancelButton);
    connect(m_solveController, &SolveController::busyChanged, this,
            [progress, cancelButton, cancel, selectNone](bool solving) {
                progress->setVisible(solving);
                progress->setRange(0, 0); // busy until the first iteration reports
                cancelButton->setVisible(solving);
                cancel->setEnabled(solving);
                selectNone->setEnabled(!solving);
            });
    connect(m_solveController, &SolveController::progress, this,
            [this, progress](int iteration, int iterations, double residual) {
                progress->setRange(0, iterations);
                progress->setValue(iteration);
                statusBar()->showMessage(tr("Solving: iteration %1 of %2, residual %3")
                                             .arg(iteration)
                                             .arg(iterations)
                                             .arg(QString::number(residual, 'e', 2)));
            });
    connect(m_solveController, &SolveController::finished, this,
            [this](const QString& text) { statusBar()->showMessage(text, 8000); });
    return {solve, drag};
}

void MainWindow::createColourActions(QMenu* view) {
    QMenu* menu = view->addMenu(tr("Colour &By"));
    menu->setObjectName(QStringLiteral("menuColourBy"));
    auto* group = new QActionGroup(this);
    const std::pair<const char*, views::ColourBy> entries[] = {
        {"actionColourPatch", views::ColourBy::Patch},
        {"actionColourDevelopability", views::ColourBy::Developability},
        {"actionColourFlatness", views::ColourBy::Flatness},
        {"actionColourAngleDefect", views::ColourBy::AngleDefect}};
    const QString texts[] = {tr("&Patch"), tr("&Developability"), tr("&Flatness"),
                             tr("&Angle Defect")};
    const QString tips[] = {
        tr("Every patch in its own colour."),
        tr("How far every sampled strip quad is from developable: the normalised "
           "|det(a−b, a′, b′)|, on a logarithmic scale."),
        tr("Flatness δ of every sampled quad: the distance of its diagonals over the mean of "
           "its two shortest edges, on a logarithmic scale."),
        tr("Angle defect |K| = |2π − Σ angles| at the interior vertices of the sampled mesh, in "
           "radians, on a logarithmic scale.")};
    for (std::size_t i = 0; i < std::size(entries); ++i) {
        QAction* action = menu->addAction(texts[i]);
        action->setObjectName(QString::fromLatin1(entries[i].first));
        action->setCheckable(true);
        action->setChecked(entries[i].second == views::ColourBy::Patch);
        action->setToolTip(tips[i]);
        action->setStatusTip(tips[i]);
        group->addAction(action);
        const views::ColourBy by = entries[i].second;
        connect(action, &QAction::triggered, m_surfaceView,
                [this, by] { m_surfaceView->setColourBy(by); });
    }
}

} // namespace devsurf::app
