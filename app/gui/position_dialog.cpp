#include "position_dialog.h"

#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QSlider>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

namespace devsurf::app {

namespace {
// Slider steps per per cent in the continuous mode.
constexpr int kStepsPerPercent = 10;
} // namespace

PositionDialog::PositionDialog(const QString& title, const QString& question, QWidget* parent)
    : QDialog(parent), m_slider(new QSlider(Qt::Horizontal, this)),
      m_percent(new QDoubleSpinBox(this)) {
    setObjectName(QStringLiteral("positionDialog"));
    setWindowTitle(title);
    auto* text = new QLabel(question, this);
    text->setWordWrap(true);
    m_percent->setSuffix(QStringLiteral(" %"));
    m_percent->setDecimals(1);
    m_slider->setMinimumWidth(260);
    auto* row = new QHBoxLayout;
    row->addWidget(m_slider, 1);
    row->addWidget(m_percent);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(text);
    layout->addLayout(row);
    layout->addWidget(buttons);
    connect(m_slider, &QSlider::valueChanged, this, &PositionDialog::onSlider);
    connect(m_percent, &QDoubleSpinBox::valueChanged, this, &PositionDialog::onPercent);
}

void PositionDialog::setRange(double minPercent, double maxPercent, double percent) {
    m_choices.clear();
    m_updating = true;
    m_percent->setReadOnly(false);
    m_percent->setButtonSymbols(QAbstractSpinBox::UpDownArrows);
    m_percent->setRange(minPercent, maxPercent);
    m_percent->setSingleStep(1.0);
    m_slider->setRange(static_cast<int>(std::lround(minPercent * kStepsPerPercent)),
                       static_cast<int>(std::lround(maxPercent * kStepsPerPercent)));
    m_updating = false;
    m_percent->setValue(percent);
    onPercent(m_percent->value());
}

void PositionDialog::setChoices(std::vector<double> fractions, int current) {
    m_choices = std::move(fractions);
    m_updating = true;
    // The number only shows where the chosen breakpoint lies; the slider chooses.
    m_percent->setRange(0.0, 100.0);
    m_percent->setReadOnly(true);
    m_percent->setButtonSymbols(QAbstractSpinBox::NoButtons);
    m_slider->setRange(0, std::max(0, static_cast<int>(m_choices.size()) - 1));
    m_slider->setTickPosition(QSlider::TicksBelow);
    m_slider->setTickInterval(1);
    m_slider->setPageStep(1);
    m_updating = false;
    m_slider->setValue(current);
    onSlider(m_slider->value());
}

double PositionDialog::fraction() const {
    return m_choices.empty() ? m_percent->value() / 100.0
                             : m_choices[static_cast<std::size_t>(choice())];
}

int PositionDialog::choice() const {
    return m_choices.empty() ? -1 : m_slider->value();
}

void PositionDialog::onSlider(int value) {
    if (m_updating) {
        return;
    }
    m_updating = true;
    if (m_choices.empty()) {
        m_percent->setValue(static_cast<double>(value) / kStepsPerPercent);
    } else {
        m_percent->setValue(100.0 * m_choices[static_cast<std::size_t>(value)]);
    }
    m_updating = false;
    emit fractionChanged(fraction());
}

void PositionDialog::onPercent(double percent) {
    if (m_updating || !m_choices.empty()) {
        return;
    }
    m_updating = true;
    m_slider->setValue(static_cast<int>(std::lround(percent * kStepsPerPercent)));
    m_updating = false;
    emit fractionChanged(fraction());
}

} // namespace devsurf::app
