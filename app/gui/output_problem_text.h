#pragma once

#include "io/output_file.h"

#include <QString>

class QWidget;

namespace devsurf::app {

// Why an export to `path` is refused (io::outputProblem), translated; empty for None. The
// design's own project file is never overwritten by an export.
QString outputProblemText(io::OutputProblem problem, const QString& path);

// Asks where to save an export (a file dialog in `directory`, proposing `baseName`.extension);
// the chosen path with `extension` appended if it lacks it, or empty if the user cancelled.
QString askExportPath(QWidget* parent, const QString& title, const QString& directory,
                      const QString& baseName, const QString& extension, const QString& filter);

// What the user reads when opening `path` ran out of memory.
QString notEnoughMemoryText(const QString& path);

} // namespace devsurf::app
