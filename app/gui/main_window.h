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
    // The action with the given object name (tests and the toolbar find actions by name).
    QAction* action(const QString& name) const;

protected:
    void closeEvent(QCloseEvent* event) override;
    void dragEnterEvent(QDragEnterEvent* event) override;
    void dropEvent(QDropEvent* event) override;

private:
    void createMenus();
    void createDocks();
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
    QLabel* m_countsLabel = nullptr;
    QLabel* m_hoverLabel = nullptr;
    QByteArray m_defaultLayout;
};

} // namespace devsurf::app
