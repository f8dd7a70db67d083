#include "approximate_dialog.h"

#include "distance_report_dialog.h"
#include "solver/session/approximation_setup.h"
#include "solver/session/solve_job.h"

#include "model/reference/bounding_box.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLocale>
#include <QPushButton>
#include <QRadioButton>
#include <QSpinBox>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

namespace devsurf::app {

ApproximateDialog::ApproximateDialog(const model::Project& project, QWidget* parent)
    : QDialog(parent), m_project(project) {
    setObjectName(QStringLiteral("approximateDialog"));
    setWindowTitle(tr("Approximate Reference Shape"));
    auto* form = new QFormLayout;

    m_shape = new QComboBox(this);
    m_shape->setObjectName(QStringLiteral("shapeBox"));
    for (const model::ReferenceShape& shape : project.referenceShapes) {
        m_shape->addItem(
            tr("%1 (%n point(s))", nullptr,
               static_cast<int>(std::min<std::size_t>(shape.points.size(), 2147483647)))
                .arg(QString::fromStdString(shape.name)));
    }
    form->addRow(tr("Reference &shape:"), m_shape);
    // One shape: nothing to choose, but the name says which.
    m_shape->setEnabled(project.referenceShapes.size() > 1);

    m_newStrips = new QRadioButton(tr("&New strips:"), this);
    m_newStrips->setObjectName(QStringLiteral("newStripsButton"));
    m_newStrips->setToolTip(
        tr("Lay as many flat strips over patches of the shape (k-means clusters; where the "
           "shape curves both ways, bands twice as long as wide), pull them towards the shape "
           "and add them to the design. A strip that cannot follow the shape and stay "
           "developable is pulled again, damped, from the cylinder that fits its points best. "
           "Then each is trimmed back where it stands off the shape."));
    m_strips = new QSpinBox(this);
    m_strips->setObjectName(QStringLiteral("stripsBox"));
    m_strips->setRange(1, 100);
    m_strips->setValue(4);
    auto* stripsRow = new QHBoxLayout;
    stripsRow->addWidget(m_newStrips);
    stripsRow->addWidget(m_strips);
    stripsRow->addStretch(1);
    m_design = new QRadioButton(tr("The &design's surfaces"), this);
    m_design->setObjectName(QStringLiteral("designButton"));
    m_design->setToolTip(tr("Pull the surfaces of the design towards the shape; each is pulled "
                            "by the points nearest to it."));
    const bool hasSurfaces =
        std::any_of(project.surfaces.begin(), project.surfaces.end(),
                    [](const model::CompositeSurface& s) { return !s.faces().empty(); });
    m_design->setEnabled(hasSurfaces);
    if (!hasSurfaces) {
        m_design->setToolTip(tr("The design has no surface yet."));
    }
    m_oneSurface = new QCheckBox(tr("As &one surface where the shape allows"), this);
    m_oneSurface->setObjectName(QStringLiteral("oneSurfaceBox"));
    m_oneSurface->setChecked(true);
    m_oneSurface->setToolTip(
        tr("Over a shape seen from one side (a panel), lay the new strips side by side as one "
           "watertight surface, bent to the shape, each two sharing a curve along which they may "
           "kink; around a shape that closes around an axis (a tube, a vase, a sphere), lay them "
           "as rings one after another, one surface open only at its two ends. Off, or over any "
           "other shape: separate strips over patches of the shape."));
    m_newStrips->setChecked(true);
    auto* start = new QVBoxLayout;
    start->addLayout(stripsRow);
    start->addWidget(m_oneSurface);
    start->addWidget(m_design);
    form->addRow(tr("Start from:"), start);

    m_intervals = new QSpinBox(this);
    m_intervals->setObjectName(QStringLiteral("intervalsBox"));
    m_intervals->setRange(1, 100);
    m_intervals->setValue(4);
    m_intervals->setToolTip(tr("Spline intervals along each new strip: more follow finer "
                               "detail and take longer."));
    form->addRow(tr("&Intervals per strip:"), m_intervals);
    connect(m_newStrips, &QRadioButton::toggled, this, [this](bool on) {
        m_strips->setEnabled(on);
        m_oneSurface->setEnabled(on);
        m_intervals->setEnabled(on);
    });

    m_iterations = new QSpinBox(this);
    m_iterations->setObjectName(QStringLiteral("iterationsBox"));
    m_iterations->setRange(1, 1000);
    m_iterations->setValue(solver::kApproximationIterations);
    m_iterations->setToolTip(tr("Iterations of the pull towards the shape; a few more follow "
                                "in which the pull fades."));
    form->addRow(tr("I&terations:"), m_iterations);

    m_rho = new QDoubleSpinBox(this);
    m_rho->setObjectName(QStringLiteral("rhoBox"));
    m_rho->setSuffix(tr(" mm"));
    m_rho->setToolTip(tr("Thinning radius ρ: the shape is thinned to points at least ρ apart, "
                         "each with the normal of the points around it."));
    form->addRow(tr("Thinning radius &ρ:"), m_rho);
    m_rhoHint = new QLabel(this);
    m_rhoHint->setObjectName(QStringLiteral("rhoHint"));
    m_rhoHint->setWordWrap(true);
    form->addRow(QString(), m_rhoHint);
    connect(m_shape, &QComboBox::currentIndexChanged, this, &ApproximateDialog::shapeChosen);
    shapeChosen(0);

    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    buttons->button(QDialogButtonBox::Ok)->setText(tr("&Approximate"));
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(form);
    layout->addWidget(buttons);
}

void ApproximateDialog::shapeChosen(int index) {
    if (index < 0 || static_cast<std::size_t>(index) >= m_project.referenceShapes.size()) {
        return;
    }
    const std::vector<model::Vec3>& points =
        m_project.referenceShapes[static_cast<std::size_t>(index)].points;
    const double diagonal = model::reference::boundingBoxDiagonal(points);
    m_defaultRho = solver::defaultApproximationRadius(points, diagonal);
    // Three significant digits whatever the shape's size (a scan in metres is 0.2 across).
    const int decimals =
        m_defaultRho > 0.0
            ? std::clamp(3 - static_cast<int>(std::floor(std::log10(m_defaultRho))), 0, 9)
            : 3;
    m_rho->setDecimals(decimals);
    m_rho->setRange(std::pow(10.0, -decimals), std::max(1e9, 2.0 * m_defaultRho));
    m_rho->setSingleStep(std::pow(10.0, std::floor(std::log10(std::max(m_defaultRho, 1e-9)))));
    m_rho->setValue(m_defaultRho);
    m_rhoShown = m_rho->value();
    m_rhoHint->setText(tr("Default: %1 % of the shape's bounding-box diagonal (%2), or more "
                          "where its points are sparse.")
                           .arg(QLocale().toString(solver::kDefaultRhoPercent, 'g', 3),
                                DistanceReportDialog::millimetres(diagonal)));
}

ApproximationChoice ApproximateDialog::choice() const {
    ApproximationChoice c;
    c.shape = std::max(0, m_shape->currentIndex());
    c.newStrips = m_newStrips->isChecked();
    c.strips = m_strips->value();
    c.oneSurface = m_oneSurface->isChecked();
    c.intervals = m_intervals->value();
    c.iterations = m_iterations->value();
    // The default as computed, not as rounded for the box, unless ρ was edited.
    c.rho = m_rho->value() == m_rhoShown ? m_defaultRho : m_rho->value();
    return c;
}

} // namespace devsurf::app
