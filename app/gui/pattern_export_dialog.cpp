#include "pattern_export_dialog.h"
#include "problem_text.h"

#include "bounded_pattern.h"
#include "output_problem_text.h"

#include "io/file_error.h"
#include "io/pattern/fabrication_report.h"
#include "model/project.h"

#include <QButtonGroup>
#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QMessageBox>
#include <QProgressDialog>
#include <QPushButton>
#include <QRadioButton>
#include <QSettings>
#include <QTableWidget>
#include <QTimer>
#include <QVBoxLayout>

namespace devsurf::app {

using model::PatternLayer;

QList<SheetPreset> sheetPresets() {
    return {{QObject::tr("Laser bed 600 × 400 mm"), {600.0, 400.0}},
            {QObject::tr("A4 (210 × 297 mm)"), {210.0, 297.0}},
            {QObject::tr("A3 (297 × 420 mm)"), {297.0, 420.0}},
            {QObject::tr("Letter (8.5 × 11 in)"), {215.9, 279.4}},
            {QObject::tr("Custom"), {0.0, 0.0}}};
}

PatternSettings PatternSettings::load() {
    QSettings s;
    s.beginGroup(QStringLiteral("pattern"));
    PatternSettings p;
    p.format = static_cast<io::PatternFormat>(
        std::clamp(s.value(QStringLiteral("format"), 0).toInt(), 0, 3));
    p.write.splines = s.value(QStringLiteral("splines"), false).toBool();
    p.write.r12 = s.value(QStringLiteral("r12"), false).toBool();
    p.write.tolerance = s.value(QStringLiteral("tolerance"), 0.01).toDouble();
    p.write.layers = s.value(QStringLiteral("layers"), io::kAllLayers).toUInt() & io::kAllLayers;
    p.write.paper =
        static_cast<io::Paper>(std::clamp(s.value(QStringLiteral("paper"), 0).toInt(), 0, 2));
    p.pattern.tolerance = p.write.tolerance;
    p.pattern.rulings = (p.write.layers & io::layerBit(PatternLayer::Score)) != 0;
    p.pattern.seamAllowance = s.value(QStringLiteral("seam"), 0.0).toDouble();
    p.pattern.glueTabs = s.value(QStringLiteral("glueTabs"), false).toBool();
    p.sheetPreset = std::clamp(s.value(QStringLiteral("sheetPreset"), 0).toInt(), 0,
                               int(sheetPresets().size()) - 1);
    p.pattern.sheetSize = {s.value(QStringLiteral("sheetWidth"), 600.0).toDouble(),
                           s.value(QStringLiteral("sheetHeight"), 400.0).toDouble()};
    return p;
}

void PatternSettings::save() const {
    QSettings s;
    s.beginGroup(QStringLiteral("pattern"));
    s.setValue(QStringLiteral("format"), static_cast<int>(format));
    s.setValue(QStringLiteral("splines"), write.splines);
    s.setValue(QStringLiteral("r12"), write.r12);
    s.setValue(QStringLiteral("tolerance"), write.tolerance);
    s.setValue(QStringLiteral("layers"), write.layers);
    s.setValue(QStringLiteral("paper"), static_cast<int>(write.paper));
    s.setValue(QStringLiteral("seam"), pattern.seamAllowance);
    s.setValue(QStringLiteral("glueTabs"), pattern.glueTabs);
    s.setValue(QStringLiteral("sheetPreset"), sheetPreset);
    s.setValue(QStringLiteral("sheetWidth"), pattern.sheetSize.x);
    s.setValue(QStringLiteral("sheetHeight"), pattern.sheetSize.y);
}

QString PatternExportDialog::filterFor(io::PatternFormat format) {
    switch (format) {
    case io::PatternFormat::Dxf:
        return tr("DXF drawing (*.dxf)");
    case io::PatternFormat::Svg:
        return tr("SVG image (*.svg)");
    case io::PatternFormat::Pdf:
        return tr("PDF document (*.pdf)");
    case io::PatternFormat::Fold:
        return tr("FOLD crease pattern (*.fold)");
    }
    return {};
}

PatternExportDialog::PatternExportDialog(const model::Project& project, const QString& baseName,
                                         const QString& directory, QWidget* parent)
    : QDialog(parent), m_project(project), m_baseName(baseName), m_directory(directory) {
    setWindowTitle(tr("Export Cutting Pattern"));
    auto* form = new QFormLayout;

    m_format = new QComboBox(this);
    m_format->addItems({tr("DXF (laser and plotter cutters)"), tr("SVG (vinyl and paper cutters)"),
                        tr("PDF (print at 1:1, tiled)"), tr("FOLD (origami simulators)")});
    form->addRow(tr("&Format:"), m_format);

    m_polylines = new QRadioButton(tr("&Polylines"), this);
    m_splines = new QRadioButton(tr("S&plines"), this);
    auto* curves = new QHBoxLayout;
    curves->addWidget(m_polylines);
    curves->addWidget(m_splines);
    auto* curveGroup = new QButtonGroup(this);
    curveGroup->addButton(m_polylines);
    curveGroup->addButton(m_splines);
    m_r12 = new QCheckBox(tr("DXF &R12 (for old cutter software)"), this);
    curves->addWidget(m_r12);
    form->addRow(tr("Curves:"), curves);

    m_tolerance = new QDoubleSpinBox(this);
    m_tolerance->setRange(0.001, 1.0);
    m_tolerance->setDecimals(3);
    m_tolerance->setSingleStep(0.005);
    m_tolerance->setSuffix(tr(" mm"));
    form->addRow(tr("&Tolerance:"), m_tolerance);

    auto* layers = new QHBoxLayout;
    const QStringList layerTexts{tr("Cut"),    tr("Mountain"),        tr("Valley"),
                                 tr("Crease"), tr("Rulings (score)"), tr("Seam"),
                                 tr("Labels")};
    for (int i = 0; i < model::kPatternLayerCount; ++i) {
        auto* box = new QCheckBox(layerTexts[i], this);
        box->setObjectName(QString::fromLatin1(io::layerStyle(PatternLayer(i)).name));
        m_layers << box;
        layers->addWidget(box);
    }
    m_layers.front()->setEnabled(false); // the cut lines are the pattern
    form->addRow(tr("Layers:"), layers);

    m_seam = new QDoubleSpinBox(this);
    m_seam->setRange(0.0, 100.0);
    m_seam->setSuffix(tr(" mm"));
    m_glueTabs = new QCheckBox(tr("as &glue tabs"), this);
    auto* seam = new QHBoxLayout;
    seam->addWidget(m_seam);
    seam->addWidget(m_glueTabs);
    // A row of several widgets: its label's mnemonic needs a buddy, else '&' shows.
    auto* seamLabel = new QLabel(tr("&Seam allowance:"), this);
    seamLabel->setBuddy(m_seam);
    form->addRow(seamLabel, seam);

    m_sheet = new QComboBox(this);
    for (const SheetPreset& preset : sheetPresets()) {
        m_sheet->addItem(preset.name);
    }
    m_sheetWidth = new QDoubleSpinBox(this);
    m_sheetHeight = new QDoubleSpinBox(this);
    for (QDoubleSpinBox* box : {m_sheetWidth, m_sheetHeight}) {
        box->setRange(10.0, 10000.0);
        box->setDecimals(1);
        box->setSuffix(tr(" mm"));
    }
    auto* sheet = new QHBoxLayout;
    sheet->addWidget(m_sheet);
    sheet->addWidget(m_sheetWidth);
    sheet->addWidget(new QLabel(QStringLiteral("×"), this));
    sheet->addWidget(m_sheetHeight);
    auto* sheetLabel = new QLabel(tr("S&heet:"), this);
    sheetLabel->setBuddy(m_sheet);
    form->addRow(sheetLabel, sheet);

    m_paper = new QComboBox(this);
    m_paper->addItems({tr("A4"), tr("A3"), tr("Letter")});
    form->addRow(tr("P&aper (PDF):"), m_paper);

    m_summary = new QLabel(this);
    m_warning = new QLabel(this);
    m_warning->setWordWrap(true);
    m_warning->setStyleSheet(QStringLiteral("color: #b00000; font-weight: bold"));
    m_report = new QTableWidget(0, 7, this);
    m_report->setHorizontalHeaderLabels({tr("Piece"), tr("Sheet"), tr("Size (mm)"),
                                         tr("Area (mm²)"), tr("Isometry error (mm)"),
                                         tr("Fits sheet"), tr("Overlaps")});
    m_report->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    m_report->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_report->verticalHeader()->hide();
    auto* reportBox = new QGroupBox(tr("Fabrication report"), this);
    auto* reportLayout = new QVBoxLayout(reportBox);
    reportLayout->addWidget(m_summary);
    reportLayout->addWidget(m_report);
    reportLayout->addWidget(m_warning);

    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    m_export = buttons->addButton(tr("&Export…"), QDialogButtonBox::AcceptRole);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    connect(m_export, &QPushButton::clicked, this, &PatternExportDialog::chooseFileAndExport);

    auto* layout = new QVBoxLayout(this);
    layout->addLayout(form);
    layout->addWidget(reportBox, 1);
    layout->addWidget(buttons);
    resize(760, 560);

    setSettings(PatternSettings::load());

    // The pattern follows the options, rebuilt once the user pauses.
    m_rebuildTimer = new QTimer(this);
    m_rebuildTimer->setSingleShot(true);
    m_rebuildTimer->setInterval(250);
    connect(m_rebuildTimer, &QTimer::timeout, this, &PatternExportDialog::rebuildPattern);
    auto later = [this] {
        updateEnabled();
        m_rebuildTimer->start();
    };
    connect(m_format, &QComboBox::currentIndexChanged, this, [this] { updateEnabled(); });
    connect(m_tolerance, &QDoubleSpinBox::valueChanged, this, later);
    connect(m_seam, &QDoubleSpinBox::valueChanged, this, later);
    connect(m_glueTabs, &QCheckBox::toggled, this, later);
    connect(m_layers[int(PatternLayer::Score)], &QCheckBox::toggled, this, later);
    connect(m_sheetWidth, &QDoubleSpinBox::valueChanged, this, later);
    connect(m_sheetHeight, &QDoubleSpinBox::valueChanged, this, later);
    connect(m_sheet, &QComboBox::currentIndexChanged, this, [this, later](int index) {
        const SheetPreset preset = sheetPresets().value(index);
        if (preset.size.x > 0.0) {
            m_sheetWidth->setValue(preset.size.x);
            m_sheetHeight->setValue(preset.size.y);
        }
        later();
    });
    rebuildPattern();
}

PatternSettings PatternExportDialog::settings() const {
    PatternSettings s;
    s.format = static_cast<io::PatternFormat>(m_format->currentIndex());
    s.write.splines = m_splines->isChecked();
    s.write.r12 = m_r12->isChecked();
    s.write.tolerance = m_tolerance->value();
    s.write.layers = 0;
    for (int i = 0; i < m_layers.size(); ++i) {
        if (m_layers[i]->isChecked()) {
            s.write.layers |= io::layerBit(PatternLayer(i));
        }
    }
    s.write.paper = static_cast<io::Paper>(m_paper->currentIndex());
    s.pattern.tolerance = s.write.tolerance;
    s.pattern.rulings =
        m_layers[int(PatternLayer::Score)]->isChecked() || s.format == io::PatternFormat::Fold;
    s.pattern.seamAllowance = m_seam->value();
    s.pattern.glueTabs = m_glueTabs->isChecked();
    s.sheetPreset = m_sheet->currentIndex();
    s.pattern.sheetSize = {m_sheetWidth->value(), m_sheetHeight->value()};
    return s;
}

void PatternExportDialog::setSettings(const PatternSettings& s) {
    const QSignalBlocker blockSheet(m_sheet);
    m_format->setCurrentIndex(static_cast<int>(s.format));
    (s.write.splines ? m_splines : m_polylines)->setChecked(true);
    m_r12->setChecked(s.write.r12);
    m_tolerance->setValue(s.write.tolerance);
    for (int i = 0; i < m_layers.size(); ++i) {
        m_layers[i]->setChecked((s.write.layers & io::layerBit(PatternLayer(i))) != 0 || i == 0);
    }
    m_paper->setCurrentIndex(static_cast<int>(s.write.paper));
    m_seam->setValue(s.pattern.seamAllowance);
    m_glueTabs->setChecked(s.pattern.glueTabs);
    m_sheet->setCurrentIndex(s.sheetPreset);
    m_sheetWidth->setValue(s.pattern.sheetSize.x);
    m_sheetHeight->setValue(s.pattern.sheetSize.y);
    updateEnabled();
}

void PatternExportDialog::updateEnabled() {
    const auto format = static_cast<io::PatternFormat>(m_format->currentIndex());
    const bool dxf = format == io::PatternFormat::Dxf;
    m_splines->setEnabled(dxf && !m_r12->isChecked());
    m_polylines->setEnabled(dxf);
    m_r12->setEnabled(dxf);
    m_paper->setEnabled(format == io::PatternFormat::Pdf);
    const bool custom = m_sheet->currentIndex() == int(sheetPresets().size()) - 1;
    m_sheetWidth->setEnabled(custom);
    m_sheetHeight->setEnabled(custom);
}

void PatternExportDialog::rebuildPattern() {
    if (m_rebuildTimer != nullptr) {
        m_rebuildTimer->stop();
    }
    BoundedPattern built = buildBoundedPattern(m_project, settings().pattern);
    m_pattern = std::move(built.pattern);
    m_samplingTolerance = built.tolerance;
    m_samplingNote = built.note;
    showReport();
}

void PatternExportDialog::showReport() {
    const io::FabricationReport report =
        io::fabricationReport(m_pattern, patternProblemTexts(m_pattern));
    m_report->setRowCount(int(report.pieces.size()));
    for (int row = 0; row < int(report.pieces.size()); ++row) {
        const io::PieceReport& piece = report.pieces[std::size_t(row)];
        QStringList overlaps;
        if (piece.selfOverlapping) {
            overlaps << tr("itself");
        }
        for (const std::string& other : piece.overlapsWith) {
            overlaps << QString::fromStdString(other);
        }
        const QStringList cells{
            QString::fromStdString(piece.name),
            piece.sheet >= 0 ? QString::number(piece.sheet + 1) : tr("none"),
            tr("%1 × %2").arg(piece.size.x, 0, 'f', 1).arg(piece.size.y, 0, 'f', 1),
            QString::number(piece.area, 'f', 0),
            QString::number(piece.maxIsometryError, 'g', 3),
            piece.fitsSheet ? tr("yes") : tr("no"),
            overlaps.isEmpty() ? tr("none") : overlaps.join(QStringLiteral(", "))};
        for (int c = 0; c < cells.size(); ++c) {
            m_report->setItem(row, c, new QTableWidgetItem(cells[c]));
        }
    }
    m_summary->setText(tr("%n piece(s)", nullptr, int(report.pieces.size())) +
                       QStringLiteral(" · ") + tr("%n sheet(s)", nullptr, report.sheetCount) +
                       QStringLiteral(" · ") +
                       tr("largest isometry error %1 mm").arg(report.maxIsometryError, 0, 'g', 3));
    QStringList problems;
    if (!m_samplingNote.isEmpty()) {
        problems << m_samplingNote;
    }
    for (const std::string& problem : report.problems) {
        problems << QString::fromStdString(problem);
    }
    m_warning->setText(problems.join(QLatin1Char('\n')));
    m_warning->setVisible(!problems.isEmpty());
    m_export->setEnabled(!m_pattern.pieces.empty());
}

void PatternExportDialog::chooseFileAndExport() {
    rebuildPattern();
    const io::FabricationReport report =
        io::fabricationReport(m_pattern, patternProblemTexts(m_pattern));
    if (report.hasOverlaps() || !report.problems.empty()) {
        const QString question =
            report.hasOverlaps()
                ? tr("Some pieces overlap and cannot be cut as laid out. Export anyway?")
                : tr("The pattern has problems (see the report). Export anyway?");
        if (QMessageBox::warning(this, tr("Export Cutting Pattern"), question,
                                 QMessageBox::Yes | QMessageBox::No,
                                 QMessageBox::No) != QMessageBox::Yes) {
            return;
        }
    }
    const auto format = static_cast<io::PatternFormat>(m_format->currentIndex());
    const QString extension = QString::fromLatin1(io::patternFormatName(format));
    const QString path = askExportPath(this, tr("Export Cutting Pattern"), m_directory, m_baseName,
                                       extension, filterFor(format));
    if (!path.isEmpty() && exportTo(path)) {
        accept();
    }
}

bool PatternExportDialog::exportTo(const QString& path) {
    const io::OutputProblem problem = io::outputProblem(
        path, m_projectFile.isEmpty() ? QStringList{} : QStringList{m_projectFile});
    if (problem != io::OutputProblem::None) {
        QMessageBox::critical(this, tr("Export failed"), outputProblemText(problem, path));
        return false;
    }
    PatternSettings s = settings();
    s.save();
    // The progress dialog runs the event loop: the pattern written stays this one.
    rebuildPattern();
    const model::CuttingPattern pattern = m_pattern;
    s.write.tolerance = m_samplingTolerance; // coarser where the design reaches far
    if (pattern.pieces.empty() && !m_samplingNote.isEmpty()) { // refused: too far to sample
        QMessageBox::critical(this, tr("Export failed"), m_samplingNote);
        return false;
    }
    s.write.problemTexts = patternProblemTexts(pattern);
    QProgressDialog progress(tr("Writing the cutting pattern…"), tr("Cancel"), 0, 1, this);
    progress.setWindowModality(Qt::WindowModal);
    progress.setMinimumDuration(400);
    const io::PatternProgress onPage = [&progress](int done, int total) {
        progress.setMaximum(total);
        progress.setValue(done);
        return !progress.wasCanceled();
    };
    try {
        return io::savePatternFile(pattern, s.format, path, s.write, onPage);
    } catch (const io::FileError& error) {
        QMessageBox::critical(this, tr("Export failed"), QString::fromStdString(error.what()));
        return false;
    }
}

} // namespace devsurf::app
