#pragma once

#include "model/vec3.h"

#include <QDialog>

class QCheckBox;
class QDoubleSpinBox;
class QRadioButton;

namespace devsurf::app {

// Exact numeric input for Tools ▸ Move or Rotate Vertices. "Keep developable" (remembered,
// on by default) asks for a solve after the motion with the moved vertices held in place.
class MoveDialog : public QDialog {
    Q_OBJECT
public:
    explicit MoveDialog(const model::Vec3& pivot, QWidget* parent = nullptr);

    bool isRotation() const;
    model::Vec3 translation() const;
    model::Vec3 axisPoint() const;
    model::Vec3 axisDirection() const;
    double angleRadians() const;
    bool keepDevelopable() const;

public slots:
    // Refuses a rotation without an axis; remembers Keep developable.
    void accept() override;

private:
    QRadioButton* m_translate;
    QRadioButton* m_rotate;
    QDoubleSpinBox* m_offset[3];
    QDoubleSpinBox* m_point[3];
    QDoubleSpinBox* m_direction[3];
    QDoubleSpinBox* m_angle;
    QCheckBox* m_keepDevelopable;
};

} // namespace devsurf::app
