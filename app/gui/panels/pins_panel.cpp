#include "pins_panel.h"

#include "model/document/document.h"

#include <QAction>
#include <QLabel>
#include <QListWidget>
#include <QPushButton>
#include <QVBoxLayout>

namespace devsurf::app {

namespace {

constexpr int kSurfaceRole = Qt::UserRole;
constexpr int kVertexRole = Qt::UserRole + 1;

} // namespace

PinsPanel::PinsPanel(document::Document* document, document::Selection* selection, QWidget* parent)
    : QWidget(parent), m_document(document), m_selection(selection), m_hint(new QLabel(this)),
      m_list(new QListWidget(this)), m_unpin(new QPushButton(tr("Unpin"), this)) {
    setObjectName(QStringLiteral("PinsPanel"));
    m_hint->setWordWrap(true);
    m_hint->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Preferred); // wraps, never widens
    m_hint->setText(tr("No vertex is pinned. Select vertices and choose Tools ▸ Pin Vertices "
                       "(Ctrl+K): the solver then never moves them."));
    m_list->setSelectionMode(QAbstractItemView::ExtendedSelection);
    m_list->setToolTip(tr("The pinned vertices: the solver never moves them. Selecting a row "
                          "selects its vertex in the views."));
    m_unpin->setObjectName(QStringLiteral("UnpinSelectedPins"));
    m_unpin->setToolTip(tr("Release the selected pinned vertices (one undo step)."));
    m_unpin->setEnabled(false);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(m_hint);
    layout->addWidget(m_list, 1);
    layout->addWidget(m_unpin);
    connect(m_list, &QListWidget::itemSelectionChanged, this, &PinsPanel::rowsSelected);
    connect(document, &document::Document::changed, this, &PinsPanel::refresh);
    connect(selection, &document::Selection::selectionChanged, this,
            &PinsPanel::documentSelectionChanged);
    refresh();
}

void PinsPanel::setUnpinAction(QAction* unpin) {
    m_unpinAction = unpin;
    connect(unpin, &QAction::changed, this, &PinsPanel::updateUnpin);
    connect(m_unpin, &QPushButton::clicked, unpin, &QAction::trigger);
    updateUnpin();
}

document::Pick PinsPanel::pickAt(int row) const {
    const QListWidgetItem* item = m_list->item(row);
    return {document::Pick::Kind::Vertex, item->data(kSurfaceRole).toInt(),
            static_cast<model::VertexId>(item->data(kVertexRole).toUInt())};
}

void PinsPanel::refresh() {
    m_syncing = true;
    m_list->clear();
    const auto& surfaces = m_document->project().surfaces;
    for (std::size_t s = 0; s < surfaces.size(); ++s) {
        for (model::VertexId v : surfaces[s].pinnedVertices()) {
            // With one surface the vertex number says it all.
            const QString text = surfaces.size() == 1
                                     ? tr("Vertex %1").arg(v)
                                     : tr("Surface %1, vertex %2").arg(s + 1).arg(v);
            auto* item = new QListWidgetItem(text, m_list);
            item->setData(kSurfaceRole, static_cast<int>(s));
            item->setData(kVertexRole, static_cast<uint>(v));
        }
    }
    m_hint->setVisible(m_list->count() == 0);
    m_syncing = false;
    documentSelectionChanged();
}

void PinsPanel::rowsSelected() {
    if (m_syncing) {
        return;
    }
    std::set<document::Pick> picks;
    for (int row = 0; row < m_list->count(); ++row) {
        if (m_list->item(row)->isSelected()) {
            picks.insert(pickAt(row));
        }
    }
    if (!picks.empty()) { // rows deselected leave the selection to the views
        m_syncing = true;
        m_selection->set(std::move(picks));
        m_syncing = false;
    }
    updateUnpin();
}

void PinsPanel::documentSelectionChanged() {
    if (m_syncing) {
        return;
    }
    m_syncing = true;
    for (int row = 0; row < m_list->count(); ++row) {
        m_list->item(row)->setSelected(m_selection->contains(pickAt(row)));
    }
    m_syncing = false;
    updateUnpin();
}

void PinsPanel::updateUnpin() {
    m_unpin->setEnabled(m_unpinAction != nullptr && m_unpinAction->isEnabled() &&
                        !m_list->selectedItems().isEmpty());
}

} // namespace devsurf::app
