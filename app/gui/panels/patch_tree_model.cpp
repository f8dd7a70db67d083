#include "patch_tree_model.h"

#include "face_type_text.h"
#include "model/document/document.h"
#include "views/surface_view.h"

#include <QColor>

#include <algorithm>

namespace devsurf::app {

namespace {
// Internal ids: 0 for surface rows, surface index + 1 for patch rows.
constexpr quintptr kSurfaceRow = 0;
} // namespace

PatchTreeModel::PatchTreeModel(document::Document* document, QObject* parent)
    : QAbstractItemModel(parent), m_document(document) {
    rebuild();
    connect(document, &document::Document::changed, this, [this](document::Changes changes) {
        if (changes & (document::Change::Topology | document::Change::Labels)) {
            beginResetModel();
            rebuild();
            endResetModel();
        }
    });
}

void PatchTreeModel::rebuild() {
    m_faces.clear();
    for (const model::CompositeSurface& surface : m_document->project().surfaces) {
        std::vector<model::FaceId> faces;
        for (const auto& entry : surface.faces()) {
            faces.push_back(entry.first);
        }
        m_faces.push_back(std::move(faces));
    }
}

QModelIndex PatchTreeModel::index(int row, int column, const QModelIndex& parent) const {
    if (row < 0 || column < 0 || column >= columnCount()) {
        return {};
    }
    if (!parent.isValid()) {
        return row < static_cast<int>(m_faces.size()) ? createIndex(row, column, kSurfaceRow)
                                                      : QModelIndex();
    }
    if (parent.internalId() != kSurfaceRow) {
        return {};
    }
    const int surface = parent.row();
    if (row >= static_cast<int>(m_faces[static_cast<std::size_t>(surface)].size())) {
        return {};
    }
    return createIndex(row, column, static_cast<quintptr>(surface) + 1);
}

QModelIndex PatchTreeModel::parent(const QModelIndex& child) const {
    if (!child.isValid() || child.internalId() == kSurfaceRow) {
        return {};
    }
    return createIndex(static_cast<int>(child.internalId() - 1), 0, kSurfaceRow);
}

int PatchTreeModel::rowCount(const QModelIndex& parent) const {
    if (!parent.isValid()) {
        return static_cast<int>(m_faces.size());
    }
    if (parent.internalId() == kSurfaceRow && parent.column() == 0) {
        return static_cast<int>(m_faces[static_cast<std::size_t>(parent.row())].size());
    }
    return 0;
}

int PatchTreeModel::columnCount(const QModelIndex&) const {
    return 2;
}

std::pair<int, model::FaceId> PatchTreeModel::entityAt(const QModelIndex& index) const {
    if (!index.isValid()) {
        return {-1, model::kInvalidId};
    }
    if (index.internalId() == kSurfaceRow) {
        return {index.row(), model::kInvalidId};
    }
    const int surface = static_cast<int>(index.internalId() - 1);
    return {surface,
            m_faces[static_cast<std::size_t>(surface)][static_cast<std::size_t>(index.row())]};
}

QModelIndex PatchTreeModel::indexOfFace(int surface, model::FaceId face) const {
    if (surface < 0 || surface >= static_cast<int>(m_faces.size())) {
        return {};
    }
    const auto& faces = m_faces[static_cast<std::size_t>(surface)];
    const auto it = std::lower_bound(faces.begin(), faces.end(), face);
    if (it == faces.end() || *it != face) {
        return {};
    }
    return createIndex(static_cast<int>(it - faces.begin()), 0, static_cast<quintptr>(surface) + 1);
}

QModelIndex PatchTreeModel::indexOfSurface(int surface) const {
    return index(surface, 0);
}

QVariant PatchTreeModel::data(const QModelIndex& index, int role) const {
    const auto [surfaceIndex, face] = entityAt(index);
    if (surfaceIndex < 0 ||
        surfaceIndex >= static_cast<int>(m_document->project().surfaces.size())) {
        return {};
    }
    const model::CompositeSurface& surface =
        m_document->project().surfaces[static_cast<std::size_t>(surfaceIndex)];
    if (face == model::kInvalidId) {
        if (role == Qt::DisplayRole) {
            return index.column() == 0
                       ? QString::fromStdString(surface.name())
                       : tr("%n patch(es)", nullptr, static_cast<int>(surface.faces().size()));
        }
        return {};
    }
    if (!surface.hasFace(face)) {
        return {};
    }
    if (role == Qt::DisplayRole) {
        if (index.column() == 0) {
            return tr("Patch %1").arg(face);
        }
        const model::FaceType type = surface.faceType(face);
        if (type == model::FaceType::Invalid) {
            return tr("invalid labelling %1")
                .arg(QString::fromStdString(surface.labelString(face)));
        }
        return faceTypeText(type);
    }
    if (role == Qt::DecorationRole && index.column() == 0) {
        return views::SurfaceView::patchColor(face);
    }
    if (role == Qt::ToolTipRole) {
        return tr("Edge labels along the patch: %1")
            .arg(QString::fromStdString(surface.labelString(face)));
    }
    return {};
}

QVariant PatchTreeModel::headerData(int section, Qt::Orientation orientation, int role) const {
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole) {
        return {};
    }
    return section == 0 ? tr("Patch") : tr("Type");
}

} // namespace devsurf::app
