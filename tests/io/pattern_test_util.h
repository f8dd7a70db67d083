#pragma once

// Running the independent readers (ezdxf, poppler) from the pattern tests.

#include <QProcess>
#include <QString>
#include <QStringList>

namespace devsurf::test {

struct ToolRun {
    bool finished = false;
    int exitCode = -1;
    QString out;
    QString err;
};

inline ToolRun runTool(const QString& program, const QStringList& arguments) {
    QProcess process;
    process.start(program, arguments);
    ToolRun run;
    if (!process.waitForFinished(300000) || process.exitStatus() != QProcess::NormalExit) {
        run.err = process.errorString();
        return run;
    }
    run.finished = true;
    run.exitCode = process.exitCode();
    run.out = QString::fromUtf8(process.readAllStandardOutput());
    run.err = QString::fromUtf8(process.readAllStandardError());
    return run;
}

} // namespace devsurf::test
