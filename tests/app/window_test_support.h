#pragma once

// What the desktop application's tests ask of a main window.

#include "io/project_file.h"
#include "main_window.h"
#include "model/document/document.h"
#include "solve_controller.h"
#include "solver/worker/solver_worker.h"
#include "workspace.h"

#include <QCoreApplication>
#include <QSignalSpy>
#include <QString>
#include <QTest>

#include <string>

namespace devsurf::test {

// The project as it would be saved: byte-exact comparisons of undo and redo.
inline std::string bytesOf(const app::MainWindow& window) {
    return io::encodeProject(window.workspace()->document()->project());
}

// Shows `window` active (keyboard shortcuts reach it) with the built-in example `name`; false
// if the window never became active.
inline bool showActiveWithExample(app::MainWindow& window, const QString& name) {
    window.show();
    window.activateWindow();
    if (!QTest::qWaitForWindowActive(&window)) {
        return false;
    }
    window.workspace()->newFromExample(name, 0);
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
