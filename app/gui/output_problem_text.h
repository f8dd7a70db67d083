#pragma once

#include "io/output_file.h"

#include <QString>

namespace devsurf::app {

// Why an export to `path` is refused (io::outputProblem), translated; empty for None. The
// design's own project file is never overwritten by an export.
QString outputProblemText(io::OutputProblem problem, const QString& path);

// What the user reads when opening `path` ran out of memory.
QString notEnoughMemoryText(const QString& path);

} // namespace devsurf::app
