#pragma once

// Reads a DXF file back with ezdxf (tests/io/check_dxf.py) and compares it with the pattern
// it was written from.

#include "model/pattern/cutting_pattern.h"

#include <QJsonObject>
#include <QString>

#include <functional>

namespace devsurf::test {

// Runs the check; `shift` gives the x offset of a sheet in the drawing. Returns ezdxf's
// findings (empty when the check could not run).
QJsonObject readBackDxf(const QString& dxfFile, const model::CuttingPattern& pattern,
                        double tolerance, const std::function<double(int sheet)>& shift);

// Qt Test checks of those findings: audit without errors, the version, $INSUNITS = 4, the seven
// layers with their own colours (folds dashed, SCORE off), the entity type, every expected
// path found within `tolerance`, closed paths closed, labels present.
void verifyDxf(const QJsonObject& result, const char* version, const char* entity,
               double tolerance);

} // namespace devsurf::test
