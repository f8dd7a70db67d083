#pragma once

// What the desktop application's tests ask of a main window.

#include "io/project_file.h"
#include "main_window.h"
#include "model/document/document.h"
#include "solve_controller.h"
#include "solver/worker/solver_worker.h"
#include "translations.h"
#include "workspace.h"

#include <QApplication>
#include <QCoreApplication>
#include <QLocale>
#include <QMessageBox>
#include <QSignalSpy>
#include <QString>
#include <QTest>
#include <QTimer>
#include <QUndoStack>

#include <string>

namespace devsurf::test {

// Accepts the message box the next event-loop turn shows (a refusal, a warning) and sets
// `answered`, so a test can check that one was shown without a user to close it.
inline void acceptNextMessageBox(bool& answered) {
    QTimer::singleShot(0, [&answered] {
        if (auto* box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget())) {
            answered = true;
            box->accept();
        }
    });
}

// The interface language the tests run in: US English, or the one DEVSURF_TEST_LANGUAGE names
// ("de", "ja").
inline QLocale testLocale() {
    const QString language = qEnvironmentVariable("DEVSURF_TEST_LANGUAGE");
    return language.isEmpty() ? QLocale(QLocale::English, QLocale::UnitedStates)
                              : QLocale(language);
}

// Makes testLocale() the default locale and installs its translations (tests that switch the
// language call it again afterwards); false if DevSurf's translation was not found.
inline bool installTestLanguage() {
    QLocale::setDefault(testLocale());
    return app::installTranslations(QLocale());
}

// The project as it would be saved: byte-exact comparisons of undo and redo.
inline std::string bytesOf(const app::MainWindow& window) {
    return io::encodeProject(window.workspace()->document()->project());
}

// The step undo would undo next as a command of class C (the first child of a macro, such as
// a solve's), or null if it is none.
template <class C> const C* undoCommand(const document::Document& doc) {
    const QUndoStack* stack = doc.undoStack();
    const QUndoCommand* step = stack->index() > 0 ? stack->command(stack->index() - 1) : nullptr;
    if (step != nullptr && step->childCount() > 0) {
        step = step->child(0);
    }
    return dynamic_cast<const C*>(step);
}

// Shows `window` active (keyboard shortcuts reach it) with the built-in example `name`; false
// if the window never became active.
inline bool showActiveWithExample(app::MainWindow& window, const QString& name,
                                  model::ExampleSheet sheet = model::ExampleSheet::AsBuilt) {
    window.show();
    window.activateWindow();
    if (!QTest::qWaitForWindowActive(&window)) {
        return false;
    }
    window.workspace()->newFromExample(name, 0, sheet);
    return true;
}

// Waits (on the signal, never by sleeping) until the controller's solve has ended; returns its
// closing sentence, "not solving" or "timeout".
inline QString waitForSolve(app::MainWindow& window) {
    QSignalSpy finished(window.solveController(), &app::SolveController::finished);
    if (!window.solveController()->isSolving()) {
        return QStringLiteral("not solving");
    }
    if (!finished.wait(120000)) {
        return QStringLiteral("timeout");
    }
    return finished.front().front().toString();
}

// Waits until the worker has reported whatever it is still solving, then delivers the queued
// events; false on a timeout.
inline bool waitForWorkerIdle(app::MainWindow& window, int milliseconds) {
    QSignalSpy results(window.solveController()->worker(), &solver::SolverWorker::finished);
    if (window.solveController()->worker()->isBusy() && !results.wait(milliseconds)) {
        return false;
    }
    QCoreApplication::processEvents();
    return true;
}

} // namespace devsurf::test
