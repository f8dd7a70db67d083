#pragma once

#include <QByteArray>
#include <QFile>
#include <QProcess>
#include <QString>
#include <QStringList>

// Runs devsurf-cli (DEVSURF_CLI_PATH, set by tests/app/CMakeLists.txt) for the command-line
// tests: its exit code and what it printed.
namespace devsurf::test {

struct CliRun {
    int exitCode = -1; // -1: it did not finish within five minutes or crashed
    QString out;
    QString err;
};

inline CliRun runCli(const QStringList& arguments) {
    QProcess process;
    process.start(QStringLiteral(DEVSURF_CLI_PATH), arguments);
    CliRun run;
    if (!process.waitForFinished(300000) || process.exitStatus() != QProcess::NormalExit) {
        return run;
    }
    run.exitCode = process.exitCode();
    run.out = QString::fromUtf8(process.readAllStandardOutput());
    run.err = QString::fromUtf8(process.readAllStandardError());
    return run;
}

// The bytes of a file the command wrote (empty if it cannot be read).
inline QByteArray contents(const QString& path) {
    QFile file(path);
    return file.open(QIODevice::ReadOnly) ? file.readAll() : QByteArray();
}

} // namespace devsurf::test
