#pragma once

#include "model/document/selection.h"
#include "solver/core/summary.h"
#include "solver/session/solve_job.h"
#include "solver/session/verdict.h"

#include <QColor>
#include <QStringList>
#include <QWidget>

#include <vector>

class QLabel;
class QPushButton;
class QTableWidget;
class QUndoCommand;

namespace devsurf::document {
class Document;
}

namespace devsurf::app {

// What the Solver panel shows about the last solve or drag.
struct SolveReport {
    solver::JobOutcome outcome; // what the sentences below word
    QString title;              // what ran: "Solve", "Drag 3 vertices"
    solver::Verdict verdict;    // what the designer can do with the result (VerdictText)
    QString status; // one sentence: converged, iteration limit, cancelled, failed (and why)
    std::vector<solver::Summary> summaries; // per surface (empty summaries are skipped)
    QStringList worstFaces;                 // filled when the tolerance was not reached
    QList<int> foldedOver; // patches that fold over onto themselves (solver::foldOvers)
    // Patches at which the development overlaps itself (SurfaceAssessment::overlapping).
    QList<int> overlapping;
    // The largest sampled residual of the crease conditions over the surfaces
    // (SurfaceAssessment::creases); −1: no crease has a condition.
    double creaseResidual = -1.0;
    // Every patch named above (least developable, folded over), for selecting them.
    std::set<document::Pick> patchesToCheck;
    double elapsedMs = 0.0;
};

// The dock "Solver": iterations, constraint residual and time of every iteration of the last
// solve, its status sentence, and the worst patches when the tolerance was not reached. It shows
// the design on screen: a report belongs to the undo state it was shown in, and an edit, undo,
// redo or a new document shows the report of the state reached, or says there is none.
class SolverPanel : public QWidget {
    Q_OBJECT
public:
    explicit SolverPanel(QWidget* parent = nullptr);

    // Follows the undo state of `document` from now on (see the class comment).
    void follow(const document::Document* document);
    // Shows the report of the design as it is now (the solve's step already pushed).
    void showReport(const SolveReport& report);
    // Whether a report is shown (false: none, or none of the design as it is now).
    bool hasReport() const { return m_hasReport; }
    // The report shown last (empty when hasReport() is false).
    const SolveReport& report() const { return m_report; }
    QString statusText() const;
    // The verdict as the panel shows it (VerdictText::of), empty without a report or verdict.
    QString verdictText() const;
    // Rows of the iteration table (one per iteration of every solved surface).
    int iterationRows() const;
    QString worstFacesText() const;
    // The colour a verdict of this kind is written in (the panel and the views' corner).
    static QColor verdictColour(solver::VerdictKind kind);
    // The button that selects the patches the last report names (disabled if it names none).
    QPushButton* selectPatchesButton() const { return m_selectPatches; }

signals:
    // The verdict of the report shown, worded briefly for the views' corner (empty: none), and
    // its kind; sent whenever the panel shows a report or clears it.
    void verdictChanged(const QString& brief, devsurf::solver::VerdictKind kind);
    // The designer asked to select the patches the last report names.
    void selectPatches(const std::set<devsurf::document::Pick>& patches);

private:
    // An undo state: the stack index and the command below it (null at index 0).
    struct State {
        int index = 0;
        const QUndoCommand* command = nullptr;
        bool operator==(const State& o) const { return index == o.index && command == o.command; }
    };
    static QString noSolveYetText();
    State currentState() const;
    void display(const SolveReport& report);
    void clearReport(const QString& text);
    void followUndoState();

    QLabel* m_verdict;
    QLabel* m_status;
    QTableWidget* m_table;
    QPushButton* m_selectPatches;
    QString m_worst;
    SolveReport m_report;
    std::set<document::Pick> m_patches;
    bool m_hasReport = false;
    const document::Document* m_document = nullptr;
    // The reports shown, each with the undo state it describes (states no longer on the
    // stack are dropped).
    std::vector<std::pair<State, SolveReport>> m_reports;
};

} // namespace devsurf::app
