// The main window's live-solving parts: Tools ▸ Solve, the Drag and Rotate tools with their
// axis choice, the Measure tool, the solve progress in the status bar, the Solver panel's
// updates, and View ▸ Colour By.

#include "camera_actions.h"
#include "drag_tool.h"
#include "main_window.h"
#include "measure_tool.h"
#include "panels/solver_panel.h"
#include "reactions/curve_reactions.h"
#include "rotate_tool.h"
#include "solve_controller.h"
#include "views/development_view.h"
#include "views/surface_view.h"

#include <QAction>
#include <QActionGroup>
#include <QInputDialog>
#include <QMenu>
#include <QProgressBar>
#include <QSettings>
#include <QStatusBar>
#include <QToolButton>

#include <algorithm>

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
    iterations->setToolTip(
        tr("The most solver iterations Tools ▸ Solve runs; it stops earlier once the "
           "surface has converged."));
    connect(iterations, &QAction::triggered, this, [this, explainSolve] {
        bool ok = false;
        const int value = QInputDialog::getInt(
            this, tr("Solver Iterations"), tr("Most iterations of Tools ▸ Solve:"),
            SolveController::iterationsSetting(), 1, 1000, 1, &ok);
        if (ok) {
            QSettings().setValue(QStringLiteral("solver/iterations"), value);
            explainSolve();
        }
    });

    QAction* drag = addAction(tools, QStringLiteral("actionDragTool"),
                              tr("&Drag Vertices and Creases"), QKeySequence(tr("G")));
    drag->setIcon(actionIcon(QStringLiteral("drag")));
    const QString dragTip =
        tr("Drag tool: press on a vertex in the 3D view and move it, the surface follows and "
           "stays developable; press on a crease to slide it within its patches. The axis "
           "chosen in the toolbar, or holding X, Y or Z, moves along that axis; Esc cancels the "
           "drag (G).");
    drag->setToolTip(dragTip);
    drag->setStatusTip(dragTip);
    m_dragTool = new DragTool(drag, m_workspace, m_surfaceView, m_solveController);
    m_dragTool->setSheetView(m_developmentView);
    QAction* snap =
        addAction(tools, QStringLiteral("actionSnapToCurves"), tr("S&nap to Reference Curves"));
    snap->setCheckable(true);
    const QString snapTip = tr("While dragging a vertex (no axis chosen), put it on the nearest "
                               "reference curve drawn within 10 pixels of the mouse.");
    snap->setToolTip(snapTip);
    snap->setStatusTip(snapTip);
    connect(snap, &QAction::toggled, m_dragTool, &DragTool::setSnapToCurves);
    new FitEdgeToCurveReaction(addAction(tools, QStringLiteral("actionFitEdgeToCurve"),
                                         tr("&Fit Edge to Reference Curve")),
                               m_workspace);
    createLengthsActions(tools);

    QAction* rotate = addAction(tools, QStringLiteral("actionRotateTool"), tr("R&otate Vertices"),
                                QKeySequence(tr("R")));
    rotate->setIcon(actionIcon(QStringLiteral("rotate")));
    const QString rotateTip =
        tr("Rotate tool (R): select two or more vertices, press on a vertex in the 3D view and "
           "move the mouse sideways; they turn about an axis through their centroid (vertical, "
           "or as chosen in the toolbar) and the surface follows. Esc cancels.");
    rotate->setToolTip(rotateTip);
    rotate->setStatusTip(rotateTip);
    auto* rotateTool = new RotateTool(rotate, m_workspace, m_surfaceView, m_solveController);

    QAction* measure = addAction(tools, QStringLiteral("actionMeasureTool"), tr("Measur&e"));
    const QString measureTip =
        tr("Measure tool: click two points of the surface in the 3D view; their distance in "
           "space and along the sheet (as the cut pattern has it) is drawn and shown in the "
           "status bar. Select an edge for its length, two edges that meet for their angle.");
    measure->setToolTip(measureTip);
    measure->setStatusTip(measureTip);
    QAction* copyMeasurement = addAction(tools, QStringLiteral("actionCopyMeasurement"),
                                         tr("Cop&y Measurement"), QKeySequence(tr("Ctrl+C")));
    copyMeasurement->setToolTip(tr("Copy the last measurement to the clipboard (Ctrl+C)."));
    auto* measureTool = new MeasureTool(measure, copyMeasurement, m_workspace, m_surfaceView);
    connect(measureTool, &MeasureTool::statusMessage, this,
            [this](const QString& text) { statusBar()->showMessage(text); });
    // One tool at a time, or none (the plain view).
    auto* toolGroup = new QActionGroup(this);
    toolGroup->setExclusionPolicy(QActionGroup::ExclusionPolicy::ExclusiveOptional);
    toolGroup->addAction(drag);
    toolGroup->addAction(rotate);
    toolGroup->addAction(measure);
    for (DragTool* tool : {m_dragTool, static_cast<DragTool*>(rotateTool)}) {
        connect(tool, &DragTool::reportReady, m_solverPanel, &SolverPanel::showReport);
        connect(tool, &DragTool::statusMessage, this,
                [this](const QString& text) { statusBar()->showMessage(text, 8000); });
    }
    connect(solve, &QAction::triggered, this, [this, rotateTool] {
        if (m_dragTool->isDragging() || rotateTool->isDragging()) {
            statusBar()->showMessage(tr("Finish the drag first; it solves as it goes."), 5000);
            return;
        }
        m_solveController->solve();
    });
    const QList<QAction*> axisActions = createAxisActions(tools, rotateTool);

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
    auto* separator = new QAction(this);
    separator->setSeparator(true);
    return QList<QAction*>{solve, drag, rotate, separator} + axisActions;
}

void MainWindow::createLengthsActions(QMenu* tools) {
    QMenu* menu = tools->addMenu(tr("&Lengths While Dragging"));
    menu->setObjectName(QStringLiteral("menuLengthsWhileDragging"));
    menu->setToolTipsVisible(true);
    auto* group = new QActionGroup(this);
    using Mode = SolveController::LengthsMode;
    struct Entry {
        const char* name;
        Mode mode;
        QString text;
        QString tip;
    };
    const Entry entries[] = {
        {"actionLengthsAutomatic", Mode::Automatic, tr("&Automatic"),
         tr("Vertex drags and rotations keep lengths. Where the sheet cannot follow that way "
            "(the drag does not converge, folds over, collapses a strip or its development "
            "overlaps itself), the drag is replayed on release letting the sheet stretch, and "
            "the better of the two is kept; the Solver panel says so.")},
        {"actionKeepLengths", Mode::Keep, tr("&Keep Lengths"),
         tr("While dragging or rotating vertices, the sheet bends instead of stretching: far "
            "parts stay in place and curved creases keep their shape and fold. A motion the "
            "sheet cannot make without stretching then may not converge. Dragged creases "
            "always resize their patches.")},
        {"actionLetStretch", Mode::Stretch, tr("Let &Stretch"),
         tr("While dragging or rotating vertices, the sheet may stretch: it stays developable "
            "and its development changes, curved creases may be pulled straight and large drags "
            "may crumple it.")}};
    const Mode saved = SolveController::lengthsSetting();
    for (const Entry& entry : entries) {
        QAction* action = menu->addAction(entry.text);
        action->setObjectName(QString::fromLatin1(entry.name));
        action->setCheckable(true);
        action->setToolTip(entry.tip);
        action->setStatusTip(entry.tip);
        group->addAction(action);
        action->setChecked(entry.mode == saved);
        const Mode mode = entry.mode;
        connect(action, &QAction::toggled, this, [mode](bool on) {
            if (on) {
                SolveController::setLengthsSetting(mode);
            }
        });
    }
}

QList<QAction*> MainWindow::createAxisActions(QMenu* tools, RotateTool* rotateTool) {
    QMenu* menu = tools->addMenu(tr("Motion &Axis"));
    menu->setObjectName(QStringLiteral("menuMotionAxis"));
    menu->setToolTipsVisible(true);
    auto* group = new QActionGroup(this);
    struct Entry {
        const char* name;
        DragTool::Axis axis;
        QString text;
        const char* icon;
        QString tip;
    };
    const Entry entries[] = {
        {"actionAxisFree", DragTool::Axis::Free, tr("&Free"), "axis-free",
         tr("Free motion: the Drag tool moves vertices in the view plane; the Rotate tool turns "
            "them about the vertical axis (Z), or about the view axis if Tools ▸ Motion Axis ▸ "
            "Rotate About the View Axis is on.")},
        {"actionAxisX", DragTool::Axis::X, tr("&X Axis"), "axis-x",
         tr("X axis: the Drag tool moves vertices along X only; the Rotate tool turns them "
            "about an X-parallel axis through their centroid. Holding Y or Z overrides.")},
        {"actionAxisY", DragTool::Axis::Y, tr("&Y Axis"), "axis-y",
         tr("Y axis: the Drag tool moves vertices along Y only; the Rotate tool turns them "
            "about a Y-parallel axis through their centroid. Holding X or Z overrides.")},
        {"actionAxisZ", DragTool::Axis::Z, tr("&Z Axis"), "axis-z",
         tr("Z axis: the Drag tool moves vertices along Z only; the Rotate tool turns them "
            "about a Z-parallel axis through their centroid. Holding X or Y overrides.")}};
    const int saved = std::clamp(QSettings().value(QStringLiteral("tools/axis"), 0).toInt(), 0, 3);
    QList<QAction*> actions;
    for (const Entry& entry : entries) {
        QAction* action = menu->addAction(entry.text);
        action->setObjectName(QString::fromLatin1(entry.name));
        action->setIcon(actionIcon(QString::fromLatin1(entry.icon)));
        action->setCheckable(true);
        action->setToolTip(entry.tip);
        action->setStatusTip(entry.tip);
        group->addAction(action);
        actions << action;
        const DragTool::Axis axis = entry.axis;
        connect(action, &QAction::toggled, this, [this, rotateTool, axis](bool on) {
            if (on) {
                m_dragTool->setChosenAxis(axis);
                rotateTool->setChosenAxis(axis);
                QSettings().setValue(QStringLiteral("tools/axis"), static_cast<int>(axis));
            }
        });
    }
    actions[saved]->setChecked(true);
    menu->addSeparator();
    QAction* viewAxis = menu->addAction(tr("Rotate About the &View Axis"));
    viewAxis->setObjectName(QStringLiteral("actionRotateViewAxis"));
    viewAxis->setCheckable(true);
    const QString viewTip = tr("With the axis choice Free, the Rotate tool turns the vertices "
                               "about the viewing direction through their centroid instead of "
                               "the vertical axis.");
    viewAxis->setToolTip(viewTip);
    viewAxis->setStatusTip(viewTip);
    connect(viewAxis, &QAction::toggled, this, [rotateTool](bool on) {
        rotateTool->setAboutViewAxis(on);
        QSettings().setValue(QStringLiteral("tools/rotateViewAxis"), on);
    });
    viewAxis->setChecked(QSettings().value(QStringLiteral("tools/rotateViewAxis"), false).toBool());
    return actions;
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
