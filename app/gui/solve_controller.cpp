#include "solve_controller.h"

#include "model/document/commands/apply_surface_command.h"
#include "model/document/document.h"
#include "solver/quality/quality_measures.h"
#include "solver/quality/shape_change.h"
#include "solver/session/solve_session.h"
#include "solver/worker/solver_worker.h"
#include "workspace.h"

#include <QSettings>
#include <QUndoStack>
#include <QVariant>

#include <algorithm>

namespace devsurf::app {

namespace {

// "1, 2, 6" for the patches a report names.
QString patchList(const QList<int>& faces) {
    QStringList patches;
    for (int face : faces) {
        patches << QString::number(face);
    }
    return patches.join(QStringLiteral(", "));
}

} // namespace

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
    const document::Document* doc = m_workspace->document();
    if (doc->surfaceCount() == 0) {
        emit finished(tr("There is nothing to solve."));
        return;
    }
    solver::SolveRequest request;
    request.revision = doc->revision();
    request.surfaces = doc->project().surfaces;
    request.iterations = iterationsSetting();
    request.sessionKey = 0;
    m_revision = request.revision;
    m_sessionKey = 0;
    m_editSurface = -1;
    m_worker->submit(std::move(request));
    if (!m_solving) {
        m_solving = true;
        emit busyChanged(true);
    }
}

void SolveController::solveEdit(int surfaceIndex, model::CompositeSurface edited,
                                const std::set<model::VertexId>& held, const QString& title,
                                int iterations) {
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
    // Edits get keys of their own: only the edited surface is solved, from the snapshot.
    static quint64 editKey = 0x45444954'00000000ULL;
    solver::SolveRequest request;
    request.revision = doc->revision();
    request.surfaces = doc->project().surfaces;
    request.pulled[surfaceIndex] = handles;
    request.iterations = iterations + 1; // the step to the targets, then `iterations` more
    request.sessionKey = ++editKey;
    m_revision = request.revision;
    m_sessionKey = request.sessionKey;
    m_editSurface = surfaceIndex;
    m_editTitle = title;
    m_worker->submit(std::move(request));
    if (!m_solving) {
        m_solving = true;
        emit busyChanged(true);
    }
}

QString SolveController::cancelledSentence(const QString& reason) const {
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
    return m_editSurface >= 0 ? tr("%1 failed: %2 Nothing moved.").arg(m_editTitle, error)
                              : tr("Solve failed: %1 The design is unchanged.").arg(error);
}

void SolveController::cancel(const QString& reason) {
    if (!m_solving) {
        return;
    }
    m_worker->cancel();
    stop(cancelledSentence(reason));
}

void SolveController::stop(const QString& sentence) {
    m_solving = false;
    emit busyChanged(false);
    emit finished(sentence);
}

void SolveController::onDocumentChanged() {
    if (m_solving && !m_applying && m_workspace->document()->revision() != m_revision) {
        cancel(tr("the design changed"));
    }
}

QString SolveController::problemsText(const solver::DragOutcome& outcome) {
    QStringList parts;
    if (outcome.stopped) {
        parts << tr("it stopped before a degenerate shape");
    }
    if (outcome.residual > solver::kDragConvergedResidual) {
        parts << tr("no convergence, residual %1").arg(QString::number(outcome.residual, 'e', 1));
    }
    if (outcome.foldOverPlaces > 0) {
        parts << tr("folded over in %n place(s)", nullptr, outcome.foldOverPlaces);
    }
    if (!outcome.overlapping.empty()) {
        parts << tr("a development overlapping itself");
    }
    if (outcome.collapsed()) {
        parts << tr("collapsed strips");
    }
    if (!outcome.measurable) {
        parts << tr("a shape too degenerate to measure");
    }
    return parts.join(QStringLiteral(", "));
}

QString SolveController::heldText(const model::HeldVertex& held) {
    if (held.pins.size() == 2) {
        return tr("; vertex %1 lies on the straight line between the pinned vertices %2 and %3, "
                  "which are as far apart as in the flat sheet, so bending cannot move it: the "
                  "sheet stretched")
            .arg(held.vertex)
            .arg(held.pins[0])
            .arg(held.pins[1]);
    }
    return tr("; vertex %1 lies inside the triangle of the pinned vertices %2, %3 and %4, which "
              "are as far apart as in the flat sheet, so bending cannot move it: the sheet "
              "stretched")
        .arg(held.vertex)
        .arg(held.pins[0])
        .arg(held.pins[1])
        .arg(held.pins[2]);
}

SolveReport SolveController::reportOf(const solver::SolveResult& result,
                                      const QString& title) const {
    SolveReport report;
    report.title = title;
    report.elapsedMs = result.elapsedMs;
    report.summaries = result.summaries;
    if (result.cancelled) {
        report.status = tr("Cancelled; the design is unchanged.");
        return report;
    }
    if (!result.ok) {
        report.status = tr("Failed: %1").arg(result.error);
        return report;
    }
    QStringList statuses;
    for (std::size_t s = 0; s < result.summaries.size(); ++s) {
        const solver::Summary& summary = result.summaries[s];
        if (summary.iterations.empty() && summary.message.empty()) {
            continue; // not solved (a drag leaves surfaces without handles alone)
        }
        QString status;
        switch (summary.status) {
        case solver::Status::Converged:
            status = tr("converged");
            break;
        case solver::Status::IterationLimit:
            status =
                summary.toleranceReached ? tr("tolerance reached") : tr("iteration limit reached");
            break;
        case solver::Status::Cancelled:
            status = tr("cancelled");
            break;
        case solver::Status::StoppedBeforeDegenerate:
            status = tr("stopped at the last valid state");
            break;
        default:
            status = tr("failed");
            break;
        }
        if (!summary.message.empty()) {
            // The solver's sentence without its full stop: the status goes on after it.
            QString message = QString::fromStdString(summary.message);
            if (message.endsWith(QLatin1Char('.'))) {
                message.chop(1);
            }
            status += tr(" (%1)").arg(message);
        }
        for (const solver::SolveResult::Kept& kept : result.kept) {
            if (kept.surface == static_cast<int>(s)) {
                status += tr("; left as it was, since solving made it less developable "
                             "(%1 → %2)")
                              .arg(QString::number(kept.before, 'e', 1),
                                   QString::number(kept.after, 'e', 1));
            }
        }
        for (const solver::SolveResult::Stretched& stretched : result.stretched) {
            if (stretched.surface == static_cast<int>(s)) {
                status += tr("; keeping lengths failed (%1), so the drag was replayed letting "
                             "the sheet stretch")
                              .arg(problemsText(stretched.keepingLengths));
            }
        }
        for (const solver::SolveResult::Held& held : result.held) {
            if (held.surface == static_cast<int>(s)) {
                status += heldText(held.held);
            }
        }
        if (s < result.surfaces.size()) {
            // A result that folds over onto itself satisfies the conditions but is no surface
            // a sheet can take (e.g. a flat design pushed within its plane): said, not hidden.
            QList<int> folded;
            for (const auto& [face, places] : solver::foldOvers(result.surfaces[s])) {
                (void)places;
                folded << static_cast<int>(face);
                report.patchesToCheck.insert(
                    {document::Pick::Kind::Face, static_cast<int>(s), face});
            }
            if (!folded.isEmpty()) {
                status += tr("; %n patch(es) fold over onto themselves, where the surface "
                             "overlaps itself: %1",
                             nullptr, static_cast<int>(folded.size()))
                              .arg(patchList(folded));
            }
            report.foldedOver << folded;
        }
        if (s < result.creaseResiduals.size()) {
            report.creaseResidual = std::max(report.creaseResidual, result.creaseResiduals[s]);
        }
        if (s < result.selfOverlaps.size() && !result.selfOverlaps[s].empty()) {
            // Every condition may hold and the development still overlap itself, e.g. where a
            // patch was turned over in the plane: such a design cannot be cut from one sheet.
            QList<int> overlapping;
            for (model::FaceId face : result.selfOverlaps[s]) {
                overlapping << static_cast<int>(face);
                report.patchesToCheck.insert(
                    {document::Pick::Kind::Face, static_cast<int>(s), face});
            }
            status += tr("; the development overlaps itself at %n patch(es) (%1) and cannot be "
                         "cut from one sheet",
                         nullptr, static_cast<int>(overlapping.size()))
                          .arg(patchList(overlapping));
            report.overlapping << overlapping;
        }
        statuses << (result.summaries.size() > 1 ? tr("surface %1 %2").arg(s + 1).arg(status)
                                                 : status);
        if (!summary.toleranceReached && s < result.surfaces.size()) {
            const auto faces = solver::developabilityByFace(result.surfaces[s]);
            for (std::size_t i = 0; i < std::min<std::size_t>(3, faces.size()); ++i) {
                report.worstFaces << tr("patch %1: %2")
                                         .arg(faces[i].first)
                                         .arg(QString::number(faces[i].second, 'e', 1));
                report.patchesToCheck.insert(
                    {document::Pick::Kind::Face, static_cast<int>(s), faces[i].first});
            }
        }
    }
    report.status = statuses.isEmpty() ? tr("nothing was solved.")
                                       : statuses.join(QStringLiteral("; ")) + QLatin1Char('.');
    return report;
}

void SolveController::onResult(const solver::SolveResult& result) {
    if (result.sessionKey != m_sessionKey || !m_solving || result.revision != m_revision) {
        return; // a drag's result, or one of a solve that was cancelled or superseded
    }
    const QString title = m_editSurface >= 0 ? m_editTitle : tr("Solve");
    const SolveReport report = reportOf(result, title);
    emit reportReady(report);
    if (result.cancelled) {
        stop(cancelledSentence(QString()));
        return;
    }
    if (!result.ok) {
        stop(failedSentence(result.error));
        return;
    }
    if (m_editSurface >= 0) {
        applyEdit(result, report);
        return;
    }
    document::Document* doc = m_workspace->document();
    if (doc->revision() != result.revision ||
        result.surfaces.size() != static_cast<std::size_t>(doc->surfaceCount())) {
        stop(tr("Solve result discarded: the design changed while solving."));
        return;
    }
    // Every surface's command is made before any is pushed: one refused (the solved shape
    // does not validate) leaves the design as it was.
    std::vector<std::unique_ptr<QUndoCommand>> commands;
    auto isKept = [&result](std::size_t s) {
        return std::any_of(result.kept.begin(), result.kept.end(),
                           [s](const auto& kept) { return kept.surface == static_cast<int>(s); });
    };
    for (std::size_t s = 0; s < result.surfaces.size(); ++s) {
        if (isKept(s)) {
            continue;
        }
        document::CommandOrError edit = document::ApplySurfaceCommand::create(
            *doc, static_cast<int>(s), result.surfaces[s], title);
        if (edit.isRefused()) {
            stop(tr("Solve failed: %1 The design is unchanged.").arg(edit.error()));
            return;
        }
        commands.push_back(edit.takeCommand());
    }
    if (!result.kept.empty()) {
        double before = 0.0;
        double after = 0.0;
        for (const auto& kept : result.kept) {
            before = std::max(before, kept.before);
            after = std::max(after, kept.after);
        }
        if (commands.empty()) {
            stop(tr("Solve left the design as it was: solving made it less developable (largest "
                    "developability residual %1 → %2).")
                     .arg(QString::number(before, 'e', 1), QString::number(after, 'e', 1)));
            return;
        }
    }
    m_applying = true;
    QUndoStack* stack = doc->undoStack();
    stack->beginMacro(title);
    for (auto& command : commands) {
        stack->push(command.release());
    }
    stack->endMacro();
    m_applying = false;
    double residual = 0.0;
    int iterations = 0;
    for (const solver::Summary& summary : result.summaries) {
        residual = std::max(residual, summary.finalMaxConstraintResidual);
        iterations = std::max(iterations, summary.iterationsCompleted);
    }
    QString sentence =
        tr("Solved: %n iteration(s), largest constraint residual %1.", nullptr, iterations)
            .arg(QString::number(residual, 'e', 2));
    if (!result.kept.empty()) {
        sentence += QLatin1Char(' ') +
                    tr("%n surface(s) left as they were: solving made them less developable.",
                       nullptr, static_cast<int>(result.kept.size()));
    }
    stop(sentence + checkShapeSentence(report));
}

void SolveController::applyEdit(const solver::SolveResult& result, const SolveReport& report) {
    document::Document* doc = m_workspace->document();
    const auto s = static_cast<std::size_t>(m_editSurface);
    if (doc->revision() != result.revision || s >= result.surfaces.size() ||
        s >= result.summaries.size()) {
        stop(tr("%1 discarded: the design changed while solving; nothing moved.").arg(m_editTitle));
        return;
    }
    model::CompositeSurface solved = result.surfaces[s];
    for (const auto& [v, target] : m_heldTargets) {
        solved.moveVertex(v, target);
    }
    document::CommandOrError edit =
        document::ApplySurfaceCommand::create(*doc, m_editSurface, solved, m_editTitle);
    if (edit.isRefused()) {
        stop(failedSentence(edit.error()));
        return;
    }
    m_applying = true;
    doc->undoStack()->push(edit.takeCommand().release());
    m_applying = false;
    const solver::Summary& summary = result.summaries[s];
    stop(tr("%1, kept developable: %n iteration(s), largest constraint residual %2.", nullptr,
            summary.iterationsCompleted)
             .arg(m_editTitle, QString::number(summary.finalMaxConstraintResidual, 'e', 2)) +
         checkShapeSentence(report));
}

} // namespace devsurf::app
