#include "patch_panel.h"

#include "model/document/selection.h"
#include "patch_tree_model.h"

#include <QHeaderView>
#include <QItemSelectionModel>
#include <QScrollBar>
#include <QTreeView>
#include <QVBoxLayout>

#include <algorithm>

namespace devsurf::app {

PatchPanel::PatchPanel(document::Document* document, document::Selection* selection,
                       QWidget* parent)
    : QWidget(parent), m_selection(selection), m_model(new PatchTreeModel(document, this)),
      m_tree(new QTreeView(this)) {
    m_tree->setModel(m_model);
    m_tree->setSelectionMode(QAbstractItemView::ExtendedSelection);
    m_tree->setUniformRowHeights(true);
    m_tree->header()->setSectionResizeMode(QHeaderView::ResizeToContents);
    m_tree->header()->setStretchLastSection(false);
    m_tree->setTextElideMode(Qt::ElideNone);
    m_tree->expandAll();
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_tree);
    connect(m_model, &QAbstractItemModel::modelReset, this, [this] {
        m_tree->expandAll();
        documentSelectionChanged();
    });
    connect(m_tree->selectionModel(), &QItemSelectionModel::selectionChanged, this,
            &PatchPanel::treeSelectionChanged);
    connect(selection, &document::Selection::selectionChanged, this,
            &PatchPanel::documentSelectionChanged);
}

QSize PatchPanel::sizeHint() const {
    int width = 0;
    for (int column = 0; column < m_model->columnCount(); ++column) {
        width += std::max(static_cast<const QAbstractItemView*>(m_tree)->sizeHintForColumn(column),
                          m_tree->header()->sectionSizeHint(column));
    }
    width += m_tree->indentation() + 2 * m_tree->frameWidth() +
             m_tree->verticalScrollBar()->sizeHint().width();
    return {std::max(width, QWidget::sizeHint().width()), QWidget::sizeHint().height()};
}

void PatchPanel::treeSelectionChanged() {
    if (m_syncing) {
        return;
    }
    // Patches in the tree replace the face picks; vertex and edge picks stay.
    std::set<document::Pick> picks;
    for (const document::Pick& pick : m_selection->picks()) {
        if (pick.kind != document::Pick::Kind::Face) {
            picks.insert(pick);
        }
    }
    for (const QModelIndex& index : m_tree->selectionModel()->selectedRows()) {
        const auto [surface, face] = m_model->entityAt(index);
        if (face != model::kInvalidId) {
            picks.insert({document::Pick::Kind::Face, surface, face});
        }
    }
    m_syncing = true;
    m_selection->set(std::move(picks));
    m_syncing = false;
}

void PatchPanel::documentSelectionChanged() {
    if (m_syncing) {
        return;
    }
    QItemSelection rows;
    for (const document::Pick& pick : m_selection->picks()) {
        if (pick.kind == document::Pick::Kind::Face) {
            const QModelIndex index = m_model->indexOfFace(pick.surface, pick.id);
            if (index.isValid()) {
                rows.select(index, index.siblingAtColumn(1));
            }
        }
    }
    m_syncing = true;
    m_tree->selectionModel()->select(rows, QItemSelectionModel::ClearAndSelect);
    if (!rows.isEmpty()) {
        m_tree->scrollTo(rows.indexes().front());
    }
    m_syncing = false;
}

} // namespace devsurf::app
