#pragma once

#include "solver/session/verdict.h"

#include <QCoreApplication>
#include <QString>

namespace devsurf::app {

// The designer's words for a solve's verdict (solver::verdictOf): one plain sentence, and the
// numbers behind it on demand. Translated like ProblemText (English in the command line).
class VerdictText {
    Q_DECLARE_TR_FUNCTIONS(VerdictText)

public:
    // "Developable to the tolerance — ready to cut.", "Developable to within 0.02 mm of
    // isometry over the sheet: the cut pattern is off by at most 0.02 mm.", "Not
    // developable at patches 3, 4. Try: …" (or, where only the development overlaps itself,
    // "Developable patch by patch, but the development overlaps itself at …"); empty for
    // VerdictKind::None.
    static QString of(const solver::Verdict& verdict);
    // A short form for the views' corner and the status bar: "Developable — ready to cut",
    // "Developable within 0.02 mm", "Not developable: patches 3, 4", "Development overlaps
    // itself: patches 3, 4".
    static QString brief(const solver::Verdict& verdict);
    // The numbers: residual and tolerance, edge-length error and the sheet's extent.
    static QString details(const solver::Verdict& verdict);
    // A length in mm as the verdict writes it ("0.02", "0.0001", "< 0.0001").
    static QString millimetres(double value);
};

} // namespace devsurf::app
