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
    // Wide enough for every column's full text (the dock starts at this width), so that no
    // language's patch names or types are cut off.
    QSize sizeHint() const override;

private:
    void treeSelectionChanged();
    void documentSelectionChanged();

    document::Selection* m_selection;
    PatchTreeModel* m_model;
    QTreeView* m_tree;
    bool m_syncing = false;
};

} // namespace devsurf::app
