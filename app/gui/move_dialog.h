#pragma once

#include "model/vec3.h"

#include <QDialog>

class QDoubleSpinBox;
class QRadioButton;

namespace devsurf::app {

// Exact numeric input for Tools ▸ Move or Rotate Vertices.
class MoveDialog : public QDialog {
    Q_OBJECT
public:
    explicit MoveDialog(const model::Vec3& pivot, QWidget* parent = nullptr);

    bool isRotation() const;
    model::Vec3 translation() const;
    model::Vec3 axisPoint() const;
    model::Vec3 axisDirection() const;
    double angleRadians() const;

private:
    QRadioButton* m_translate;
    QRadioButton* m_rotate;
    QDoubleSpinBox* m_offset[3];
    QDoubleSpinBox* m_point[3];
    QDoubleSpinBox* m_direction[3];
    QDoubleSpinBox* m_angle;
};

} // namespace devsurf::app
