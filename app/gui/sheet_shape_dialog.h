#pragma once

#include "model/sampled_mesh.h"
#include "model/sheet_domain.h"

#include <QDialog>

#include <vector>

class QComboBox;
class QDoubleSpinBox;
class QLabel;

namespace devsurf::app {

// Tools ▸ Sheet Shape…: the sheet a surface is folded from — free (its development held as it
// is) or a rectangle, disk or annulus its development is confined to. Sizes start at the sheet
// that just holds the development; the dialog compares the two areas as the sizes change.
class SheetShapeDialog : public QDialog {
    Q_OBJECT
public:
    // `development` is the surface's development of `mesh` (kept, or as it unfolds now).
    SheetShapeDialog(const model::SheetDomain& current, const model::SampledMesh& mesh,
                     std::vector<model::Vec2> development, QWidget* parent);

    // The chosen sheet, placed where it fits the development best (model::placeDomain).
    model::SheetDomain domain() const;

    QComboBox* shapeBox() const { return m_shape; }
    QDoubleSpinBox* widthBox() const { return m_width; }
    QDoubleSpinBox* heightBox() const { return m_height; }
    QDoubleSpinBox* radiusBox() const { return m_radius; }
    QDoubleSpinBox* innerRadiusBox() const { return m_innerRadius; }
    QLabel* fitLabel() const { return m_fit; }

private:
    void onShapeChanged();
    void updateFit();
    model::SheetDomain unplaced() const;

    const model::SampledMesh& m_mesh;
    std::vector<model::Vec2> m_development;
    double m_developedArea = 0.0;
    QComboBox* m_shape;
    QDoubleSpinBox* m_width;
    QDoubleSpinBox* m_height;
    QDoubleSpinBox* m_radius;
    QDoubleSpinBox* m_innerRadius;
    QLabel* m_fit;
};

} // namespace devsurf::app
