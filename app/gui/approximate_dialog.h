#pragma once

#include "model/project.h"

#include <QDialog>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QRadioButton;
class QSpinBox;

namespace devsurf::app {

// What Tools ▸ Approximate Reference Shape… is asked to do.
struct ApproximationChoice {
    int shape = 0;          // index into the project's reference shapes
    bool newStrips = true;  // K new flat strips, or the design's surfaces
    int strips = 4;         // K
    bool oneSurface = true; // new strips laid as one surface over a patch or around an axis
    int intervals = 4;      // spline intervals per new strip
    int iterations = 30;    // of the pull (the job adds its fading iterations)
    double rho = 0.0;       // thinning radius, mm
};

// The choices of Tools ▸ Approximate Reference Shape…: which reference shape (when there are
// several), start from K new flat strips or from the design's surfaces (when it has any),
// whether new strips over a shape that is one patch become one surface, intervals per new
// strip, iterations and the thinning radius ρ, which starts at the default
// the command line uses (2 % of the shape's bounding-box diagonal) and follows the shape
// chosen until edited.
class ApproximateDialog : public QDialog {
    Q_OBJECT
public:
    ApproximateDialog(const model::Project& project, QWidget* parent = nullptr);

    ApproximationChoice choice() const;
    // The default ρ of the shape chosen (mm).
    double defaultRho() const { return m_defaultRho; }

    QComboBox* shapeBox() const { return m_shape; }
    QRadioButton* newStripsButton() const { return m_newStrips; }
    QRadioButton* designButton() const { return m_design; }
    QSpinBox* stripsBox() const { return m_strips; }
    QCheckBox* oneSurfaceBox() const { return m_oneSurface; }
    QSpinBox* intervalsBox() const { return m_intervals; }
    QSpinBox* iterationsBox() const { return m_iterations; }
    QDoubleSpinBox* rhoBox() const { return m_rho; }

private:
    void shapeChosen(int index);

    const model::Project& m_project; // modal: the design does not change meanwhile
    QComboBox* m_shape = nullptr;
    QRadioButton* m_newStrips = nullptr;
    QRadioButton* m_design = nullptr;
    QSpinBox* m_strips = nullptr;
    QCheckBox* m_oneSurface = nullptr;
    QSpinBox* m_intervals = nullptr;
    QSpinBox* m_iterations = nullptr;
    QDoubleSpinBox* m_rho = nullptr;
    QLabel* m_rhoHint = nullptr;
    double m_defaultRho = 0.0;
    double m_rhoShown = 0.0; // m_defaultRho as the box rounds it
};

} // namespace devsurf::app
