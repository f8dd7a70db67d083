#include "cli_output.h"

#include "command_line.h"
#include "io/file_error.h"
#include "io/output_file.h"
#include "io/project_file.h"

#include <QFileInfo>
#include <QString>
#include <QStringList>

#include <iostream>

namespace devsurf::app {

namespace {

// The extensions of the files DevSurf writes.
const char* const kKnownExtensions[] = {"devsurf", "json", "dxf", "svg", "pdf", "fold", "step",
                                        "stp",     "iges", "igs", "obj", "stl", "ply"};

} // namespace

void checkOutput(const std::string& output, const std::vector<std::string>& inputs, OutputKind kind,
                 const std::string& what) {
    if (output == "-") {
        if (kind == OutputKind::Project) {
            throw UsageError{"a project is written to a file, not to standard output ('-')"};
        }
        return;
    }
    QStringList sources;
    for (const std::string& input : inputs) {
        sources << QString::fromStdString(input);
    }
    switch (io::outputProblem(QString::fromStdString(output), sources)) {
    case io::OutputProblem::None:
        return;
    case io::OutputProblem::SameAsInput:
        if (kind == OutputKind::Project) {
            return; // an edit in place; saveProjectFile keeps the previous file as .bak
        }
        throw io::FileError("Refusing to write " + what + " to '" + output +
                            "': it is the project being read, which would be lost. Choose "
                            "another output file.");
    case io::OutputProblem::Folder:
        throw io::FileError("Cannot write " + what + " to '" + output +
                            "': it is a folder. Give a file name.");
    case io::OutputProblem::NotRegularFile:
        throw io::FileError("Cannot write " + what + " to '" + output +
                            "': it is a device, pipe or socket, not a regular file" +
                            (kind == OutputKind::Project ? std::string(".")
                                                         : "; use -o - to write to standard "
                                                           "output."));
    }
}

void checkExtension(const std::string& output, const std::string& extension,
                    const std::string& formatName) {
    if (output == "-") {
        return;
    }
    const QString suffix = QFileInfo(QString::fromStdString(output)).suffix().toLower();
    if (suffix.isEmpty() || suffix == QString::fromStdString(extension)) {
        return;
    }
    for (const char* known : kKnownExtensions) {
        if (suffix == QLatin1String(known)) {
            throw UsageError{"'" + output + "' ends in ." + known + " but " + formatName +
                             " is written; name it ." + extension +
                             " or choose the format that matches"};
        }
    }
}

void writeProject(const model::Project& project, const std::string& output) {
    io::saveProjectFile(project, QString::fromStdString(output));
}

void writeStandardOutput(const QByteArray& bytes) {
    std::cout.write(bytes.constData(), static_cast<std::streamsize>(bytes.size()));
    if (!std::cout.flush()) {
        throw io::FileError("Cannot write to standard output.");
    }
}

} // namespace devsurf::app
