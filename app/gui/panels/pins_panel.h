#pragma once

#include "model/document/selection.h"

#include <QWidget>

class QAction;
class QLabel;
class QListWidget;
class QPushButton;

namespace devsurf::document {
class Document;
} // namespace devsurf::document

namespace devsurf::app {

// The dock "Pins": every pinned vertex (the solver never moves them). Selecting rows selects
// those vertices in the views, and the other way round; Unpin releases the selected ones
// through Tools ▸ Unpin Vertices (one undo step).
class PinsPanel : public QWidget {
    Q_OBJECT
public:
    PinsPanel(document::Document* document, document::Selection* selection,
              QWidget* parent = nullptr);

    // The action the Unpin button triggers (it acts on the selection, which follows the rows).
    void setUnpinAction(QAction* unpin);

    QListWidget* list() const { return m_list; }
    QPushButton* unpinButton() const { return m_unpin; }
    // The vertex a row lists.
    document::Pick pickAt(int row) const;

private:
    void refresh();
    void rowsSelected();
    void documentSelectionChanged();
    void updateUnpin();

    document::Document* m_document;
    document::Selection* m_selection;
    QLabel* m_hint;
    QListWidget* m_list;
    QPushButton* m_unpin;
    QAction* m_unpinAction = nullptr;
    bool m_syncing = false;
};

} // namespace devsurf::app
