#include "distance_report_dialog.h"

#include "model/document/document.h"
#include "views/reference_distances.h"

#include <QDialogButtonBox>
#include <QGroupBox>
#include <QHeaderView>
#include <QLabel>
#include <QLocale>
#include <QProgressBar>
#include <QPushButton>
#include <QScrollArea>
#include <QTableWidget>
#include <QVBoxLayout>

#include <cmath>

namespace devsurf::app {

using model::reference::DistanceReport;
using model::reference::OneSidedDistance;

// Four significant digits, but whole millimetres from a metre on (no exponent for a building).
QString DistanceReportDialog::millimetres(double value) {
    return tr("%1 mm").arg(std::abs(value) >= 1000.0 ? QLocale().toString(value, 'f', 0)
                                                     : QLocale().toString(value, 'g', 4));
}

QString DistanceReportDialog::percent(double value) {
    return tr("%1 %").arg(QLocale().toString(value, 'g', 3));
}

namespace {

using Dialog = DistanceReportDialog;

// A cell "1.234 mm (0.56 %)" holding both values as data (tests read state, not words).
QTableWidgetItem* cell(double mm, double pct) {
    auto* item = new QTableWidgetItem(
        DistanceReportDialog::tr("%1 (%2)").arg(Dialog::millimetres(mm), Dialog::percent(pct)));
    item->setData(Qt::UserRole, mm);
    item->setData(Qt::UserRole + 1, pct);
    item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
    item->setFlags(Qt::ItemIsEnabled | Qt::ItemIsSelectable);
    return item;
}

QTableWidget* reportTable(const DistanceReport& report, QWidget* parent) {
    auto* table = new QTableWidget(2, 3, parent);
    table->setHorizontalHeaderLabels({DistanceReportDialog::tr("Mean"),
                                      DistanceReportDialog::tr("95th percentile"),
                                      DistanceReportDialog::tr("Largest")});
    table->setVerticalHeaderLabels({DistanceReportDialog::tr("Reference shape → design"),
                                    DistanceReportDialog::tr("Design → reference shape")});
    const OneSidedDistance* rows[] = {&report.targetToSurface, &report.surfaceToTarget};
    for (int row = 0; row < 2; ++row) {
        const OneSidedDistance& d = *rows[row];
        table->setItem(row, 0, cell(d.mean, d.meanPercent));
        table->setItem(row, 1, cell(d.percentile95, d.percentile95Percent));
        table->setItem(row, 2, cell(d.max, d.maxPercent));
    }
    table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    table->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    table->verticalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    table->setVerticalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    table->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    table->resizeColumnsToContents();
    table->resizeRowsToContents();
    // Exactly as high as its two rows: no empty band below them.
    table->setFixedHeight(table->horizontalHeader()->sizeHint().height() + table->rowHeight(0) +
                          table->rowHeight(1) + 2 * table->frameWidth());
    table->setSizeAdjustPolicy(QAbstractScrollArea::AdjustToContents);
    return table;
}

} // namespace

DistanceReportDialog::DistanceReportDialog(document::Document* document, QWidget* parent)
    : QDialog(parent), m_document(document), m_source(views::ReferenceDistances::of(document)) {
    setObjectName(QStringLiteral("distanceReportDialog"));
    setWindowTitle(tr("Distance to Reference"));
    auto* layout = new QVBoxLayout(this);
    m_status = new QLabel(this);
    m_status->setWordWrap(true);
    layout->addWidget(m_status);
    m_busy = new QProgressBar(this);
    m_busy->setRange(0, 0); // busy: measureDistance reports no steps
    m_busy->setTextVisible(false);
    layout->addWidget(m_busy);
    auto* scroll = new QScrollArea(this);
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    m_reports = new QWidget(scroll);
    m_reportsLayout = new QVBoxLayout(m_reports);
    m_reportsLayout->setContentsMargins(0, 0, 0, 0);
    scroll->setWidget(m_reports);
    layout->addWidget(scroll, 1);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    layout->addWidget(buttons);
    resize(660, 260);

    connect(m_source, &views::ReferenceDistances::changed, this, &DistanceReportDialog::refresh);
    m_source->use(this, true);
    refresh();
}

DistanceReportDialog::~DistanceReportDialog() {
    if (m_source != nullptr) {
        m_source->use(this, false);
    }
}

bool DistanceReportDialog::showsCurrent() const {
    return m_source != nullptr && m_shown != nullptr && m_shown == m_source->latest() &&
           m_source->isCurrent();
}

bool DistanceReportDialog::isMeasuring() const {
    return m_source != nullptr && m_source->isMeasuring();
}

QTableWidget* DistanceReportDialog::table(int shape) const {
    return shape >= 0 && shape < static_cast<int>(m_tables.size())
               ? m_tables[static_cast<std::size_t>(shape)]
               : nullptr;
}

void DistanceReportDialog::refresh() {
    if (m_source == nullptr) {
        return;
    }
    const std::shared_ptr<const views::ReferenceDistanceResult> latest = m_source->latest();
    if (latest != m_shown) {
        m_shown = latest;
        if (m_shown != nullptr) {
            rebuildReports(*m_shown);
        } else {
            clearReports();
        }
    }
    using Failure = views::ReferenceDistanceResult::Failure;
    const bool measuring = m_source->isMeasuring();
    m_busy->setVisible(measuring);
    QString status;
    if (!m_source->hasInput()) {
        status = m_document->project().referenceShapes.empty()
                     ? tr("The project has no reference shape; import one with File ▸ Import "
                          "Reference Shape….")
                     : tr("The design has no surface to measure.");
    } else if (m_shown == nullptr) {
        status = tr("Measuring the distance between the design and the reference shapes…");
    } else if (m_shown->failure == Failure::InvalidSurface) {
        status = tr("A surface of the design is not valid; solve or undo, then measure again.");
    } else if (m_shown->failure == Failure::NoSurface) {
        status = tr("The design has no surface to measure.");
    } else if (!m_source->isCurrent()) {
        status = tr("The design changed: measuring again. The figures below are out of date.");
    } else {
        status =
            tr("Measured in %1 s.").arg(QLocale().toString(m_shown->milliseconds / 1000.0, 'f', 2));
    }
    m_status->setText(status);
    m_reports->setEnabled(m_shown != nullptr && m_source->isCurrent());
    emit updated();
}

void DistanceReportDialog::clearReports() {
    m_tables.clear();
    while (QLayoutItem* item = m_reportsLayout->takeAt(0)) {
        if (item->widget() != nullptr) {
            item->widget()->deleteLater();
        }
        delete item;
    }
}

void DistanceReportDialog::rebuildReports(const views::ReferenceDistanceResult& result) {
    clearReports();
    const auto& shapes = m_document->project().referenceShapes;
    for (std::size_t i = 0; i < result.reports.size(); ++i) {
        const DistanceReport& report = result.reports[i];
        const QString name =
            i < shapes.size() ? QString::fromStdString(shapes[i].name) : QString::number(i + 1);
        auto* box = new QGroupBox(tr("Reference shape %1").arg(name), m_reports);
        auto* boxLayout = new QVBoxLayout(box);
        QTableWidget* table = reportTable(report, box);
        table->setObjectName(QStringLiteral("distanceTable%1").arg(i));
        boxLayout->addWidget(table);
        const auto points = static_cast<qulonglong>(report.targetDistances.size());
        auto* coverage =
            new QLabel(tr("Coverage: %1 of the %n point(s) lie within %2 of the design.", nullptr,
                          static_cast<int>(std::min<qulonglong>(points, 2147483647)))
                           .arg(percent(100.0 * report.coverage), millimetres(report.tolerance)),
                       box);
        coverage->setObjectName(QStringLiteral("coverage%1").arg(i));
        coverage->setProperty("coverage", report.coverage);
        coverage->setProperty("tolerance", report.tolerance);
        coverage->setWordWrap(true);
        boxLayout->addWidget(coverage);
        auto* detail = new QLabel(
            tr("Two-sided (Hausdorff) distance %1; bounding-box diagonal %2; the design sampled "
               "every %3.")
                .arg(millimetres(report.hausdorff()), millimetres(report.diagonal),
                     millimetres(report.surfaceSpacing)),
            box);
        detail->setWordWrap(true);
        boxLayout->addWidget(detail);
        m_reportsLayout->addWidget(box);
        m_tables.push_back(table);
    }
    m_reportsLayout->addStretch(1);
}

} // namespace devsurf::app
