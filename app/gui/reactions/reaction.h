#pragma once

#include <QObject>

class QAction;

namespace devsurf::app {

class Workspace;

// One small handler per action: it owns the behaviour of one QAction (what happens when it is
// triggered, when it is enabled) so that the main window only builds menus.
class Reaction : public QObject {
    Q_OBJECT
public:
    Reaction(QAction* action, Workspace* workspace);

    QAction* action() const { return m_action; }
    Workspace* workspace() const { return m_workspace; }

protected:
    virtual void onTriggered() = 0;
    // Called whenever the document or the selection changed.
    virtual void updateEnableState() {}
    // Reactions whose enabled state depends on document or selection call this once.
    void followDocumentAndSelection();

private:
    QAction* m_action;
    Workspace* m_workspace;
};

} // namespace devsurf::app
