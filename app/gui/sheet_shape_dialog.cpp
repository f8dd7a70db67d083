#include "sheet_shape_dialog.h"

#include "io/curves/curve_import.h"
#include "model/sheet_creases.h"

#include <QApplication>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLocale>
#include <QPushButton>
#include <QVBoxLayout>

namespace devsurf::app {

namespace {

constexpr double kLargestSize = 1e6; // mm: a kilometre
constexpr double kFits = 0.01;       // mm: a development this close to a sheet lies on it

// Where a rectangle's drawing has its origin: at its corner, the sheet's frame at its centre.
model::Vec2 drawingOrigin(const model::SheetDomain& d) {
    return d.shape == model::SheetShape::Rectangle ? model::Vec2(0.5 * d.width, 0.5 * d.height)
                                                   : model::Vec2();
}

QDoubleSpinBox* sizeBox(QWidget* parent, const QString& name) {
    auto* box = new QDoubleSpinBox(parent);
    box->setObjectName(name);
    box->setRange(0.01, kLargestSize);
    box->setDecimals(2);
    box->setSuffix(QStringLiteral(" mm"));
    box->setAccelerated(true);
    return box;
}

} // namespace

SheetShapeDialog::SheetShapeDialog(const model::CompositeSurface& surface,
                                   const model::SampledMesh& mesh,
                                   std::vector<model::Vec2> development, QWidget* parent)
    : QDialog(parent), m_surface(surface), m_mesh(mesh), m_development(std::move(development)),
      m_shape(new QComboBox(this)), m_width(sizeBox(this, QStringLiteral("sheetWidth"))),
      m_height(sizeBox(this, QStringLiteral("sheetHeight"))),
      m_radius(sizeBox(this, QStringLiteral("sheetRadius"))),
      m_innerRadius(sizeBox(this, QStringLiteral("sheetInnerRadius"))), m_fit(new QLabel(this)),
      m_outlineName(new QLabel(this)), m_chooseOutline(new QPushButton(tr("Choose…"), this)),
      m_creasesName(new QLabel(this)), m_chooseCreases(new QPushButton(tr("Choose…"), this)),
      m_clearCreases(new QPushButton(tr("None"), this)),
      m_keepCreases(new QPushButton(tr("As They Lie"), this)) {
    const model::SheetDomain& current = surface.sheetDomain();
    setObjectName(QStringLiteral("sheetShapeDialog"));
    setWindowTitle(tr("Sheet Shape"));
    m_developedArea = model::developedArea(m_mesh, m_development);
    m_shape->setObjectName(QStringLiteral("sheetShape"));
    m_shape->addItem(tr("Free: the development as it is"),
                     static_cast<int>(model::SheetShape::Free));
    m_shape->addItem(tr("Rectangle"), static_cast<int>(model::SheetShape::Rectangle));
    m_shape->addItem(tr("Disk"), static_cast<int>(model::SheetShape::Disk));
    m_shape->addItem(tr("Annulus"), static_cast<int>(model::SheetShape::Annulus));
    m_shape->addItem(tr("Outline of a drawing"), static_cast<int>(model::SheetShape::Outline));
    if (current.shape == model::SheetShape::Outline) {
        m_outline = current.outline;
    }
    m_outlineName->setObjectName(QStringLiteral("sheetOutlineName"));
    // The outline kept now (a file is named once one is chosen).
    m_outlineName->setText(
        m_outline.empty() ? tr("none chosen")
                          : tr("%n closed curve(s)", nullptr, static_cast<int>(m_outline.size())));
    m_chooseOutline->setObjectName(QStringLiteral("sheetOutlineChoose"));
    m_chooseOutline->setToolTip(
        tr("The closed curves of a DXF, SVG, STEP or IGES file, seen from above: the largest "
           "is the sheet's boundary, the others its holes."));
    // Sizes start at the sheets that just hold the development, or at the sheet kept now.
    const auto rectangle =
        model::fittingDomain(model::SheetShape::Rectangle, m_mesh, m_development);
    const auto annulus = model::fittingDomain(model::SheetShape::Annulus, m_mesh, m_development);
    m_width->setValue(current.shape == model::SheetShape::Rectangle ? current.width
                                                                    : rectangle.width);
    m_height->setValue(current.shape == model::SheetShape::Rectangle ? current.height
                                                                     : rectangle.height);
    const bool round =
        current.shape == model::SheetShape::Disk || current.shape == model::SheetShape::Annulus;
    m_radius->setValue(round ? current.radius : annulus.radius);
    m_innerRadius->setValue(current.shape == model::SheetShape::Annulus ? current.innerRadius
                                                                        : annulus.innerRadius);
    const int index = m_shape->findData(static_cast<int>(current.shape));
    m_shape->setCurrentIndex(index >= 0 ? index : 0);

    auto* intro = new QLabel(tr("The sheet the surface is folded from. Every solve and drag keeps "
                                "the surface isometric to its development; with a shape, the "
                                "development may change inside it, its boundary on the shape's "
                                "and its corners at the shape's corners."),
                             this);
    intro->setWordWrap(true);
    auto* form = new QFormLayout;
    form->addRow(tr("Shape:"), m_shape);
    form->addRow(tr("Width:"), m_width);
    form->addRow(tr("Height:"), m_height);
    form->addRow(tr("Radius:"), m_radius);
    form->addRow(tr("Inner radius:"), m_innerRadius);
    auto* outlineRow = new QHBoxLayout;
    outlineRow->addWidget(m_outlineName, 1);
    outlineRow->addWidget(m_chooseOutline);
    form->addRow(tr("Outline:"), outlineRow);
    // The crease curves kept now, as they were drawn.
    for (model::SheetDomain::Curve curve : current.creaseCurves) {
        for (model::Vec2& p : curve.points) {
            p = p + drawingOrigin(current);
        }
        m_creaseDrawing.push_back(std::move(curve));
    }
    m_creasesName->setObjectName(QStringLiteral("sheetCreasesName"));
    m_creasesName->setWordWrap(true);
    m_chooseCreases->setObjectName(QStringLiteral("sheetCreasesChoose"));
    m_chooseCreases->setToolTip(
        tr("Curves drawn in the sheet for the creases to follow: every curve of a DXF, SVG, "
           "STEP or IGES file, seen from above, in the sheet's frame (a rectangle from its "
           "corner at 0,0; circles centred at 0,0; an outline in its own drawing's "
           "coordinates). A crease lying near a curve keeps its development on it."));
    m_clearCreases->setObjectName(QStringLiteral("sheetCreasesClear"));
    m_clearCreases->setToolTip(tr("No curves: the creases move freely inside the sheet."));
    m_keepCreases->setObjectName(QStringLiteral("sheetCreasesAsTheyLie"));
    m_keepCreases->setToolTip(
        tr("Hold every crease on the curve it lies on in the sheet now: the crease pattern stays "
           "as it is while the rulings move in the sheet, so the design folds along its own "
           "creases."));
    auto* creasesRow = new QHBoxLayout;
    creasesRow->addWidget(m_creasesName, 1);
    creasesRow->addWidget(m_chooseCreases);
    creasesRow->addWidget(m_keepCreases);
    creasesRow->addWidget(m_clearCreases);
    form->addRow(tr("Crease curves:"), creasesRow);
    m_fit->setObjectName(QStringLiteral("sheetFit"));
    m_fit->setWordWrap(true);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    m_ok = buttons->button(QDialogButtonBox::Ok);
    connect(m_chooseOutline, &QPushButton::clicked, this, [this] {
        const QString path = m_chooser
                                 ? m_chooser()
                                 : QFileDialog::getOpenFileName(
                                       this, tr("Sheet Outline"), QString(),
                                       tr("Drawings (*.dxf *.svg *.step *.stp *.iges *.igs)"));
        if (!path.isEmpty()) {
            loadOutline(path);
        }
    });
    connect(m_chooseCreases, &QPushButton::clicked, this, [this] {
        const QString path = m_creasesChooser
                                 ? m_creasesChooser()
                                 : QFileDialog::getOpenFileName(
                                       this, tr("Crease Curves"), QString(),
                                       tr("Drawings (*.dxf *.svg *.step *.stp *.iges *.igs)"));
        if (!path.isEmpty()) {
            loadCreaseCurves(path);
        }
    });
    connect(m_keepCreases, &QPushButton::clicked, this, [this] {
        if (m_lyingCreases.empty()) {
            QApplication::setOverrideCursor(Qt::WaitCursor);
            m_lyingCreases = model::creaseCurvesAsTheyLie(m_surface, m_development);
            QApplication::restoreOverrideCursor();
        }
        m_creaseDrawing.clear();
        m_creaseFile.clear();
        m_creasesProblem =
            m_lyingCreases.empty() ? tr("The surface has no crease to hold.") : QString();
        m_creasesAsTheyLie = !m_lyingCreases.empty();
        updateCreases();
    });
    connect(m_clearCreases, &QPushButton::clicked, this, [this] {
        m_creasesAsTheyLie = false;
        m_creaseDrawing.clear();
        m_creaseFile.clear();
        m_creasesProblem.clear();
        updateCreases();
    });
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(intro);
    layout->addLayout(form);
    layout->addWidget(m_fit);
    layout->addWidget(buttons);
    setMinimumWidth(420);
    connect(m_shape, &QComboBox::currentIndexChanged, this, &SheetShapeDialog::onShapeChanged);
    for (QDoubleSpinBox* box : {m_width, m_height, m_radius, m_innerRadius}) {
        connect(box, &QDoubleSpinBox::valueChanged, this, &SheetShapeDialog::updateFit);
        connect(box, &QDoubleSpinBox::valueChanged, this, &SheetShapeDialog::updateCreases);
    }
    onShapeChanged();
}

model::SheetDomain SheetShapeDialog::unplaced() const {
    model::SheetDomain d;
    d.shape = static_cast<model::SheetShape>(m_shape->currentData().toInt());
    switch (d.shape) {
    case model::SheetShape::Rectangle:
        d.width = m_width->value();
        d.height = m_height->value();
        break;
    case model::SheetShape::Disk:
        d.radius = m_radius->value();
        break;
    case model::SheetShape::Annulus:
        d.radius = m_radius->value();
        d.innerRadius = m_innerRadius->value();
        break;
    case model::SheetShape::Outline:
        d.outline = m_outline;
        break;
    case model::SheetShape::Free:
    case model::SheetShape::Cylinder: // never offered: a surface that closes around keeps it
        break;
    }
    return d;
}

bool SheetShapeDialog::loadOutline(const QString& path) {
    const QString name = QFileInfo(path).fileName();
    QApplication::setOverrideCursor(Qt::WaitCursor);
    const io::CurveImportResult read = io::importCurveFile(path);
    QApplication::restoreOverrideCursor();
    std::vector<std::vector<model::Vec2>> loops;
    if (!read.error) {
        loops = model::closedLoopsFromAbove(read.curves);
    }
    model::SheetDomain check;
    check.shape = model::SheetShape::Outline;
    check.outline = loops;
    if (read.error) {
        m_outlineProblem =
            tr("%1 cannot be read as a drawing: choose a DXF, SVG, STEP or IGES file.").arg(name);
    } else if (loops.empty() || model::domainProblem(check)) {
        m_outlineProblem =
            tr("%1 holds no closed curve enclosing an area to be the sheet's outline.").arg(name);
    } else {
        m_outlineProblem.clear();
        m_outline = std::move(loops);
        m_outlineName->setText(
            tr("%1: %n closed curve(s)", nullptr, static_cast<int>(m_outline.size())).arg(name));
    }
    const int index = m_shape->findData(static_cast<int>(model::SheetShape::Outline));
    if (m_shape->currentIndex() != index) {
        m_shape->setCurrentIndex(index); // updates the fit
    } else {
        updateFit();
    }
    return m_outlineProblem.isEmpty();
}

model::SheetDomain SheetShapeDialog::domain() const {
    return withCreases(model::placeDomain(unplaced(), m_mesh, m_development));
}

model::SheetDomain SheetShapeDialog::withCreases(model::SheetDomain placed) const {
    if (placed.isFree() || placed.shape == model::SheetShape::Cylinder ||
        (m_creaseDrawing.empty() && !m_creasesAsTheyLie)) {
        return placed;
    }
    if (m_creasesAsTheyLie) {
        placed.creaseCurves = model::sheetFrameCurves(placed, m_lyingCreases);
    }
    const model::Vec2 origin = drawingOrigin(placed);
    for (model::SheetDomain::Curve curve : m_creaseDrawing) {
        for (model::Vec2& p : curve.points) {
            p = p - origin;
        }
        placed.creaseCurves.push_back(std::move(curve));
    }
    placed.creaseCurveOf = model::assignCreasesToCurves(placed, m_surface, m_mesh, m_development);
    if (placed.creaseCurveOf.empty()) {
        placed.creaseCurves.clear(); // curves that hold nothing are not kept
    }
    return placed;
}

bool SheetShapeDialog::loadCreaseCurves(const QString& path) {
    const QString name = QFileInfo(path).fileName();
    QApplication::setOverrideCursor(Qt::WaitCursor);
    io::CurveImportOptions options;
    options.tolerance = model::kCreaseCurveTolerance;
    const io::CurveImportResult read = io::importCurveFile(path, options);
    QApplication::restoreOverrideCursor();
    std::vector<model::SheetDomain::Curve> curves;
    if (!read.error) {
        curves = model::sheetCurvesFromAbove(read.curves);
    }
    if (read.error) {
        m_creasesProblem =
            tr("%1 cannot be read as a drawing: choose a DXF, SVG, STEP or IGES file.").arg(name);
    } else if (curves.empty()) {
        m_creasesProblem = tr("%1 holds no curve for the creases to follow.").arg(name);
    } else {
        m_creasesProblem.clear();
        m_creaseDrawing = std::move(curves);
        m_creaseFile = name;
        m_creasesAsTheyLie = false;
    }
    updateCreases();
    return m_creasesProblem.isEmpty();
}

void SheetShapeDialog::updateCreases() {
    const auto shape = static_cast<model::SheetShape>(m_shape->currentData().toInt());
    const bool shaped = shape != model::SheetShape::Free && shape != model::SheetShape::Cylinder;
    m_chooseCreases->setEnabled(shaped);
    m_keepCreases->setEnabled(shaped);
    m_clearCreases->setEnabled(shaped && (!m_creaseDrawing.empty() || m_creasesAsTheyLie));
    if (!m_creasesProblem.isEmpty()) {
        m_creasesName->setText(m_creasesProblem);
        m_creasesName->setStyleSheet(QStringLiteral("color: #b00020;"));
        return;
    }
    m_creasesName->setStyleSheet(QString());
    if (m_creaseDrawing.empty() && !m_creasesAsTheyLie) {
        m_creasesName->setText(tr("none"));
        return;
    }
    const QString curves = tr("%n curve(s)", nullptr, static_cast<int>(m_creaseDrawing.size()));
    const QString drawn =
        m_creasesAsTheyLie
            ? tr("the creases as they lie: %n curve(s)", nullptr,
                 static_cast<int>(m_lyingCreases.size()))
            : (m_creaseFile.isEmpty() ? curves : tr("%1: %2").arg(m_creaseFile, curves));
    if (!shaped) {
        m_creasesName->setText(tr("%1, used with a shape only").arg(drawn));
        return;
    }
    const model::SheetDomain d = domain();
    if (d.creaseCurveOf.empty()) {
        m_creasesName->setText(
            tr("%1; no crease lies near them (within half its length, no other crease nearer), "
               "so they are not used")
                .arg(drawn));
        m_creasesName->setStyleSheet(QStringLiteral("color: #b00020;"));
        return;
    }
    m_creasesName->setText(
        tr("%1, holding %n crease(s)", nullptr, static_cast<int>(d.creaseCurveOf.size()))
            .arg(drawn));
}

void SheetShapeDialog::onShapeChanged() {
    const auto shape = static_cast<model::SheetShape>(m_shape->currentData().toInt());
    m_width->setEnabled(shape == model::SheetShape::Rectangle);
    m_height->setEnabled(shape == model::SheetShape::Rectangle);
    m_radius->setEnabled(shape == model::SheetShape::Disk || shape == model::SheetShape::Annulus);
    m_innerRadius->setEnabled(shape == model::SheetShape::Annulus);
    m_chooseOutline->setEnabled(shape == model::SheetShape::Outline);
    updateFit();
    updateCreases();
}

void SheetShapeDialog::updateFit() {
    const model::SheetDomain d = unplaced();
    const QLocale locale;
    const QString developed = locale.toString(m_developedArea / 100.0, 'f', 0);
    m_ok->setEnabled(true);
    if (d.isFree()) {
        m_fit->setText(tr("The development covers %1 cm² and is held as it is.").arg(developed));
        m_fit->setStyleSheet(QString());
        return;
    }
    const bool outline = d.shape == model::SheetShape::Outline;
    if (outline && (!m_outlineProblem.isEmpty() || m_outline.empty())) {
        m_fit->setText(m_outlineProblem.isEmpty()
                           ? tr("Choose a drawing whose closed curves are the sheet's outline.")
                           : m_outlineProblem);
        m_fit->setStyleSheet(m_outlineProblem.isEmpty() ? QString()
                                                        : QStringLiteral("color: #b00020;"));
        m_ok->setEnabled(!m_outline.empty());
        if (m_outline.empty()) {
            return;
        }
    } else if (const auto problem = model::domainProblem(d)) {
        m_fit->setText(outline ? tr("The outline has no closed curve enclosing an area.")
                               : tr("The inner radius must be smaller than the radius."));
        m_fit->setStyleSheet(QStringLiteral("color: #b00020;"));
        m_ok->setEnabled(false);
        return;
    }
    if (outline && !m_outlineProblem.isEmpty()) {
        return; // the problem stays said; the outline chosen before is still the one used
    }
    const double area = model::domainArea(d);
    const QString sheet = locale.toString(area / 100.0, 'f', 0);
    if (m_developedArea > area * (1.0 + 1e-9)) {
        m_fit->setText(tr("The development (%1 cm²) is larger than this sheet (%2 cm²): no solve "
                          "can fold the design from it.")
                           .arg(developed, sheet));
        m_fit->setStyleSheet(QStringLiteral("color: #b00020;"));
        return;
    }
    const double gap = model::largestDomainGap(model::placeDomain(d, m_mesh, m_development), m_mesh,
                                               m_development);
    if (gap <= kFits) {
        m_fit->setText(tr("The development (%1 cm²) fits this sheet (%2 cm²): its boundary lies "
                          "on the sheet's.")
                           .arg(developed, sheet));
    } else {
        m_fit->setText(tr("The development covers %1 cm² of this sheet's %2 cm²; its boundary is "
                          "up to %3 mm from the sheet's, and the next Solve moves it onto the "
                          "sheet.")
                           .arg(developed, sheet, locale.toString(gap, 'f', 1)));
    }
    m_fit->setStyleSheet(QString());
}

} // namespace devsurf::app
