#include "approximate_reaction.h"

#include "../distance_report_dialog.h"
#include "../edit_refusal.h"
#include "../solve_controller.h"
#include "../workspace.h"
#include "background_read.h"
#include "model/document/commands/add_surfaces_command.h"
#include "model/document/commands/apply_surface_command.h"
#include "model/document/document.h"
#include "model/reference/distance_report.h"
#include "solver/session/approximation_setup.h"
#include "solver/worker/solver_worker.h"

#include <QAction>
#include <QElapsedTimer>
#include <QLocale>
#include <QThread>
#include <QUndoCommand>

#include <array>
#include <optional>
#include <stdexcept>
#include <string>

namespace devsurf::app {

// One approximation, shared with the threads of its steps: each thread writes only its own
// fields, which the GUI thread reads after the thread finished.
struct ApproximateReaction::Run {
    ApproximationChoice choice;
    quint64 revision = 0; // of the design the setup started from
    std::vector<model::Vec3> points;
    std::vector<std::array<int, 3>> triangles;  // the shape's, if a mesh
    std::vector<model::CompositeSurface> start; // empty: new strips
    int firstNumber = 1;
    solver::ApproximationSetup setup;        // the setup thread's
    std::optional<std::string> setupFailure; // the setup threw (the model's own words)
    quint64 ticket = 0;
    enum class Step { Preparing, Solving, Measuring } step = Step::Preparing;
    solver::SolveResult result;
    std::optional<model::reference::DistanceReport> distance; // the measuring thread's
    double measureMs = 0.0;
    // Set when the approximation ends before its measurement (cancelled, closed): the
    // measuring thread then stops within a few hundred points instead of measuring on.
    std::atomic<bool> stopMeasuring{false};
};

namespace {

QString title() {
    return ApproximateReaction::tr("Approximate Reference Shape");
}

} // namespace

ApproximateReaction::ApproximateReaction(QAction* action, Workspace* workspace,
                                         SolveController* solve)
    : Reaction(action, workspace), m_solve(solve) {
    connect(m_solve, &SolveController::jobDone, this, &ApproximateReaction::onJobDone);
    connect(m_solve, &SolveController::finished, this, &ApproximateReaction::onControllerFinished);
    connect(m_solve, &SolveController::busyChanged, this, [this] { updateEnableState(); });
    followDocumentAndSelection();
}

ApproximateReaction::~ApproximateReaction() {
    // Closed while working: the setup is cancelled and waited for, the measuring waited for.
    delete m_setup;
    if (m_run) {
        m_run->stopMeasuring = true;
    }
    if (m_measure != nullptr) {
        m_measure->wait();
        delete m_measure;
    }
}

bool ApproximateReaction::isBusy() const {
    // A measurement cancelled with its approximation runs to its end (measureDistance cannot
    // stop early); a new approximation waits for it.
    return m_run != nullptr || m_measure != nullptr;
}

void ApproximateReaction::updateEnableState() {
    const model::Project& project = workspace()->document()->project();
    const bool shapes = !project.referenceShapes.empty();
    const bool busy = isBusy() || m_solve->isSolving();
    action()->setEnabled(shapes && !busy);
    const QString tip =
        !shapes ? tr("Fit developable strips to a reference shape: import one first (File ▸ "
                     "Import Reference Shape…).")
        : busy  ? tr("Fit developable strips to a reference shape: wait until the solver has "
                      "finished, or cancel it (Esc).")
                : tr("Fit developable strips to a reference shape, or pull the design's surfaces "
                      "towards it; one undo step.");
    action()->setToolTip(tip);
    action()->setStatusTip(tip);
}

void ApproximateReaction::onTriggered() {
    if (!action()->isEnabled()) {
        return;
    }
    ApproximateDialog dialog(workspace()->document()->project(), workspace()->window());
    if (dialog.exec() == QDialog::Accepted) {
        start(dialog.choice());
    }
}

void ApproximateReaction::start(const ApproximationChoice& choice) {
    const document::Document* doc = workspace()->document();
    const model::Project& project = doc->project();
    if (isBusy() || m_solve->isSolving() || choice.shape < 0 ||
        static_cast<std::size_t>(choice.shape) >= project.referenceShapes.size()) {
        return;
    }
    auto run = std::make_shared<Run>();
    run->choice = choice;
    run->revision = doc->revision();
    run->points = project.referenceShapes[static_cast<std::size_t>(choice.shape)].points;
    run->triangles = project.referenceShapes[static_cast<std::size_t>(choice.shape)].triangles;
    if (!choice.newStrips) {
        run->start = project.surfaces;
    }
    run->firstNumber = doc->surfaceCount() + 1;
    m_run = run;
    m_setup = new BackgroundRead(
        workspace()->window(),
        tr("Preparing the approximation: thinning the reference shape and placing the strips…"),
        title(), QStringLiteral("approximationSetupProgress"),
        [run](const BackgroundRead::Progress& progress) {
            solver::ApproximationOptions options;
            options.strips = run->choice.strips;
            options.oneSurface = run->choice.oneSurface;
            options.intervals = run->choice.intervals;
            options.rho = run->choice.rho;
            options.iterations = run->choice.iterations;
            try {
                run->setup = solver::prepareApproximation(run->points, run->start, options,
                                                          progress, run->firstNumber);
            } catch (const std::exception& e) {
                run->setupFailure = e.what(); // e.g. a design surface that is not valid
            }
        },
        this);
    connect(m_setup, &BackgroundRead::done, this, &ApproximateReaction::onPrepared);
    updateEnableState();
}

void ApproximateReaction::onPrepared() {
    const bool cancelled = m_setup->wasCancelled();
    m_setup->deleteLater();
    m_setup = nullptr;
    Run& run = *m_run;
    using Error = solver::ApproximationSetup::Error;
    if (cancelled || run.setup.error == Error::Cancelled) {
        end(false, tr("Approximation cancelled; the design is unchanged."));
        return;
    }
    if (run.setupFailure) {
        const QString sentence = tr("The approximation could not be set up: %1")
                                     .arg(QString::fromStdString(*run.setupFailure));
        workspace()->showError(tr("Cannot approximate the reference shape"), sentence);
        end(false, sentence);
        return;
    }
    if (run.setup.error != Error::None) {
        const QString rho = DistanceReportDialog::millimetres(run.setup.target.rho);
        QString sentence;
        switch (run.setup.error) {
        case Error::TooFewPoints:
            sentence = tr("Thinning the reference shape with radius %1 kept %n point(s), too few "
                          "for the strips asked for; choose a smaller radius or fewer strips.",
                          nullptr, static_cast<int>(run.setup.target.thinned.points.size()))
                           .arg(rho);
            break;
        case Error::Collinear:
            sentence = tr("The points of the reference shape lie on a line; no strip can be "
                          "fitted to them.");
            break;
        default:
            sentence = tr("No surface of the design is near enough to the reference shape to be "
                          "pulled towards it; start from new strips instead.");
            break;
        }
        workspace()->showError(tr("Cannot approximate the reference shape"), sentence);
        end(false, sentence);
        return;
    }
    if (workspace()->document()->revision() != run.revision) {
        end(false, tr("Approximation discarded: the design changed meanwhile; it is unchanged."));
        return;
    }
    run.step = Run::Step::Solving;
    run.ticket = m_solve->runJob(run.setup.request, title());
}

void ApproximateReaction::onJobDone(const solver::SolveResult& result) {
    if (!m_run || m_run->step != Run::Step::Solving || result.ticket != m_run->ticket) {
        return;
    }
    m_run->step = Run::Step::Measuring;
    m_run->result = result;
    emit workspace()->statusMessage(
        tr("Measuring the distance of the result to the reference shape…"));
    // The distance of the result to the whole shape, as Tools ▸ Distance to Reference… measures
    // it, on a thread of its own (tens of thousands of points).
    std::shared_ptr<Run> run = m_run;
    m_measure = QThread::create([run] {
        QElapsedTimer clock;
        clock.start();
        model::reference::DistanceOptions options;
        options.cancel = &run->stopMeasuring;
        options.triangles = &run->triangles;
        try {
            run->distance = model::reference::measureDistance(run->result.outcome.surfaces,
                                                              run->points, options);
        } catch (const std::exception&) {
            run->distance.reset(); // not measurable: the sentence goes without it
        }
        run->measureMs = static_cast<double>(clock.nsecsElapsed()) / 1e6;
    });
    connect(m_measure, &QThread::finished, this, &ApproximateReaction::onMeasured);
    m_measure->start();
}

void ApproximateReaction::onMeasured() {
    m_measure->wait();
    m_measure->deleteLater();
    m_measure = nullptr;
    if (!m_run || m_solve->runningTicket() != m_run->ticket) {
        updateEnableState(); // cancelled meanwhile: onControllerFinished() ended it
        return;
    }
    Run& run = *m_run;
    document::Document* doc = workspace()->document();
    const solver::JobOutcome& outcome = run.result.outcome;
    SolveReport report = SolveController::reportOf(run.result, title());
    // Every command is made before any is pushed: one refused leaves the design as it was.
    std::vector<std::unique_ptr<QUndoCommand>> commands;
    const auto refuse = [&](const document::CommandOrError& edit) {
        const QString sentence =
            tr("%1 failed: %2 The design is unchanged.").arg(title(), refusalText(edit));
        run.step = Run::Step::Preparing; // ending: onControllerFinished() leaves it to end()
        m_solve->finishJob(SolveController::Ending::Failed, report, sentence);
        end(false, sentence);
    };
    if (run.setup.newStrips) {
        document::CommandOrError add =
            document::AddSurfacesCommand::create(*doc, outcome.surfaces, title());
        if (add.isRefused()) {
            refuse(add);
            return;
        }
        commands.push_back(add.takeCommand());
    } else {
        for (std::size_t s = 0; s < outcome.surfaces.size(); ++s) {
            if (static_cast<int>(s) >= doc->surfaceCount() ||
                outcome.surfaces[s] == doc->surface(static_cast<int>(s))) {
                continue;
            }
            document::CommandOrError edit = document::ApplySurfaceCommand::createValidated(
                *doc, static_cast<int>(s), outcome.surfaces[s], title());
            if (edit.isRefused()) {
                refuse(edit);
                return;
            }
            commands.push_back(edit.takeCommand());
        }
    }
    int solved = 0;
    int within = 0;
    int keptAsLaid = 0;
    int trimmed = 0;
    for (const solver::SurfaceAssessment& a : outcome.assessments) {
        solved += a.solved ? 1 : 0;
        within += a.solved && a.summary.toleranceReached ? 1 : 0;
        keptAsLaid += a.solved && a.approximationKeptStart ? 1 : 0;
        trimmed += a.solved && a.approximationTrim ? 1 : 0;
    }
    const int count = static_cast<int>(outcome.surfaces.size());
    // The distance first (what the designer asked for), then whether the strips are
    // developable to the solver's tolerance.
    const QString residual = QString::number(outcome.largestResidual(), 'e', 2);
    const QString developable =
        within == solved
            ? tr("largest constraint residual %1, within the tolerance").arg(residual)
            : tr("largest constraint residual %1, not within the tolerance (Tools ▸ Solve may "
                 "help)")
                  .arg(residual);
    QString sentence;
    if (run.distance) {
        const QString distance =
            tr("the reference shape is %1 from the %n surface(s) on average, %2 at most", nullptr,
               count)
                .arg(DistanceReportDialog::millimetres(run.distance->targetToSurface.mean),
                     DistanceReportDialog::millimetres(run.distance->targetToSurface.max));
        sentence = tr("Approximated: %1; %2.").arg(distance, developable);
        report.status += QLatin1Char(' ') + tr("Afterwards %1.").arg(distance);
    } else {
        sentence = tr("Approximated with %n surface(s): %1.", nullptr, count).arg(developable);
    }
    if (solved < count) {
        sentence += QLatin1Char(' ') + tr("%n surface(s) too far from the shape were left as they "
                                          "were.",
                                          nullptr, count - solved);
    }
    // How strips ended other than pulled: also in the Solver panel, as the status bar elides
    // a long sentence.
    QString how;
    if (run.setup.stripsInOneSurface > 0 && run.setup.stripsAsRings) {
        how += QLatin1Char(' ') + tr("The reference shape closes around an axis: its %n strip(s) "
                                     "were laid as rings one after another around it, one "
                                     "surface open only at its two ends.",
                                     nullptr, run.setup.stripsInOneSurface);
    } else if (run.setup.stripsInOneSurface > 0) {
        how += QLatin1Char(' ') + tr("The reference shape is one patch: its %n strip(s) were laid "
                                     "side by side as one watertight surface.",
                                     nullptr, run.setup.stripsInOneSurface);
    }
    if (trimmed > 0) {
        how +=
            QLatin1Char(' ') +
            tr("%n strip(s) were trimmed back where they stood off the shape.", nullptr, trimmed);
    }
    if (keptAsLaid > 0 && run.setup.stripsInOneSurface > 0) {
        how += QLatin1Char(' ') + tr("Pulled closer, the surface did not end developable; it was "
                                     "kept as it was laid, bent to the shape.");
    } else if (keptAsLaid > 0) {
        how += QLatin1Char(' ') +
               tr("%n strip(s) could not be pulled closer and stay developable; they were "
                  "kept as they were laid.",
                  nullptr, keptAsLaid);
    }
    sentence += how;
    report.status += how;
    // The verdict is in the Solver panel and the views' corner; the status bar keeps the
    // figures, which a verdict naming many patches would push out of sight.
    report.status +=
        QLatin1Char(' ') + tr("Set up in %1 s, solved in %2 s, measured in %3 s.")
                               .arg(QLocale().toString(run.setup.milliseconds / 1000.0, 'f', 2),
                                    QLocale().toString(outcome.elapsedMs / 1000.0, 'f', 2),
                                    QLocale().toString(run.measureMs / 1000.0, 'f', 2));
    m_timings = {run.setup.milliseconds, outcome.elapsedMs, run.measureMs};
    const bool applied = !commands.empty();
    run.step = Run::Step::Preparing; // ending: onControllerFinished() leaves it to end()
    m_solve->finishJob(SolveController::Ending::Solved, report, sentence, std::move(commands));
    end(applied, sentence);
}

void ApproximateReaction::onControllerFinished(const QString& sentence) {
    // The controller ended our job itself: cancelled, failed, or discarded after an edit.
    if (m_run && m_run->step != Run::Step::Preparing && m_solve->runningTicket() == 0) {
        end(false, sentence);
    }
}

void ApproximateReaction::end(bool applied, const QString& sentence) {
    if (m_run) {
        m_run->stopMeasuring = true; // a measurement still running is of no use now
    }
    m_run.reset();
    updateEnableState();
    emit workspace()->statusMessage(sentence);
    emit finished(applied, sentence);
}

} // namespace devsurf::app
