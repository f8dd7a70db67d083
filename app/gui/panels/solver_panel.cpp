#include "solver_panel.h"

#include "model/document/document.h"
#include "verdict_text.h"

#include <QHeaderView>
#include <QLabel>
#include <QLocale>
#include <QPushButton>
#include <QScrollArea>
#include <QTableWidget>
#include <QUndoStack>
#include <QVBoxLayout>

#include <algorithm>

namespace devsurf::app {

SolverPanel::SolverPanel(QWidget* parent)
    : QWidget(parent), m_verdict(new QLabel(this)), m_status(new QLabel(this)),
      m_table(new QTableWidget(this)),
      m_selectPatches(new QPushButton(tr("Select Patches to Check"), this)) {
    setObjectName(QStringLiteral("SolverPanel"));
    auto* layout = new QVBoxLayout(this);
    // Both labels wrap within the dock's width: a long sentence never widens the dock.
    m_verdict->setObjectName(QStringLiteral("SolverVerdict"));
    m_verdict->setWordWrap(true);
    m_verdict->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_verdict->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Preferred);
    m_verdict->hide();
    m_status->setWordWrap(true);
    m_status->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Preferred);
    m_status->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_table->setColumnCount(4);
    // Short headers: the dock is narrow. Their tooltips say what the columns are.
    const QStringList headers{tr("Surf."), tr("Iter."), tr("Residual"), tr("ms")};
    const QStringList tips{tr("Surface"), tr("Iteration"),
                           tr("Largest constraint residual after the iteration"),
                           tr("Time of the iteration in milliseconds")};
    m_table->setHorizontalHeaderLabels(headers);
    for (int c = 0; c < headers.size(); ++c) {
        m_table->horizontalHeaderItem(c)->setToolTip(tips[c]);
    }
    m_table->verticalHeader()->hide();
    m_table->verticalHeader()->setDefaultSectionSize(fontMetrics().height() + 6);
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_table->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    m_table->horizontalHeader()->setStretchLastSection(true);
    m_selectPatches->setObjectName(QStringLiteral("SelectPatchesToCheck"));
    m_selectPatches->setToolTip(tr("Selects the patches the last solve names: the least "
                                   "developable ones and those that fold over onto themselves"));
    m_selectPatches->setEnabled(false);
    connect(m_selectPatches, &QPushButton::clicked, this,
            [this] { emit selectPatches(m_patches); });
    // The sentences scroll when the dock is short, rather than being cut off.
    auto* sentences = new QWidget;
    auto* sentencesLayout = new QVBoxLayout(sentences);
    sentencesLayout->setContentsMargins(0, 0, 0, 0);
    sentencesLayout->addWidget(m_verdict);
    sentencesLayout->addWidget(m_status);
    sentencesLayout->addStretch();
    auto* scroll = new QScrollArea(this);
    scroll->setObjectName(QStringLiteral("SolverSentences"));
    scroll->setWidget(sentences);
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    layout->addWidget(scroll, 1);
    layout->addWidget(m_selectPatches);
    layout->addWidget(m_table, 1);
    clearReport(noSolveYetText());
}

QString SolverPanel::noSolveYetText() {
    return tr("No solve yet. Tools ▸ Solve (Ctrl+Return) makes the design developable; the Drag "
              "tool keeps it developable while you pull vertices.");
}

void SolverPanel::follow(const document::Document* document) {
    m_document = document;
    m_reports.clear();
    connect(document->undoStack(), &QUndoStack::indexChanged, this, &SolverPanel::followUndoState);
    connect(document, &document::Document::projectReset, this, [this] {
        m_reports.clear();
        clearReport(noSolveYetText());
    });
}

SolverPanel::State SolverPanel::currentState() const {
    const QUndoStack* stack = m_document->undoStack();
    const int index = stack->index();
    return {index, index > 0 ? stack->command(index - 1) : nullptr};
}

void SolverPanel::followUndoState() {
    const QUndoStack* stack = m_document->undoStack();
    // Drop the reports of states that are gone (a push after undo deletes the redo tail).
    const auto gone = [stack](const auto& entry) {
        const State& state = entry.first;
        return state.index > stack->count() ||
               (state.index > 0 ? stack->command(state.index - 1) : nullptr) != state.command;
    };
    m_reports.erase(std::remove_if(m_reports.begin(), m_reports.end(), gone), m_reports.end());
    const State now = currentState();
    for (const auto& [state, report] : m_reports) {
        if (state == now) {
            display(report);
            return;
        }
    }
    clearReport(tr("No solve of the design as it is now: it was edited, or a step undone or "
                   "redone, since the last report. Tools ▸ Solve (Ctrl+Return) reports on it."));
}

void SolverPanel::clearReport(const QString& text) {
    m_report = SolveReport();
    m_hasReport = false;
    m_status->setText(text);
    m_verdict->clear();
    m_verdict->setToolTip(QString());
    m_verdict->hide();
    emit verdictChanged(QString(), solver::VerdictKind::None);
    m_table->setRowCount(0);
    m_patches.clear();
    m_selectPatches->setEnabled(false);
    m_worst.clear();
}

void SolverPanel::showReport(const SolveReport& report) {
    if (m_document != nullptr) {
        const State now = currentState();
        const auto same = [now](const auto& entry) { return entry.first == now; };
        m_reports.erase(std::remove_if(m_reports.begin(), m_reports.end(), same), m_reports.end());
        m_reports.emplace_back(now, report);
    }
    display(report);
}

void SolverPanel::display(const SolveReport& report) {
    m_report = report;
    m_hasReport = true;
    int iterations = 0;
    for (const solver::Summary& summary : report.summaries) {
        iterations += static_cast<int>(summary.iterations.size());
    }
    // The table lists the iterations that settled the result (or, for a drag taken back whole,
    // those of the refused release); the count says how many ran, a second settling and a
    // partway search included.
    const int listed = iterations;
    iterations = std::max(iterations, report.outcome.iterationsRun);
    const QLocale locale;
    m_status->setText(tr("<b>%1</b>: %2<br>%n iteration(s) in %3 ms.", nullptr, iterations)
                          .arg(report.title.toHtmlEscaped(), report.status.toHtmlEscaped(),
                               locale.toString(report.elapsedMs, 'f', 1)));
    m_table->setRowCount(listed);
    int row = 0;
    for (std::size_t s = 0; s < report.summaries.size(); ++s) {
        for (const solver::IterationStats& stats : report.summaries[s].iterations) {
            const double ms = stats.assemblyMs + stats.factorizationMs + stats.solveMs;
            const QStringList cells{QString::number(s + 1), QString::number(stats.iteration + 1),
                                    QString::number(stats.maxConstraintResidual, 'e', 2),
                                    locale.toString(ms, 'f', 2)};
            for (int c = 0; c < cells.size(); ++c) {
                auto* item = new QTableWidgetItem(cells[c]);
                item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
                m_table->setItem(row, c, item);
            }
            ++row;
        }
    }
    m_patches = report.patchesToCheck;
    m_selectPatches->setEnabled(!m_patches.empty());
    if (report.creaseResidual >= 0.0) {
        // The solver's residual holds at collocation values; this one along the whole creases.
        m_status->setText(m_status->text() +
                          tr("<br>Crease conditions, sampled along the creases: largest "
                             "residual %1.")
                              .arg(QString::number(report.creaseResidual, 'e', 1)));
    }
    m_worst = report.worstFaces.join(QStringLiteral(", "));
    if (!m_worst.isEmpty()) {
        m_status->setText(m_status->text() +
                          tr("<br>Least developable patches (normalised residual): %1")
                              .arg(m_worst.toHtmlEscaped()));
    }
    // The verdict first, in the colour of its kind; its numbers in the tooltip and below.
    const QString verdict = VerdictText::of(report.verdict);
    const QString details = VerdictText::details(report.verdict);
    m_verdict->setVisible(!verdict.isEmpty());
    m_verdict->setText(
        QStringLiteral("<b><span style=\"color:%1\">%2</span></b>")
            .arg(verdictColour(report.verdict.kind).name(), verdict.toHtmlEscaped()));
    m_verdict->setToolTip(details);
    emit verdictChanged(VerdictText::brief(report.verdict), report.verdict.kind);
}

QColor SolverPanel::verdictColour(solver::VerdictKind kind) {
    switch (kind) {
    case solver::VerdictKind::ReadyToCut:
        return QColor(0x1b, 0x7a, 0x2e);
    case solver::VerdictKind::WithinIsometry:
        return QColor(0x9a, 0x60, 0x00);
    case solver::VerdictKind::NotDevelopable:
        return QColor(0xb0, 0x1c, 0x1c);
    case solver::VerdictKind::None:
        break;
    }
    return QColor(0x30, 0x30, 0x30);
}

QString SolverPanel::verdictText() const {
    return m_hasReport ? VerdictText::of(m_report.verdict) : QString();
}

QString SolverPanel::statusText() const {
    return m_status->text();
}

int SolverPanel::iterationRows() const {
    return m_table->rowCount();
}

QString SolverPanel::worstFacesText() const {
    return m_worst;
}

} // namespace devsurf::app
