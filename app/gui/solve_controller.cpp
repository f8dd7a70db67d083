#include "solve_controller.h"
#include "edit_refusal.h"
#include "verdict_text.h"

#include "model/document/commands/apply_surface_command.h"
#include "model/document/document.h"
#include "solver/session/solve_session.h"
#include "solver/session/verdict.h"
#include "solver/worker/solver_worker.h"
#include "workspace.h"

#include <QSettings>
#include <QUndoStack>
#include <QVariant>

#include <algorithm>

namespace devsurf::app {

namespace {

// Solves and edits get tickets of their own (drags use their ids, see DragTool).
quint64 nextTicket() {
    static quint64 ticket = 0x534f4c56'00000000ULL;
    return ++ticket;
}

} // namespace

QString SolveController::patchList(const QList<int>& faces) {
    QStringList patches;
    for (int face : faces) {
        patches << QString::number(face);
    }
    return patches.join(QStringLiteral(", "));
}

SolveController::SolveController(Workspace* workspace, QObject* parent)
    : QObject(parent), m_workspace(workspace), m_worker(new solver::SolverWorker(this)) {
    connect(m_worker, &solver::SolverWorker::finished, this, &SolveController::onResult);
    connect(m_worker, &solver::SolverWorker::progress, this,
            [this](quint64 revision, int iteration, int iterations, double residual) {
                if (m_solving && revision == m_revision) {
                    emit progress(iteration, iterations, residual);
                }
            });
    connect(workspace->document(), &document::Document::changed, this,
            &SolveController::onDocumentChanged);
}

SolveController::~SolveController() = default;

int SolveController::iterationsSetting() {
    return std::clamp(
        QSettings().value(QStringLiteral("solver/iterations"), solver::kSolveIterations).toInt(), 1,
        1000);
}

SolveController::LengthsMode SolveController::lengthsSetting() {
    QSettings settings;
    const QString key = QStringLiteral("solver/lengthsWhileDragging");
    if (!settings.contains(key)) {
        // The on/off choice of earlier versions, if one was made.
        const QVariant old = settings.value(QStringLiteral("solver/keepLengths"));
        if (old.isValid()) {
            return old.toBool() ? LengthsMode::Keep : LengthsMode::Stretch;
        }
        return LengthsMode::Automatic;
    }
    const int mode = settings.value(key).toInt();
    return mode == 1   ? LengthsMode::Keep
           : mode == 2 ? LengthsMode::Stretch
                       : LengthsMode::Automatic;
}

void SolveController::setLengthsSetting(LengthsMode mode) {
    QSettings().setValue(QStringLiteral("solver/lengthsWhileDragging"), static_cast<int>(mode));
}

bool SolveController::keepsLengths() {
    return lengthsSetting() != LengthsMode::Stretch;
}

bool SolveController::stretchesWhereLengthsFail() {
    return lengthsSetting() == LengthsMode::Automatic;
}

void SolveController::solve() {
    if (m_solving && m_job) {
        // A job of its own (an approximation) runs: a Solve would supersede it without a word.
        emit m_workspace->statusMessage(
            tr("Solve is not started while %1 runs; cancel it first (Esc).").arg(m_editTitle));
        return;
    }
    const document::Document* doc = m_workspace->document();
    if (doc->surfaceCount() == 0) {
        emit finished(tr("There is nothing to solve."));
        return;
    }
    solver::SolveRequest request;
    request.revision = doc->revision();
    request.ticket = nextTicket();
    request.job.kind = solver::JobKind::Solve;
    request.job.surfaces = doc->project().surfaces;
    request.job.iterations = iterationsSetting();
    m_revision = request.revision;
    m_ticket = request.ticket;
    m_editSurface = -1;
    m_job = false;
    m_worker->submit(std::move(request));
    if (!m_solving) {
        m_solving = true;
        emit busyChanged(true);
    }
}

void SolveController::solveEdit(int surfaceIndex, model::CompositeSurface edited,
                                const std::set<model::VertexId>& held, const QString& title) {
    const document::Document* doc = m_workspace->document();
    if (surfaceIndex < 0 || surfaceIndex >= doc->surfaceCount() || held.empty()) {
        emit finished(tr("%1: there is nothing to solve; nothing changed.").arg(title));
        return;
    }
    // The solve starts from the design before the edit, with the held vertices pulled to where
    // the edit puts them, as a drag in one step does: started from the edited shape (the held
    // vertices pinned there) the solver collapsed rulings next to them. The result then puts
    // the held vertices exactly where the edit put them (they arrive within ~1e-13 mm).
    m_heldTargets.clear();
    std::vector<solver::VertexHandle> handles;
    for (model::VertexId v : held) {
        if (!edited.hasVertex(v) || edited.isPinned(v)) {
            continue;
        }
        m_heldTargets[v] = edited.position(v);
        handles.push_back({v, false, edited.position(v)});
    }
    solver::SolveRequest request;
    request.revision = doc->revision();
    request.ticket = nextTicket();
    request.job.kind = solver::JobKind::Edit;
    request.job.surfaces = doc->project().surfaces;
    request.job.pulled[surfaceIndex] = handles;
    m_revision = request.revision;
    m_ticket = request.ticket;
    m_editSurface = surfaceIndex;
    m_editTitle = title;
    m_job = false;
    m_worker->submit(std::move(request));
    if (!m_solving) {
        m_solving = true;
        emit busyChanged(true);
    }
}

quint64 SolveController::runJob(solver::JobRequest job, const QString& title) {
    solver::SolveRequest request;
    request.revision = m_workspace->document()->revision();
    request.ticket = nextTicket();
    request.job = std::move(job);
    m_revision = request.revision;
    m_ticket = request.ticket;
    m_editSurface = -1;
    m_editTitle = title;
    m_job = true;
    m_worker->submit(std::move(request));
    if (!m_solving) {
        m_solving = true;
        emit busyChanged(true);
    }
    return m_ticket;
}

void SolveController::finishJob(Ending ending, const SolveReport& report, const QString& sentence,
                                std::vector<std::unique_ptr<QUndoCommand>> commands) {
    if (!m_solving || !m_job) {
        return;
    }
    if (!commands.empty()) {
        m_applying = true;
        QUndoStack* stack = m_workspace->document()->undoStack();
        stack->beginMacro(m_editTitle);
        for (auto& command : commands) {
            stack->push(command.release());
        }
        stack->endMacro();
        m_applying = false;
    }
    stop(&report, ending, sentence);
}

QString SolveController::cancelledSentence(const QString& reason) const {
    if (m_job) {
        return reason.isEmpty()
                   ? tr("%1 cancelled; the design is unchanged.").arg(m_editTitle)
                   : tr("%1 cancelled: %2; the design is unchanged.").arg(m_editTitle, reason);
    }
    if (m_editSurface >= 0) {
        return reason.isEmpty() ? tr("%1 cancelled; nothing moved.").arg(m_editTitle)
                                : tr("%1 cancelled: %2; nothing moved.").arg(m_editTitle, reason);
    }
    return reason.isEmpty() ? tr("Solve cancelled; the design is unchanged.")
                            : tr("Solve cancelled: %1; the design is unchanged.").arg(reason);
}

QString SolveController::checkShapeSentence(const SolveReport& report) const {
    if (!report.foldedOver.isEmpty()) {
        return QLatin1Char(' ') +
               tr("Check the shape: %n patch(es) fold over onto themselves (%1); undo, or pin or "
                  "move differently.",
                  nullptr, static_cast<int>(report.foldedOver.size()))
                   .arg(patchList(report.foldedOver));
    }
    if (!report.overlapping.isEmpty()) {
        return QLatin1Char(' ') +
               tr("Check the shape: the development overlaps itself at %n patch(es) (%1); undo, "
                  "or pin or move differently.",
                  nullptr, static_cast<int>(report.overlapping.size()))
                   .arg(patchList(report.overlapping));
    }
    return {};
}

QString SolveController::failedSentence(const QString& error) const {
    if (m_job) {
        return tr("%1 failed: %2 The design is unchanged.").arg(m_editTitle, error);
    }
    return m_editSurface >= 0 ? tr("%1 failed: %2 Nothing moved.").arg(m_editTitle, error)
                              : tr("Solve failed: %1 The design is unchanged.").arg(error);
}

void SolveController::cancel(const QString& reason) {
    if (!m_solving) {
        return;
    }
    m_worker->cancel();
    stop(nullptr, m_cancelledByChange ? Ending::CancelledByChange : Ending::Cancelled,
         cancelledSentence(reason));
    m_cancelledByChange = false;
}

void SolveController::stop(const SolveReport* report, Ending ending, const QString& sentence) {
    m_ending = ending;
    m_solving = false;
    if (report != nullptr) {
        // Once the design shows the result (its step pushed, or nothing changed): the Solver
        // panel files the report under that undo state.
        emit reportReady(*report);
    }
    emit busyChanged(false);
    emit finished(sentence);
}

void SolveController::onDocumentChanged() {
    if (m_solving && !m_applying && m_workspace->document()->revision() != m_revision) {
        m_cancelledByChange = true;
        cancel(tr("the design changed"));
    }
}

void SolveController::onResult(const solver::SolveResult& result) {
    if (result.ticket != m_ticket || !m_solving || result.revision != m_revision) {
        return; // a drag's result, or one of a solve that was cancelled or superseded
    }
    const QString title = m_editSurface >= 0 || m_job ? m_editTitle : tr("Solve");
    const SolveReport report = reportOf(result, title);
    const solver::JobOutcome& outcome = result.outcome;
    if (outcome.cancelled()) {
        stop(&report, Ending::Cancelled, cancelledSentence(QString()));
        return;
    }
    if (!outcome.ok) {
        stop(&report, Ending::Failed, failedSentence(failureText(outcome.failure)));
        return;
    }
    if (m_editSurface >= 0) {
        applyEdit(result, report);
        return;
    }
    if (m_job) {
        if (m_workspace->document()->revision() != result.revision) {
            stop(nullptr, Ending::Discarded,
                 tr("%1 discarded: the design changed meanwhile; it is unchanged.").arg(title));
            return;
        }
        emit jobDone(result); // still busy: the caller ends it with finishJob()
        return;
    }
    document::Document* doc = m_workspace->document();
    if (doc->revision() != result.revision ||
        outcome.surfaces.size() != static_cast<std::size_t>(doc->surfaceCount())) {
        stop(nullptr, Ending::Discarded,
             tr("Solve result discarded: the design changed while solving."));
        return;
    }
    // Every surface's command is made before any is pushed: one refused (the solved shape
    // does not validate) leaves the design as it was.
    std::vector<std::unique_ptr<QUndoCommand>> commands;
    int keptCount = 0;
    double before = 0.0;
    double after = 0.0;
    for (std::size_t s = 0; s < outcome.surfaces.size(); ++s) {
        if (const auto& kept = outcome.assessments[s].keptAsItWas) {
            ++keptCount;
            before = std::max(before, kept->before);
            after = std::max(after, kept->after);
            continue;
        }
        if (outcome.surfaces[s] == doc->surface(static_cast<int>(s))) {
            continue; // nothing changed: no undo step
        }
        document::CommandOrError edit = document::ApplySurfaceCommand::create(
            *doc, static_cast<int>(s), outcome.surfaces[s], title);
        if (edit.isRefused()) {
            stop(&report, Ending::Failed,
                 tr("Solve failed: %1 The design is unchanged.").arg(refusalText(edit)));
            return;
        }
        commands.push_back(edit.takeCommand());
    }
    if (keptCount > 0) {
        if (commands.empty()) {
            stop(&report, Ending::LeftAsItWas,
                 tr("Solve left the design as it was: solving made it less developable (largest "
                    "developability residual %1 → %2).")
                     .arg(QString::number(before, 'e', 1), QString::number(after, 'e', 1)));
            return;
        }
    }
    if (!commands.empty()) {
        m_applying = true;
        QUndoStack* stack = doc->undoStack();
        stack->beginMacro(title);
        for (auto& command : commands) {
            stack->push(command.release());
        }
        stack->endMacro();
        m_applying = false;
    }
    const double residual = outcome.largestResidual();
    const int iterations = outcome.largestIterationCount();
    // The verdict first: what the designer can do with the result; then the numbers.
    const QString verdict = VerdictText::brief(report.verdict);
    QString sentence =
        tr("Solved: %n iteration(s), largest constraint residual %1.", nullptr, iterations)
            .arg(QString::number(residual, 'e', 2));
    if (!verdict.isEmpty()) {
        sentence = tr("%1. %2", "a verdict, then a sentence").arg(verdict, sentence);
    }
    if (keptCount > 0) {
        sentence += QLatin1Char(' ') +
                    tr("%n surface(s) left as they were: solving made them less developable.",
                       nullptr, keptCount);
    }
    stop(&report, Ending::Solved, sentence + checkShapeSentence(report));
}

void SolveController::applyEdit(const solver::SolveResult& result, const SolveReport& report) {
    document::Document* doc = m_workspace->document();
    const auto s = static_cast<std::size_t>(m_editSurface);
    const solver::JobOutcome& outcome = result.outcome;
    if (doc->revision() != result.revision || s >= outcome.surfaces.size()) {
        stop(nullptr, Ending::Discarded,
             tr("%1 discarded: the design changed while solving; nothing moved.").arg(m_editTitle));
        return;
    }
    const solver::SurfaceAssessment& assessment = outcome.assessments[s];
    if (assessment.takenBack) {
        // The job refused the result (broken, or not developable from its held sheet):
        // nothing moves.
        stop(&report, Ending::LeftAsItWas,
             tr("%1 not applied: the motion %2; the design is unchanged.")
                 .arg(m_editTitle, takenBackText(*assessment.takenBack)));
        return;
    }
    model::CompositeSurface solved = outcome.surfaces[s];
    // The moved vertices arrive within ~1e-13 mm and are put exactly where the edit put them;
    // on a surface that holds its sheet they stay where the sheet let them (they lag where it
    // cannot follow, and moving them on would stretch it).
    const bool sheetHeld = solved.keepsDevelopment();
    if (!sheetHeld) {
        for (const auto& [v, target] : m_heldTargets) {
            solved.moveVertex(v, target);
        }
    }
    const solver::Summary& summary = assessment.summary;
    QString sentence =
        tr("%1, kept developable: %n iteration(s), largest constraint residual %2.", nullptr,
           summary.iterationsCompleted)
            .arg(m_editTitle, QString::number(summary.finalMaxConstraintResidual, 'e', 2));
    // The verdict first, as after Solve: a result short of the tolerance says so.
    if (const QString verdict = VerdictText::brief(report.verdict); !verdict.isEmpty()) {
        sentence = tr("%1. %2", "a verdict, then a sentence").arg(verdict, sentence);
    }
    if (sheetHeld && assessment.largestHandleGap > solver::kNegligibleLag) {
        sentence += QLatin1Char(' ') + tr("The sheet held the moved vertices back by up to %1 mm.")
                                           .arg(lagText(assessment.largestHandleGap));
    }
    sentence += checkShapeSentence(report);
    if (solved == doc->surface(m_editSurface)) {
        stop(&report, Ending::Solved, sentence); // nothing moved: no undo step, not modified
        return;
    }
    document::CommandOrError edit =
        document::ApplySurfaceCommand::create(*doc, m_editSurface, solved, m_editTitle);
    if (edit.isRefused()) {
        stop(&report, Ending::Failed, failedSentence(refusalText(edit)));
        return;
    }
    m_applying = true;
    doc->undoStack()->push(edit.takeCommand().release());
    m_applying = false;
    stop(&report, Ending::Solved, sentence);
}

} // namespace devsurf::app
