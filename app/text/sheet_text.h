#pragma once

#include "model/ids.h"

#include <QCoreApplication>
#include <QString>

namespace devsurf::app {

// Why a held sheet lags: words both front ends share (translated like ProblemText, English in
// the command line).
class SheetText {
    Q_DECLARE_TR_FUNCTIONS(SheetText)

public:
    // A clause (no capital, no full stop) for two pinned vertices that hold the straight line
    // between them in the sheet (solver::SurfaceAssessment::tautPins).
    static QString tautPins(model::VertexId first, model::VertexId second);
};

} // namespace devsurf::app
