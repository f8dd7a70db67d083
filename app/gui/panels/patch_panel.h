#pragma once

#include <QWidget>

class QTreeView;

namespace devsurf::document {
class Document;
class Selection;
} // namespace devsurf::document

namespace devsurf::app {

class PatchTreeModel;

// The tree of surfaces and patches; its selection and the views' selection follow each other.
class PatchPanel : public QWidget {
    Q_OBJECT
public:
    PatchPanel(document::Document* document, document::Selection* selection,
               QWidget* parent = nullptr);

    QTreeView* treeView() const { return m_tree; }
    PatchTreeModel* model() const { return m_model; }

private:
    void treeSelectionChanged();
    void documentSelectionChanged();

    document::Selection* m_selection;
    PatchTreeModel* m_model;
    QTreeView* m_tree;
    bool m_syncing = false;
};

} // namespace devsurf::app
