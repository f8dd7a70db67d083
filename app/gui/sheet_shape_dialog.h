#pragma once

#include "model/composite_surface.h"
#include "model/sampled_mesh.h"
#include "model/sheet_domain.h"

#include <QDialog>

#include <functional>
#include <vector>

class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QPushButton;

namespace devsurf::app {

// Tools ▸ Sheet Shape…: the sheet a surface is folded from — free (its development held as it
// is) or a rectangle, disk, annulus or the outline of a drawing (the closed curves of a DXF,
// SVG, STEP or IGES file) its development is confined to. Sizes start at the sheet that just
// holds the development; the dialog compares the two areas as the sizes change. With a shape,
// the curves of a drawing can be drawn in the sheet for the creases near them to follow, or the
// creases held where they lie.
class SheetShapeDialog : public QDialog {
    Q_OBJECT
public:
    // `development` is `surface`'s development of `mesh` (kept, or as it unfolds now); the
    // dialog starts at the surface's sheet. `surface` must outlive the dialog.
    SheetShapeDialog(const model::CompositeSurface& surface, const model::SampledMesh& mesh,
                     std::vector<model::Vec2> development, QWidget* parent);

    // The chosen sheet, placed where it fits the development best (model::placeDomain), with
    // the drawn crease curves and the creases they hold (none for a free sheet).
    model::SheetDomain domain() const;

    QComboBox* shapeBox() const { return m_shape; }
    QDoubleSpinBox* widthBox() const { return m_width; }
    QDoubleSpinBox* heightBox() const { return m_height; }
    QDoubleSpinBox* radiusBox() const { return m_radius; }
    QDoubleSpinBox* innerRadiusBox() const { return m_innerRadius; }
    QLabel* fitLabel() const { return m_fit; }
    QPushButton* outlineButton() const { return m_chooseOutline; }
    QPushButton* okButton() const { return m_ok; }
    QPushButton* creasesButton() const { return m_chooseCreases; }
    QPushButton* clearCreasesButton() const { return m_clearCreases; }
    QPushButton* keepCreasesButton() const { return m_keepCreases; }
    QLabel* creasesLabel() const { return m_creasesName; }

    // Reads the outline from a drawing's closed curves; false (said in the dialog, the outline
    // kept as it was) if the file cannot be read or holds no closed curve enclosing an area.
    bool loadOutline(const QString& path);
    // What "Choose…" asks for the drawing with (default: a file dialog); for tests.
    void setOutlineChooser(std::function<QString()> chooser) { m_chooser = std::move(chooser); }
    // Reads the crease curves from every curve of a drawing; false (said in the dialog, the
    // curves kept as they were) if the file cannot be read or holds no curve.
    bool loadCreaseCurves(const QString& path);
    void setCreasesChooser(std::function<QString()> chooser) {
        m_creasesChooser = std::move(chooser);
    }

private:
    void onShapeChanged();
    void updateFit();
    model::SheetDomain unplaced() const;
    // `placed` with the drawn crease curves in its frame and the creases they hold.
    model::SheetDomain withCreases(model::SheetDomain placed) const;
    void updateCreases();

    const model::CompositeSurface& m_surface;
    const model::SampledMesh& m_mesh;
    std::vector<model::Vec2> m_development;
    double m_developedArea = 0.0;
    QComboBox* m_shape;
    QDoubleSpinBox* m_width;
    QDoubleSpinBox* m_height;
    QDoubleSpinBox* m_radius;
    QDoubleSpinBox* m_innerRadius;
    QLabel* m_fit;
    std::vector<std::vector<model::Vec2>> m_outline; // loops in the drawing's frame, mm
    QLabel* m_outlineName;
    QPushButton* m_chooseOutline;
    QPushButton* m_ok = nullptr;
    QString m_outlineProblem;
    std::function<QString()> m_chooser;
    // The crease curves as drawn (a rectangle's from its corner at 0,0; see withCreases).
    std::vector<model::SheetDomain::Curve> m_creaseDrawing;
    QString m_creaseFile;
    QString m_creasesProblem;
    QLabel* m_creasesName;
    QPushButton* m_chooseCreases;
    QPushButton* m_clearCreases;
    // "As They Lie": the creases held on the curves they lie on now (model::
    // creaseCurvesAsTheyLie, in the development's plane), instead of a drawing's.
    QPushButton* m_keepCreases;
    bool m_creasesAsTheyLie = false;
    std::vector<model::SheetDomain::Curve> m_lyingCreases;
    std::function<QString()> m_creasesChooser;
};

} // namespace devsurf::app
