#pragma once

#include <QMainWindow>

class QAction;
class QLabel;
class QSplitter;

namespace devsurf::views {
class SurfaceView;
class DevelopmentView;
} // namespace devsurf::views

namespace devsurf::app {

class Workspace;
class PatchPanel;
class PropertiesPanel;
class SolveController;
class SolverPanel;
class PinsPanel;
class DragTool;
class RotateTool;

// The main window builds menus, toolbar, docks and the status bar; what each action does lives
// in its reaction (reactions/).
class MainWindow : public QMainWindow {
    Q_OBJECT
public:
    explicit MainWindow(QWidget* parent = nullptr);
    ~MainWindow() override;

    Workspace* workspace() const { return m_workspace; }
    views::SurfaceView* surfaceView() const { return m_surfaceView; }
    views::DevelopmentView* developmentView() const { return m_developmentView; }
    PatchPanel* patchPanel() const { return m_patchPanel; }
    PropertiesPanel* propertiesPanel() const { return m_propertiesPanel; }
    PinsPanel* pinsPanel() const { return m_pinsPanel; }
    SolverPanel* solverPanel() const { return m_solverPanel; }
    SolveController* solveController() const { return m_solveController; }
    DragTool* dragTool() const { return m_dragTool; }
    // The action with the given object name (tests and the toolbar find actions by name).
    QAction* action(const QString& name) const;

protected:
    void closeEvent(QCloseEvent* event) override;
    void dragEnterEvent(QDragEnterEvent* event) override;
    void dropEvent(QDropEvent* event) override;

private:
    void createMenus();
    void createDocks();
    // Tools ▸ Solve, the Drag tool and the solve progress in the status bar
    // (main_window_solver.cpp). Returns the actions for the toolbar.
    QList<QAction*> createSolverActions(QMenu* tools, QAction* selectNone);
    // Tools ▸ Motion Axis (Free / X / Y / Z) for the Drag and Rotate tools; returns its actions.
    QList<QAction*> createAxisActions(QMenu* tools, RotateTool* rotateTool);
    // Tools ▸ Lengths While Dragging: Automatic, Keep Lengths, Let Stretch (remembered).
    void createLengthsActions(QMenu* tools);
    // View ▸ Colour By: patch, developability, flatness, angle defect.
    void createColourActions(QMenu* view);
    void updateTitle();
    void updateCounts();
    // View ▸ Reset Layout: docks, toolbar and both views as at the first start.
    void resetLayout();
    QAction* addAction(QMenu* menu, const QString& name, const QString& text,
                       const QKeySequence& shortcut = {});

    Workspace* m_workspace;
    QSplitter* m_splitter = nullptr;
    views::SurfaceView* m_surfaceView = nullptr;
    views::DevelopmentView* m_developmentView = nullptr;
    PatchPanel* m_patchPanel = nullptr;
    PropertiesPanel* m_propertiesPanel = nullptr;
    PinsPanel* m_pinsPanel = nullptr;
    SolverPanel* m_solverPanel = nullptr;
    SolveController* m_solveController = nullptr;
    DragTool* m_dragTool = nullptr;
    QLabel* m_countsLabel = nullptr;
    QLabel* m_hoverLabel = nullptr;
    QByteArray m_defaultLayout;
};

} // namespace devsurf::app
