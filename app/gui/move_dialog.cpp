#include "move_dialog.h"

#include <QCheckBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QPushButton>
#include <QRadioButton>
#include <QSettings>
#include <QVBoxLayout>

#include <cmath>

namespace devsurf::app {

namespace {

const QString kKeepDevelopableKey = QStringLiteral("move/keepDevelopable");

// Three spin boxes named name + X, Y, Z.
QWidget* vectorRow(QWidget* parent, QDoubleSpinBox* (&boxes)[3], const model::Vec3& initial,
                   const QString& suffix, const QString& name) {
    auto* row = new QWidget(parent);
    auto* layout = new QHBoxLayout(row);
    layout->setContentsMargins(0, 0, 0, 0);
    for (int axis = 0; axis < 3; ++axis) {
        boxes[axis] = new QDoubleSpinBox(row);
        boxes[axis]->setRange(-1e6, 1e6);
        boxes[axis]->setDecimals(4);
        boxes[axis]->setSuffix(suffix);
        boxes[axis]->setValue(initial[axis]);
        boxes[axis]->setObjectName(name + QLatin1Char("XYZ"[axis]));
        layout->addWidget(boxes[axis]);
    }
    return row;
}

} // namespace

MoveDialog::MoveDialog(const model::Vec3& pivot, QWidget* parent)
    : QDialog(parent), m_translate(new QRadioButton(tr("&Translate"), this)),
      m_rotate(new QRadioButton(tr("&Rotate"), this)), m_angle(new QDoubleSpinBox(this)),
      m_keepDevelopable(new QCheckBox(tr("&Keep developable"), this)) {
    setWindowTitle(tr("Move or Rotate Vertices"));
    m_translate->setChecked(true);
    m_translate->setObjectName(QStringLiteral("translate"));
    m_rotate->setObjectName(QStringLiteral("rotate"));
    m_angle->setObjectName(QStringLiteral("angle"));

    auto* translateBox = new QGroupBox(tr("Translation"), this);
    auto* translateForm = new QFormLayout(translateBox);
    translateForm->addRow(
        tr("Offset (x, y, z):"),
        vectorRow(translateBox, m_offset, {}, QStringLiteral(" mm"), QStringLiteral("offset")));

    auto* rotateBox = new QGroupBox(tr("Rotation"), this);
    auto* rotateForm = new QFormLayout(rotateBox);
    rotateForm->addRow(
        tr("Axis through (x, y, z):"),
        vectorRow(rotateBox, m_point, pivot, QStringLiteral(" mm"), QStringLiteral("point")));
    rotateForm->addRow(tr("Axis direction:"), vectorRow(rotateBox, m_direction, {0, 0, 1}, {},
                                                        QStringLiteral("direction")));
    m_angle->setRange(-360, 360);
    m_angle->setDecimals(3);
    m_angle->setSuffix(QStringLiteral(" °"));
    rotateForm->addRow(tr("Angle:"), m_angle);
    rotateBox->setEnabled(false);
    connect(m_rotate, &QRadioButton::toggled, rotateBox, &QWidget::setEnabled);
    connect(m_translate, &QRadioButton::toggled, translateBox, &QWidget::setEnabled);

    m_keepDevelopable->setObjectName(QStringLiteral("keepDevelopable"));
    m_keepDevelopable->setChecked(QSettings().value(kKeepDevelopableKey, true).toBool());
    m_keepDevelopable->setToolTip(
        tr("After the motion, run 10 solver iterations with the moved vertices held at their new "
           "positions and the pinned vertices where they are, so that the surface stays "
           "developable. The motion and the solve are one undo step; Esc cancels the solve and "
           "nothing moves. Off: only the exact motion."));

    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    connect(buttons, &QDialogButtonBox::accepted, this, &MoveDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);

    auto* layout = new QVBoxLayout(this);
    layout->addWidget(m_translate);
    layout->addWidget(translateBox);
    layout->addWidget(m_rotate);
    layout->addWidget(rotateBox);
    layout->addWidget(m_keepDevelopable);
    layout->addWidget(buttons);
}

void MoveDialog::accept() {
    // A rotation needs an axis: refuse a zero direction here rather than in the model.
    if (isRotation() && axisDirection().norm() == 0.0) {
        m_direction[2]->setFocus();
        return;
    }
    QSettings().setValue(kKeepDevelopableKey, m_keepDevelopable->isChecked());
    QDialog::accept();
}

bool MoveDialog::isRotation() const {
    return m_rotate->isChecked();
}

model::Vec3 MoveDialog::translation() const {
    return {m_offset[0]->value(), m_offset[1]->value(), m_offset[2]->value()};
}

model::Vec3 MoveDialog::axisPoint() const {
    return {m_point[0]->value(), m_point[1]->value(), m_point[2]->value()};
}

model::Vec3 MoveDialog::axisDirection() const {
    return {m_direction[0]->value(), m_direction[1]->value(), m_direction[2]->value()};
}

bool MoveDialog::keepDevelopable() const {
    return m_keepDevelopable->isChecked();
}

double MoveDialog::angleRadians() const {
    return m_angle->value() * M_PI / 180.0;
}

} // namespace devsurf::app
