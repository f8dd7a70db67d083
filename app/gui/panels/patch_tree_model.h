#pragma once

#include "model/ids.h"

#include <QAbstractItemModel>

#include <vector>

namespace devsurf::document {
class Document;
}

namespace devsurf::app {

// The tree of surfaces and their patches (faces) for the patch panel. Rows of the second level
// are faces in id order; the decoration is the patch colour of the 3D view.
class PatchTreeModel : public QAbstractItemModel {
    Q_OBJECT
public:
    explicit PatchTreeModel(document::Document* document, QObject* parent = nullptr);

    QModelIndex index(int row, int column, const QModelIndex& parent = {}) const override;
    QModelIndex parent(const QModelIndex& child) const override;
    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role) const override;
    QVariant headerData(int section, Qt::Orientation orientation, int role) const override;

    // Surface index and face id of a patch row; face kInvalidId for a surface row.
    std::pair<int, model::FaceId> entityAt(const QModelIndex& index) const;
    QModelIndex indexOfFace(int surface, model::FaceId face) const;
    QModelIndex indexOfSurface(int surface) const;

private:
    void rebuild();

    document::Document* m_document;
    std::vector<std::vector<model::FaceId>> m_faces; // per surface, in id order
};

} // namespace devsurf::app
