// Tools ▸ Approximate Reference Shape…: driven through its dialog, the job ends with strips that
// are developable (sampled here, independently of the solver) and close to the target, the same
// strips the shared setup and job give outside the window, as one undo step that undo and redo
// take back and re-apply byte for byte; Cancel and the dialog's Cancel change nothing.
#include "approximate_dialog.h"
#include "io/reference/reference_import.h"
#include "main_window.h"
#include "model/document/commands/command_or_error.h"
#include "model/document/commands/reference_shapes_command.h"
#include "model/document/document.h"
#include "model/reference/distance_report.h"
#include "model/reference/strip_rings.h"
#include "model/reference/thinning.h"
#include "model/strip_joining.h"
#include "reactions/approximate_reaction.h"
#include "sampled_developability.h"
#include "solve_controller.h"
#include "solver/session/approximation_setup.h"
#include "solver/session/solve_job.h"
#include "test_registry.h"
#include "views/surface_view.h"
#include "window_test_support.h"
#include "workspace.h"

#include <QAction>
#include <QApplication>
#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QElapsedTimer>
#include <QMessageBox>
#include <QRadioButton>
#include <QSettings>
#include <QSignalSpy>
#include <QSpinBox>
#include <QTest>
#include <QTimer>
#include <QUndoStack>

#include <algorithm>
#include <cmath>
#include <functional>

using namespace devsurf;
using model::Vec3;

namespace {

// Points on a cylinder over the parabola y = x² / 100, 100 × 60 mm (as tests/solver's
// tst_approximation): a cubic spline strip holds it exactly.
model::ReferenceShape parabolicCylinder() {
    model::ReferenceShape shape{"cylinder", "", {}, {}, {}};
    for (int i = 0; i <= 60; ++i) {
        for (int j = 0; j <= 36; ++j) {
            const double x = -50.0 + 100.0 * i / 60;
            shape.points.push_back({x, 0.01 * x * x, 60.0 * j / 36});
        }
    }
    return shape;
}

// A project holding only that reference shape (no surface: the strips are the design).
void openCylinderOnly(app::MainWindow& window) {
    model::Project project;
    project.referenceShapes.push_back(parabolicCylinder());
    window.workspace()->document()->resetProject(project);
}

// A project holding only a sphere of radius 100 (but 3° about its poles), which closes around
// an axis.
void openSphereOnly(app::MainWindow& window) {
    model::ReferenceShape sphere{"sphere", "", {}, {}, {}};
    for (int i = 0; i <= 40; ++i) {
        const double theta = 0.05 + 3.04 * i / 40;
        for (int j = 0; j < 60; ++j) {
            const double phi = 6.283185307179586 * j / 60;
            sphere.points.push_back(Vec3(std::sin(theta) * std::cos(phi),
                                         std::sin(theta) * std::sin(phi), std::cos(theta)) *
                                    100.0);
        }
    }
    model::Project project;
    project.referenceShapes.push_back(sphere);
    window.workspace()->document()->resetProject(project);
}

app::ApproximateReaction* reactionOf(app::MainWindow& window) {
    QAction* action = window.action(QStringLiteral("actionApproximateReference"));
    return action != nullptr ? action->findChild<app::ApproximateReaction*>() : nullptr;
}

// Runs `fill` on the dialog once it is open (it runs its own event loop).
void whenDialogOpens(QTimer& poll, const std::function<void(app::ApproximateDialog*)>& fill) {
    QObject::connect(&poll, &QTimer::timeout, &poll, [&poll, fill] {
        if (auto* dialog =
                qobject_cast<app::ApproximateDialog*>(QApplication::activeModalWidget())) {
            poll.stop();
            fill(dialog);
        }
    });
    poll.start(10);
}

// One strip of 4 intervals, `iterations` iterations, the default ρ.
std::function<void(app::ApproximateDialog*)> oneStrip(int iterations) {
    return [iterations](app::ApproximateDialog* dialog) {
        dialog->newStripsButton()->setChecked(true);
        dialog->stripsBox()->setValue(1);
        dialog->intervalsBox()->setValue(4);
        dialog->iterationsBox()->setValue(iterations);
        dialog->accept();
    };
}

// Three new strips of 2 intervals, 30 iterations, as one surface over a patch or not.
std::function<void(app::ApproximateDialog*)> threeStrips(bool oneSurface) {
    return [oneSurface](app::ApproximateDialog* dialog) {
        dialog->newStripsButton()->setChecked(true);
        dialog->stripsBox()->setValue(3);
        dialog->oneSurfaceBox()->setChecked(oneSurface);
        dialog->intervalsBox()->setValue(2);
        dialog->iterationsBox()->setValue(30);
        dialog->accept();
    };
}

// The dialog's "one surface" box starts checked and goes with the new strips.
bool dialogBoxDefaultsToOneSurface(app::MainWindow& window) {
    app::ApproximateDialog dialog(window.workspace()->document()->project(), &window);
    const bool checked = dialog.oneSurfaceBox()->isChecked() && dialog.choice().oneSurface;
    dialog.newStripsButton()->setChecked(false);
    dialog.designButton()->setEnabled(true);
    dialog.designButton()->setChecked(true);
    const bool followsNewStrips = !dialog.oneSurfaceBox()->isEnabled();
    return checked && followsNewStrips;
}

} // namespace

class TstApproximateGui : public QObject {
    Q_OBJECT

private slots:
    void init() { QSettings().clear(); }

    void actionNeedsAReferenceShape() {
        app::MainWindow window;
        QVERIFY(test::showActiveWithExample(window, QStringLiteral("sheet")));
        document::Document* doc = window.workspace()->document();
        QAction* approximate = window.action(QStringLiteral("actionApproximateReference"));
        QVERIFY(approximate != nullptr);
        QVERIFY(!approximate->isEnabled());
        const QString noShape = approximate->toolTip();
        QVERIFY(!noShape.isEmpty());
        document::CommandOrError add =
            document::ReferenceShapesCommand::createImport(*doc, parabolicCylinder());
        QVERIFY(document::push(*doc, add));
        QVERIFY(approximate->isEnabled());
        QVERIFY(approximate->toolTip() != noShape);
        doc->undoStack()->undo();
        QVERIFY(!approximate->isEnabled());
        QCOMPARE(approximate->toolTip(), noShape);
    }

    void dialogOffersTheDefaults() {
        app::MainWindow window;
        QVERIFY(test::showActiveWithExample(window, QStringLiteral("sheet")));
        document::Document* doc = window.workspace()->document();
        document::CommandOrError add =
            document::ReferenceShapesCommand::createImport(*doc, parabolicCylinder());
        QVERIFY(document::push(*doc, add));
        app::ApproximateDialog dialog(doc->project(), &window);
        // ρ: 2 % of the diagonal (the cloud is dense enough for that to hold a plane).
        const std::vector<Vec3>& points = doc->project().referenceShapes[0].points;
        const double diagonal = std::sqrt(100.0 * 100.0 + 25.0 * 25.0 + 60.0 * 60.0);
        QCOMPARE(dialog.defaultRho(), solver::defaultApproximationRadius(points, diagonal));
        QCOMPARE(dialog.defaultRho(),
                 std::max(0.02 * diagonal, model::reference::defaultThinningRadius(points)));
        const app::ApproximationChoice choice = dialog.choice();
        QCOMPARE(choice.rho, dialog.defaultRho()); // not the box's rounding of it
        QCOMPARE(choice.iterations, solver::kApproximationIterations);
        QVERIFY(choice.newStrips);
        QCOMPARE(choice.strips, 4);
        QVERIFY(dialog.designButton()->isEnabled()); // the sheet is a surface to start from
        QVERIFY(!dialog.shapeBox()->isEnabled());    // one shape: nothing to choose
    }

    void approximatesAsOneUndoStep() {
        app::MainWindow window;
        QVERIFY(test::showActiveWithExample(window, QStringLiteral("sheet")));
        openCylinderOnly(window);
        document::Document* doc = window.workspace()->document();
        const std::string before = test::bytesOf(window);
        const int steps = doc->undoStack()->count();
        app::ApproximateReaction* reaction = reactionOf(window);
        QVERIFY(reaction != nullptr);
        QSignalSpy finished(reaction, &app::ApproximateReaction::finished);
        QTimer poll;
        whenDialogOpens(poll, oneStrip(30));
        window.action(QStringLiteral("actionApproximateReference"))->trigger();
        QVERIFY(reaction->isBusy());
        QVERIFY(!window.action(QStringLiteral("actionApproximateReference"))->isEnabled());
        QVERIFY(finished.wait(120000));
        QVERIFY2(finished.front().at(0).toBool(), qPrintable(finished.front().at(1).toString()));
        QVERIFY(!reaction->isBusy());
        QCOMPARE(doc->undoStack()->count(), steps + 1);
        QCOMPARE(doc->surfaceCount(), 1);

        // Developable, sampled from the splines, and on the cylinder.
        const model::CompositeSurface strip = doc->surface(0);
        const double developability = test::sampledDevelopability(strip);
        QVERIFY2(developability <= 1e-8, qPrintable(QString::number(developability)));
        const std::vector<Vec3>& points = doc->project().referenceShapes[0].points;
        const model::reference::DistanceReport distance =
            model::reference::measureDistance(strip, points);
        QVERIFY2(distance.targetToSurface.max <= 1e-5 * distance.diagonal,
                 qPrintable(QString::number(distance.targetToSurface.max)));
        QCOMPARE(distance.coverage, 1.0);

        // The same strip as the shared setup and job give outside the window (the command
        // line's path), bit for bit but for the id the design gave it.
        solver::ApproximationOptions options;
        options.strips = 1;
        options.intervals = 4;
        options.iterations = 30;
        const solver::ApproximationSetup setup = solver::prepareApproximation(points, {}, options);
        QCOMPARE(setup.error, solver::ApproximationSetup::Error::None);
        solver::SolveJob job;
        const solver::JobOutcome outcome = job.run(setup.request);
        QVERIFY(outcome.ok);
        model::CompositeSurface expected = outcome.surfaces.front();
        expected.setId(strip.id());
        QVERIFY(expected == strip);

        const std::string after = test::bytesOf(window);
        doc->undoStack()->undo();
        QCOMPARE(test::bytesOf(window), before);
        QCOMPARE(doc->surfaceCount(), 0);
        doc->undoStack()->redo();
        QCOMPARE(test::bytesOf(window), after);
    }

    void stripsOverAPatchBecomeOneSurface() {
        // Three new strips over the cylinder patch (one patch seen from one side): one surface
        // of three strips added, watertight, developable, on the cylinder; the sentence says
        // so; one undo step.
        app::MainWindow window;
        QVERIFY(test::showActiveWithExample(window, QStringLiteral("sheet")));
        openCylinderOnly(window);
        document::Document* doc = window.workspace()->document();
        const int steps = doc->undoStack()->count();
        app::ApproximateReaction* reaction = reactionOf(window);
        QSignalSpy finished(reaction, &app::ApproximateReaction::finished);
        QTimer poll;
        whenDialogOpens(poll, threeStrips(true));
        window.action(QStringLiteral("actionApproximateReference"))->trigger();
        QVERIFY(finished.wait(120000));
        QVERIFY2(finished.front().at(0).toBool(), qPrintable(finished.front().at(1).toString()));
        QVERIFY2(finished.front().at(1).toString().contains(
                     QStringLiteral("its 3 strips were laid side by side as one watertight")),
                 qPrintable(finished.front().at(1).toString()));
        QCOMPARE(doc->undoStack()->count(), steps + 1);
        QCOMPARE(doc->surfaceCount(), 1);
        const model::CompositeSurface surface = doc->surface(0);
        QCOMPARE(surface.faces().size(), std::size_t(3));
        QCOMPARE(model::surfaceParts(surface).size(), std::size_t(1));
        QVERIFY(test::sampledDevelopability(surface) <= 1e-8);
        const model::reference::DistanceReport distance =
            model::reference::measureDistance(surface, doc->project().referenceShapes[0].points);
        QVERIFY2(distance.targetToSurface.mean <= 1e-3 * distance.diagonal,
                 qPrintable(QString::number(distance.targetToSurface.mean)));
        doc->undoStack()->undo();
        QCOMPARE(doc->surfaceCount(), 0);

        // Unchecked: three separate strips over patches, as over a closed shape.
        QVERIFY(dialogBoxDefaultsToOneSurface(window));
        finished.clear();
        QTimer again;
        whenDialogOpens(again, threeStrips(false));
        window.action(QStringLiteral("actionApproximateReference"))->trigger();
        QVERIFY(finished.wait(120000));
        QVERIFY2(finished.front().at(0).toBool(), qPrintable(finished.front().at(1).toString()));
        QVERIFY(!finished.front().at(1).toString().contains(QStringLiteral("one watertight")));
        QCOMPARE(doc->surfaceCount(), 3);
    }

    void stripsAroundAClosedShapeBecomeRings() {
        // Three new strips around a sphere: one surface of three rings, open only at the poles,
        // developable; the sentence says so; one undo step.
        app::MainWindow window;
        QVERIFY(test::showActiveWithExample(window, QStringLiteral("sheet")));
        openSphereOnly(window);
        document::Document* doc = window.workspace()->document();
        const int steps = doc->undoStack()->count();
        QSignalSpy finished(reactionOf(window), &app::ApproximateReaction::finished);
        QTimer poll;
        whenDialogOpens(poll, threeStrips(true));
        window.action(QStringLiteral("actionApproximateReference"))->trigger();
        QVERIFY(finished.wait(120000));
        const QString sentence = finished.front().at(1).toString();
        QVERIFY2(finished.front().at(0).toBool(), qPrintable(sentence));
        QVERIFY2(sentence.contains(QStringLiteral("closes around an axis: its 3 strips were laid "
                                                  "as rings")),
                 qPrintable(sentence));
        QCOMPARE(doc->undoStack()->count(), steps + 1);
        QCOMPARE(doc->surfaceCount(), 1);
        const model::CompositeSurface surface = doc->surface(0);
        QCOMPARE(surface.faces().size(), std::size_t(3 * model::reference::kRingSectors));
        QCOMPARE(model::surfaceParts(surface).size(), std::size_t(1));
        QVERIFY(test::sampledDevelopability(surface) <= 1e-8);
    }

    void pullsTheDesignsSurfaces() {
        // The design: a flat strip on the cylinder's points (as the setup would place it),
        // pulled onto them in place, one undo step, with no strip added.
        app::MainWindow window;
        QVERIFY(test::showActiveWithExample(window, QStringLiteral("sheet")));
        const model::ReferenceShape cylinder = parabolicCylinder();
        model::Project project;
        project.referenceShapes.push_back(cylinder);
        for (model::CompositeSurface& strip :
             solver::initialStrips(solver::thinTarget(cylinder.points, 0.0), 1, 4)) {
            project.addSurface(std::move(strip));
        }
        QCOMPARE(project.surfaces.size(), std::size_t{1});
        document::Document* doc = window.workspace()->document();
        doc->resetProject(project);
        const std::string before = test::bytesOf(window);
        const double startDistance =
            model::reference::measureDistance(doc->project().surfaces, cylinder.points)
                .targetToSurface.max;
        app::ApproximateReaction* reaction = reactionOf(window);
        QSignalSpy finished(reaction, &app::ApproximateReaction::finished);
        QTimer poll;
        whenDialogOpens(poll, [](app::ApproximateDialog* dialog) {
            QVERIFY(dialog->designButton()->isEnabled());
            dialog->designButton()->setChecked(true);
            QVERIFY(!dialog->stripsBox()->isEnabled());
            dialog->accept();
        });
        window.action(QStringLiteral("actionApproximateReference"))->trigger();
        QVERIFY(finished.wait(120000));
        QVERIFY2(finished.front().at(0).toBool(), qPrintable(finished.front().at(1).toString()));
        QCOMPARE(doc->undoStack()->count(), 1);
        QCOMPARE(doc->surfaceCount(), 1); // no strip added
        const model::reference::DistanceReport end =
            model::reference::measureDistance(doc->project().surfaces, cylinder.points);
        QVERIFY2(
            end.targetToSurface.max <= 1e-5 * end.diagonal && startDistance > 1.0,
            qPrintable(QStringLiteral("%1 → %2").arg(startDistance).arg(end.targetToSurface.max)));
        const double developability = test::sampledDevelopability(doc->surface(0));
        QVERIFY2(developability <= 1e-8, qPrintable(QString::number(developability)));
        const std::string after = test::bytesOf(window);
        doc->undoStack()->undo();
        QCOMPARE(test::bytesOf(window), before);
        doc->undoStack()->redo();
        QCOMPARE(test::bytesOf(window), after);
    }

    void cancelChangesNothing() {
        app::MainWindow window;
        QVERIFY(test::showActiveWithExample(window, QStringLiteral("sheet")));
        openCylinderOnly(window);
        document::Document* doc = window.workspace()->document();
        const std::string before = test::bytesOf(window);
        const int steps = doc->undoStack()->count();
        app::ApproximateReaction* reaction = reactionOf(window);
        QSignalSpy finished(reaction, &app::ApproximateReaction::finished);
        // Cancel (the status bar's, Esc) as soon as the job reports its first iteration.
        QAction* cancel = window.action(QStringLiteral("actionCancelSolve"));
        QVERIFY(cancel != nullptr);
        int reported = 0;
        connect(window.solveController(), &app::SolveController::progress, this,
                [&reported, cancel] {
                    if (reported++ == 0) {
                        QVERIFY(cancel->isEnabled());
                        cancel->trigger();
                    }
                });
        QTimer poll;
        whenDialogOpens(poll, oneStrip(1000));
        window.action(QStringLiteral("actionApproximateReference"))->trigger();
        QVERIFY(finished.wait(120000));
        QVERIFY(reported > 0);
        QVERIFY(!finished.front().at(0).toBool());
        QVERIFY(!reaction->isBusy());
        QVERIFY(test::waitForWorkerIdle(window, 60000));
        QCOMPARE(test::bytesOf(window), before);
        QCOMPARE(doc->undoStack()->count(), steps);
        QVERIFY(!doc->isModified());
        QVERIFY(window.action(QStringLiteral("actionApproximateReference"))->isEnabled());
    }

    void solveWaitsForTheApproximation() {
        // Tools ▸ Solve while the approximation's job runs is not started, said so; the
        // approximation goes on and ends as one undo step.
        app::MainWindow window;
        QVERIFY(test::showActiveWithExample(window, QStringLiteral("sheet")));
        openCylinderOnly(window);
        document::Document* doc = window.workspace()->document();
        const int steps = doc->undoStack()->count();
        app::ApproximateReaction* reaction = reactionOf(window);
        QSignalSpy finished(reaction, &app::ApproximateReaction::finished);
        QSignalSpy status(window.workspace(), &app::Workspace::statusMessage);
        int reported = 0;
        connect(window.solveController(), &app::SolveController::progress, this,
                [&reported, &window] {
                    if (reported++ == 0) {
                        window.solveController()->solve();
                    }
                });
        QTimer poll;
        whenDialogOpens(poll, oneStrip(30));
        window.action(QStringLiteral("actionApproximateReference"))->trigger();
        QVERIFY(finished.wait(120000));
        QVERIFY(reported > 0);
        QVERIFY2(finished.front().at(0).toBool(), qPrintable(finished.front().at(1).toString()));
        QCOMPARE(doc->undoStack()->count(), steps + 1);
        const QString refused =
            app::SolveController::tr("Solve is not started while %1 runs; cancel it first (Esc).")
                .arg(app::ApproximateReaction::tr("Approximate Reference Shape"));
        QStringList messages;
        for (const QList<QVariant>& message : status) {
            messages << message.front().toString();
        }
        QVERIFY2(messages.contains(refused), qPrintable(messages.join(QStringLiteral(" | "))));
        QVERIFY(test::waitForWorkerIdle(window, 60000));
    }

    // 40,000 points on a cylinder (or the file DEVSURF_TEST_LARGE_REFERENCE names, e.g. the
    // Stanford bunny in mm, with DEVSURF_TEST_STRIPS strips of 2 intervals): start() hands every
    // step to other threads, so it returns with the design untouched; the times of the steps
    // and the longest pause of the event loop are printed, not checked.
    void largeReferenceIsSetUpOffTheGuiThread() {
        app::MainWindow window;
        QVERIFY(test::showActiveWithExample(window, QStringLiteral("sheet")));
        model::Project project;
        model::ReferenceShape shape{"large", "", {}, {}, {}};
        const QString file = qEnvironmentVariable("DEVSURF_TEST_LARGE_REFERENCE");
        app::ApproximationChoice choice;
        if (!file.isEmpty()) {
            io::ReferenceImportResult read = io::readReferenceShape(file.toStdString());
            QVERIFY(!read.error);
            shape = std::move(read.shape);
            choice.strips = qEnvironmentVariableIntValue("DEVSURF_TEST_STRIPS");
            choice.strips = choice.strips > 0 ? choice.strips : 30;
            choice.intervals = 2;
        } else {
            // Half a cylinder of radius 90 mm, 180 mm long.
            for (int i = 0; i < 200; ++i) {
                for (int j = 0; j < 200; ++j) {
                    const double angle = M_PI * i / 199.0;
                    shape.points.push_back(
                        {90.0 * std::cos(angle), 90.0 * std::sin(angle), 0.9 * j});
                }
            }
        }
        project.referenceShapes.push_back(shape);
        document::Document* doc = window.workspace()->document();
        doc->resetProject(project);
        app::ApproximateDialog dialog(doc->project(), &window);
        choice.rho = dialog.defaultRho();
        const std::string before = test::bytesOf(window);
        app::ApproximateReaction* reaction = reactionOf(window);
        QSignalSpy finished(reaction, &app::ApproximateReaction::finished);
        window.surfaceView()->grabImage(); // the shape's first frame, before the clock starts
        QElapsedTimer clock;
        qint64 last = 0;
        qint64 longest = 0;
        qint64 longestEnd = 0;
        QTimer tick;
        connect(&tick, &QTimer::timeout, [&] {
            if (clock.elapsed() - last > longest) {
                longest = clock.elapsed() - last;
                longestEnd = clock.elapsed();
            }
            last = clock.elapsed();
        });
        clock.start();
        tick.start(5);
        reaction->start(choice);
        const qint64 returned = clock.elapsed();
        QVERIFY(reaction->isBusy());
        QCOMPARE(test::bytesOf(window), before); // nothing done on this thread yet
        QVERIFY(finished.wait(600000));
        const qint64 total = clock.elapsed();
        const app::ApproximateReaction::Timings t = reaction->lastTimings();
        qInfo("%zu points, %d strip(s) of %d interval(s): start() returned after %lld ms; set up "
              "in %.0f ms, solved in %.0f ms, measured in %.0f ms, %lld ms in all; longest pause "
              "of the event loop %lld ms (ending at %lld ms); %s",
              shape.points.size(), choice.strips, choice.intervals, returned, t.setup, t.solve,
              t.measure, total, longest, longestEnd, qPrintable(finished.front().at(1).toString()));
        QVERIFY(!reaction->isBusy());
    }

    void tooFewPointsIsOneSentence() {
        // ρ of 50 mm on a 119 mm wide cloud keeps a handful of points, too few for 100 strips:
        // refused in one sentence (a message box, then the status bar), nothing changed.
        app::MainWindow window;
        QVERIFY(test::showActiveWithExample(window, QStringLiteral("sheet")));
        openCylinderOnly(window);
        document::Document* doc = window.workspace()->document();
        const std::string before = test::bytesOf(window);
        app::ApproximateReaction* reaction = reactionOf(window);
        QSignalSpy finished(reaction, &app::ApproximateReaction::finished);
        QString shown;
        QTimer poll;
        connect(&poll, &QTimer::timeout, &poll, [&poll, &shown] {
            if (auto* box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget())) {
                poll.stop();
                shown = box->text();
                box->accept();
            }
        });
        poll.start(10);
        app::ApproximationChoice choice;
        choice.strips = 100;
        choice.rho = 50.0;
        reaction->start(choice);
        QVERIFY(finished.wait(60000));
        QVERIFY(!finished.front().at(0).toBool());
        const QString sentence = finished.front().at(1).toString();
        QCOMPARE(shown, sentence);
        QVERIFY(sentence.endsWith(QLatin1Char('.')) || sentence.endsWith(QChar(0x3002)));
        QCOMPARE(test::bytesOf(window), before);
        QCOMPARE(doc->undoStack()->count(), 0);
        QVERIFY(!window.solveController()->isSolving());
        QVERIFY(window.action(QStringLiteral("actionApproximateReference"))->isEnabled());
    }

    void dialogCancelChangesNothing() {
        app::MainWindow window;
        QVERIFY(test::showActiveWithExample(window, QStringLiteral("sheet")));
        openCylinderOnly(window);
        document::Document* doc = window.workspace()->document();
        const std::string before = test::bytesOf(window);
        app::ApproximateReaction* reaction = reactionOf(window);
        QTimer poll;
        whenDialogOpens(poll, [](app::ApproximateDialog* dialog) { dialog->reject(); });
        window.action(QStringLiteral("actionApproximateReference"))->trigger();
        QVERIFY(!reaction->isBusy());
        QVERIFY(!window.solveController()->isSolving());
        QCOMPARE(test::bytesOf(window), before);
        QCOMPARE(doc->undoStack()->count(), 0);
    }
};

DEVSURF_REGISTER_TEST(TstApproximateGui);

#include "tst_approximate_gui.moc"
