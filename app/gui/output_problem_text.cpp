#include "output_problem_text.h"

#include <QCoreApplication>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>

namespace devsurf::app {

QString outputProblemText(io::OutputProblem problem, const QString& path) {
    const QString name = QFileInfo(path).fileName();
    switch (problem) {
    case io::OutputProblem::None:
        break;
    case io::OutputProblem::SameAsInput:
        return QCoreApplication::translate(
                   "OutputProblem", "“%1” is the project file of this design: exporting over it "
                                    "would destroy the design. Choose another file name.")
            .arg(name);
    case io::OutputProblem::Folder:
        return QCoreApplication::translate("OutputProblem", "“%1” is a folder. Choose a file name.")
            .arg(name);
    case io::OutputProblem::NotRegularFile:
        return QCoreApplication::translate(
                   "OutputProblem",
                   "“%1” is a device, pipe or socket, not a file. Choose a file name.")
            .arg(name);
    }
    return {};
}

QString askExportPath(QWidget* parent, const QString& title, const QString& directory,
                      const QString& baseName, const QString& extension, const QString& filter) {
    QString path = QFileDialog::getSaveFileName(
        parent, title, QDir(directory).filePath(baseName + QLatin1Char('.') + extension), filter);
    if (!path.isEmpty() && !path.endsWith(QLatin1Char('.') + extension, Qt::CaseInsensitive)) {
        path += QLatin1Char('.') + extension;
    }
    return path;
}

QString notEnoughMemoryText(const QString& path) {
    return QCoreApplication::translate("OutputProblem", "There is not enough memory to open “%1”.")
        .arg(QFileInfo(path).fileName());
}

} // namespace devsurf::app
