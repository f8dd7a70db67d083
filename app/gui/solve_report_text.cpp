// The Solver panel's and the status bar's words for a job's outcome: SolveController's report
// (reportOf) and the sentences it is built from. Split from solve_controller.cpp, which runs
// the jobs.
#include "problem_text.h"
#include "sheet_text.h"
#include "solve_controller.h"

#include "solver/session/drag_lengths.h"
#include "solver/session/solve_session.h"
#include "solver/session/verdict.h"
#include "solver/worker/solver_worker.h"

#include <QStringList>

#include <algorithm>
#include <cmath>

namespace devsurf::app {

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

QString SolveController::takenBackText(const solver::SurfaceAssessment& refused) {
    const solver::BrokenBy by = solver::brokenBy(refused);
    QStringList parts;
    if (by.worstFace) {
        parts << tr("did not reach the tolerance (residual %1; patch %2 sampled %3 from "
                    "developable)")
                     .arg(QString::number(refused.summary.finalMaxConstraintResidual, 'e', 1))
                     .arg(by.worstFace->first)
                     .arg(QString::number(by.worstFace->second, 'e', 1));
    }
    if (by.offSheet) {
        parts << tr("left its kept sheet by %1 mm")
                     .arg(QString::number(refused.sheetStretchMm, 'g', 2));
    }
    if (by.foldOverPlaces > 0) {
        parts << tr("folded over in %n place(s)", nullptr, by.foldOverPlaces);
    }
    if (!refused.overlapping.empty()) {
        parts << tr("left a development overlapping itself at %n patch(es)", nullptr,
                    static_cast<int>(refused.overlapping.size()));
    }
    if (!refused.summary.toleranceReached &&
        refused.edgeLengthError > solver::kDragConvergedResidual) {
        // Beyond 100 % the figure says nothing a designer can use.
        parts << (refused.edgeLengthError < 1.0
                      ? tr("would stretch its sheet by %1 % to lie flat")
                            .arg(QString::number(100.0 * refused.edgeLengthError, 'g', 2))
                      : tr("would not lie flat as one sheet"));
    }
    if (parts.isEmpty()) {
        parts << tr("ended not developable");
    }
    return parts.join(QStringLiteral(", "));
}

QString SolveController::lagText(double mm) {
    return mm < 1.0 ? QString::number(mm, 'g', 2) : QString::number(mm, 'f', 1);
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

QString SolveController::failureText(const solver::JobFailure& failure) {
    const QString surface = tr("Surface %1").arg(failure.surface + 1);
    QString text;
    switch (failure.error) {
    case solver::JobError::None:
    case solver::JobError::Cancelled:
        return tr("The solve was cancelled.");
    case solver::JobError::CannotSolve:
        text = failure.problem
                   ? tr("%1 cannot be solved: %2").arg(surface, ProblemText::of(*failure.problem))
                   : tr("%1 cannot be solved.").arg(surface);
        break;
    case solver::JobError::TargetNotFinite:
        text = failure.vertex != model::kInvalidId
                   ? tr("The drag target of vertex %1 is not a finite point.").arg(failure.vertex)
                   : tr("The drag target of control point %1 of edge %2 is not a finite point.")
                         .arg(failure.index)
                         .arg(failure.edge);
        break;
    case solver::JobError::SolverFailed:
        text = failure.status == solver::Status::FactorizationFailed
                   ? tr("%1 could not be solved: the linear system could not be factorised.")
                         .arg(surface)
                   : tr("%1 could not be solved: an iteration gave values that are not finite.")
                         .arg(surface);
        break;
    case solver::JobError::NotFinite:
        text = tr("%1 could not be solved: the solver produced a value that is not finite.")
                   .arg(surface);
        break;
    }
    if (!failure.detail.empty()) {
        // The solver's technical note, untranslated, for a support request.
        text += QLatin1Char(' ') + tr("(Solver: %1)").arg(QString::fromStdString(failure.detail));
    }
    return text;
}

SolveReport SolveController::reportOf(const solver::SolveResult& result, const QString& title) {
    const solver::JobOutcome& outcome = result.outcome;
    SolveReport report;
    report.title = title;
    report.outcome = outcome;
    report.elapsedMs = outcome.elapsedMs;
    for (const solver::SurfaceAssessment& a : outcome.assessments) {
        // A drag taken back whole lists the iterations of the refused release (the press has
        // none); one that follows part of the way those that settled the state it keeps.
        report.summaries.push_back(a.takenBack && a.followed <= 0.0 ? a.takenBack->summary
                                                                    : a.summary);
    }
    if (outcome.cancelled()) {
        report.status = tr("Cancelled; the design is unchanged.");
        return report;
    }
    if (!outcome.ok) {
        report.status = tr("Failed: %1").arg(failureText(outcome.failure));
        return report;
    }
    QStringList statuses;
    for (std::size_t s = 0; s < outcome.assessments.size(); ++s) {
        const solver::SurfaceAssessment& a = outcome.assessments[s];
        if (!a.solved) {
            continue; // a drag leaves surfaces without handles alone
        }
        const solver::Summary& summary = a.summary;
        const int surface = static_cast<int>(s);
        QString status;
        switch (summary.status) {
        case solver::Status::Converged:
            status = tr("converged");
            break;
        case solver::Status::IterationLimit:
            if (summary.toleranceReached) {
                status = tr("tolerance reached");
            } else if (a.stalledAfter > 0) {
                // A held settling that stopped before its limit (SolveSession::stalled).
                status = tr("stopped after %1 iterations, the residual no longer falling")
                             .arg(a.stalledAfter);
            } else {
                status = tr("iteration limit reached");
            }
            break;
        case solver::Status::StoppedBeforeDegenerate:
            status = tr("stopped at the last valid state, before a ruling, curve or patch "
                        "collapsed");
            break;
        default:
            status = tr("failed");
            break;
        }
        if (a.bestIteration > 0) {
            status += tr(" (ended on iteration %1, the one with the smallest residual)")
                          .arg(a.bestIteration);
        }
        if (a.keptAsItWas) {
            status += tr("; left as it was, since solving made it less developable "
                         "(%1 → %2)")
                          .arg(QString::number(a.keptAsItWas->before, 'e', 1),
                               QString::number(a.keptAsItWas->after, 'e', 1));
        }
        if (a.settledAgain) {
            status += tr("; settled a second time, since the first settling after the release "
                         "did not converge");
        }
        if (a.replay && a.replay->taken) {
            status += tr("; keeping lengths failed (%1), so the drag was replayed letting "
                         "the sheet stretch")
                          .arg(problemsText(a.replay->keepingLengths));
        }
        if (a.held) {
            status += heldText(*a.held);
        }
        if (a.takenBack && a.followed > 0.0) {
            // The design follows the start of the drag that ends well; the rest is refused.
            status = tr("followed %1 % of the drag and held back %2 mm, since the whole drag "
                        "%3: the design stays at its last developable state")
                         .arg(QString::number(std::round(100.0 * a.followed)))
                         .arg(QString::number(a.largestHandleGap, 'f', 1))
                         .arg(takenBackText(*a.takenBack));
        } else if (a.takenBack && outcome.kind == solver::JobKind::Edit) {
            status = tr("not applied, since the motion %1: the design stays as it was")
                         .arg(takenBackText(*a.takenBack));
        } else if (a.takenBack) {
            // The design is as at the press: what the refused iterations reached is the news.
            status = tr("taken back to where the drag started, since the drag %1: the design "
                        "stays at its last developable state")
                         .arg(takenBackText(*a.takenBack));
        } else if (a.sheetHeld && a.largestHandleGap > solver::kNegligibleLag) {
            status += tr("; held back %1 mm by the sheet").arg(lagText(a.largestHandleGap));
        }
        if (!a.tautPins.empty()) {
            status += QStringLiteral("; ") +
                      SheetText::tautPins(a.tautPins.front().first, a.tautPins.front().second);
        }
        QList<int> folded;
        for (const auto& [face, places] : a.foldOvers) {
            (void)places;
            folded << static_cast<int>(face);
            report.patchesToCheck.insert({document::Pick::Kind::Face, surface, face});
        }
        if (!folded.isEmpty()) {
            // Every condition may hold and the surface still overlap itself (e.g. a flat
            // design pushed within its plane): said, not hidden.
            status += tr("; %n patch(es) fold over onto themselves, where the surface "
                         "overlaps itself: %1",
                         nullptr, static_cast<int>(folded.size()))
                          .arg(patchList(folded));
        }
        report.foldedOver << folded;
        if (a.creases.creases > 0) {
            report.creaseResidual = std::max(report.creaseResidual, a.creases.residualMax);
        }
        if (!a.overlapping.empty()) {
            QList<int> overlapping;
            for (model::FaceId face : a.overlapping) {
                overlapping << static_cast<int>(face);
                report.patchesToCheck.insert({document::Pick::Kind::Face, surface, face});
            }
            status += tr("; the development overlaps itself at %n patch(es) (%1) and cannot be "
                         "cut from one sheet",
                         nullptr, static_cast<int>(overlapping.size()))
                          .arg(patchList(overlapping));
            report.overlapping << overlapping;
        }
        statuses << (outcome.assessments.size() > 1 ? tr("surface %1 %2").arg(s + 1).arg(status)
                                                    : status);
        for (std::size_t i = 0; i < std::min<std::size_t>(3, a.worstFaces.size()); ++i) {
            const auto& [face, residual] = a.worstFaces[i];
            report.worstFaces
                << tr("patch %1: %2").arg(face).arg(QString::number(residual, 'e', 1));
            report.patchesToCheck.insert({document::Pick::Kind::Face, surface, face});
        }
    }
    report.verdict = solver::verdictOf(outcome);
    report.status = statuses.isEmpty() ? tr("nothing was solved.")
                                       : statuses.join(QStringLiteral("; ")) + QLatin1Char('.');
    return report;
}

} // namespace devsurf::app
