#pragma once

#include "reaction.h"

#include <QString>

class QMenu;

namespace devsurf::app {

// File ▸ New from Example…: choose an example and its size.
class NewFromExampleReaction : public Reaction {
    Q_OBJECT
public:
    using Reaction::Reaction;

protected:
    void onTriggered() override;
};

class OpenReaction : public Reaction {
    Q_OBJECT
public:
    using Reaction::Reaction;

protected:
    void onTriggered() override;
};

// File ▸ Open Recent: keeps the submenu in step with the recent-files list.
class OpenRecentReaction : public QObject {
    Q_OBJECT
public:
    OpenRecentReaction(QMenu* menu, Workspace* workspace);

private:
    void rebuild();
    QMenu* m_menu;
    Workspace* m_workspace;
};

class SaveReaction : public Reaction {
    Q_OBJECT
public:
    using Reaction::Reaction;

protected:
    void onTriggered() override;
};

class SaveAsReaction : public Reaction {
    Q_OBJECT
public:
    using Reaction::Reaction;

protected:
    void onTriggered() override;
};

class ExportJsonReaction : public Reaction {
    Q_OBJECT
public:
    using Reaction::Reaction;

    // The file the interchange JSON goes to for a name the user chose: without an extension
    // .json is added; under another extension (.svg, .dxf, ...) the user is asked whether to
    // write NAME.json instead. Empty when the user cancels.
    static QString jsonPathFor(const QString& chosen, QWidget* window);

protected:
    void onTriggered() override;
};

} // namespace devsurf::app
