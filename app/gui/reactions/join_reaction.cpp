#include "join_reaction.h"

#include "../edit_refusal.h"
#include "../solve_controller.h"
#include "../workspace.h"
#include "background_read.h"
#include "model/document/commands/join_surfaces_command.h"
#include "model/document/document.h"
#include "model/document/selection.h"
#include "problem_text.h"
#include "solver/session/join_job.h"
#include "solver/worker/solver_worker.h"

#include <QAction>
#include <QLocale>
#include <QUndoCommand>

#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

namespace devsurf::app {

// One join, shared with the thinning thread, which writes only `target`, `rho` and
// `thinningFailure`.
struct JoinReaction::Run {
    quint64 revision = 0;                      // of the design the join started from
    std::vector<int> indices;                  // the surfaces to join, ascending
    std::vector<model::ReferenceShape> shapes; // the design's (none: the pairing alone)
    std::shared_ptr<const model::reference::ThinningResult> target;
    double rho = 0.0;
    std::optional<std::string> thinningFailure; // thinning threw: why
    quint64 ticket = 0;
};

namespace {

QString joinTitle() {
    return JoinReaction::tr("Join Surfaces");
}

// The surfaces with a selected vertex, edge or patch when at least two have one; else all.
std::vector<int> surfacesToJoin(const Workspace& workspace) {
    std::set<int> selected;
    for (const document::Pick& pick : workspace.selection()->picks()) {
        selected.insert(pick.surface);
    }
    if (selected.size() >= 2) {
        return {selected.begin(), selected.end()};
    }
    std::vector<int> all;
    for (int s = 0; s < workspace.document()->surfaceCount(); ++s) {
        all.push_back(s);
    }
    return all;
}

} // namespace

JoinReaction::JoinReaction(QAction* action, Workspace* workspace, SolveController* solve)
    : Reaction(action, workspace), m_solve(solve) {
    connect(m_solve, &SolveController::jobDone, this, &JoinReaction::onJobDone);
    connect(m_solve, &SolveController::finished, this, &JoinReaction::onControllerFinished);
    connect(m_solve, &SolveController::busyChanged, this, [this] { updateEnableState(); });
    followDocumentAndSelection();
}

JoinReaction::~JoinReaction() {
    delete m_thinning; // cancels the thinning and waits for it
}

void JoinReaction::updateEnableState() {
    const bool enough = workspace()->document()->surfaceCount() >= 2;
    const bool busy = isBusy() || m_solve->isSolving();
    action()->setEnabled(enough && !busy);
    const QString tip =
        !enough ? tr("Join surfaces into one composite where their boundary edges face each "
                     "other: the design needs at least two surfaces.")
        : busy  ? tr("Join surfaces into one composite: wait until the solver has finished, or "
                      "cancel it (Esc).")
                : tr("Join the selected surfaces (all when fewer than two are selected) into one "
                      "composite: boundary curves or rulings that face each other become shared "
                      "edges, held to the reference shapes where there are any; one undo step.");
    action()->setToolTip(tip);
    action()->setStatusTip(tip);
}

void JoinReaction::onTriggered() {
    const document::Document* doc = workspace()->document();
    if (!action()->isEnabled() || isBusy() || m_solve->isSolving()) {
        return;
    }
    auto run = std::make_shared<Run>();
    run->revision = doc->revision();
    run->indices = surfacesToJoin(*workspace());
    run->shapes = doc->project().referenceShapes;
    m_run = run;
    updateEnableState();
    if (run->shapes.empty()) {
        runJob();
        return;
    }
    m_thinning = new BackgroundRead(
        workspace()->window(), tr("Preparing the join: thinning the reference shapes…"),
        joinTitle(), QStringLiteral("joinThinningProgress"),
        [run](const BackgroundRead::Progress& progress) {
            try {
                const std::optional<solver::ThinnedTarget> thinned = solver::thinReferenceShapes(
                    run->shapes, [&](std::size_t done, std::size_t total) {
                        return progress(total > 0 ? static_cast<double>(done) / total : 0.0);
                    });
                if (thinned && !thinned->thinned.cancelled) {
                    run->target =
                        std::make_shared<const model::reference::ThinningResult>(thinned->thinned);
                    run->rho = thinned->rho;
                }
            } catch (const std::exception& e) {
                run->thinningFailure = e.what(); // the model's own words
            }
        },
        this);
    connect(m_thinning, &BackgroundRead::done, this, &JoinReaction::onThinned);
}

void JoinReaction::onThinned() {
    const bool cancelled = m_thinning->wasCancelled();
    m_thinning->deleteLater();
    m_thinning = nullptr;
    if (m_run->thinningFailure) {
        const QString sentence =
            tr("The reference shapes could not be thinned for the join (%1); nothing was joined.")
                .arg(QString::fromStdString(*m_run->thinningFailure));
        workspace()->showError(tr("Cannot join the surfaces"), sentence);
        end(false, sentence);
        return;
    }
    if (cancelled || !m_run->target) {
        end(false, tr("Join cancelled; the design is unchanged."));
        return;
    }
    if (workspace()->document()->revision() != m_run->revision) {
        end(false, tr("Join discarded: the design changed meanwhile; it is unchanged."));
        return;
    }
    runJob();
}

void JoinReaction::runJob() {
    const document::Document* doc = workspace()->document();
    solver::JobRequest request;
    request.kind = solver::JobKind::Join;
    for (int index : m_run->indices) {
        request.surfaces.push_back(doc->surface(index));
    }
    request.joinTarget = m_run->target;
    request.joinRho = m_run->rho;
    m_run->ticket = m_solve->runJob(std::move(request), joinTitle());
}

void JoinReaction::onJobDone(const solver::SolveResult& result) {
    if (!m_run || m_run->ticket == 0 || result.ticket != m_run->ticket) {
        return;
    }
    Run& run = *m_run;
    run.ticket = 0; // ending: onControllerFinished() leaves it to end()
    const solver::JobOutcome& outcome = result.outcome;
    SolveReport report = SolveController::reportOf(result, joinTitle());
    const solver::JoinReport& join = *outcome.join;
    const int count = static_cast<int>(run.indices.size());
    if (join.separations.empty()) {
        const QString sentence =
            tr("No two of the %n surface(s) have boundary edges facing each other (within %1 % "
               "of their length); nothing was joined.",
               nullptr, count)
                .arg(QLocale().toString(solver::kJoinReach * 100.0));
        report.status = sentence;
        m_solve->finishJob(SolveController::Ending::LeftAsItWas, report, sentence);
        end(false, sentence);
        return;
    }
    // The surfaces the job joined (those facing no other are left as they are).
    std::vector<int> joined;
    for (int k : join.joined) {
        joined.push_back(run.indices[static_cast<std::size_t>(k)]);
    }
    document::CommandOrError edit = document::JoinSurfacesCommand::create(
        *workspace()->document(), joined, outcome.surfaces.front(), joinTitle());
    if (edit.isRefused()) {
        const QString sentence =
            tr("%1 failed: %2 The design is unchanged.").arg(joinTitle(), refusalText(edit));
        m_solve->finishJob(SolveController::Ending::Failed, report, sentence);
        end(false, sentence);
        return;
    }
    const solver::SurfaceAssessment& a = outcome.assessments.front();
    const QString residual = QString::number(a.summary.finalMaxConstraintResidual, 'e', 2);
    const int pairs = static_cast<int>(join.separations.size());
    QString sentence =
        tr("Joined %n surface(s) into one: ", nullptr, static_cast<int>(joined.size())) +
        tr("%1 of %n pair(s) of facing edges welded", nullptr, pairs).arg(join.welded) +
        (join.parts > 1 ? tr(", %n part(s) not connected", nullptr, join.parts) : QString()) +
        QStringLiteral("; ") +
        (a.summary.toleranceReached
             ? tr("largest constraint residual %1, within the tolerance.").arg(residual)
             : tr("largest constraint residual %1, not within the tolerance (Tools ▸ Solve may "
                  "help).")
                   .arg(residual));
    for (const model::Problem& problem : join.refused) {
        sentence += QLatin1Char(' ') + tr("Not welded: %1").arg(ProblemText::of(problem));
    }
    if (joined.size() < run.indices.size()) {
        sentence +=
            QLatin1Char(' ') + tr("%n surface(s) facing no other were left as they are.", nullptr,
                                  static_cast<int>(run.indices.size() - joined.size()));
    }
    if (join.pulledToReference) {
        sentence +=
            QLatin1Char(' ') + tr("The surfaces were held to the reference shape meanwhile.");
    }
    report.status = sentence;
    std::vector<std::unique_ptr<QUndoCommand>> commands;
    commands.push_back(edit.takeCommand());
    m_solve->finishJob(SolveController::Ending::Solved, report, sentence, std::move(commands));
    end(true, sentence);
}

void JoinReaction::onControllerFinished(const QString& sentence) {
    // The controller ended our job itself: cancelled, failed, or discarded after an edit.
    if (m_run && m_run->ticket != 0 && m_solve->runningTicket() == 0) {
        end(false, sentence);
    }
}

void JoinReaction::end(bool applied, const QString& sentence) {
    m_run.reset();
    updateEnableState();
    emit workspace()->statusMessage(sentence);
    emit finished(applied, sentence);
}

} // namespace devsurf::app
