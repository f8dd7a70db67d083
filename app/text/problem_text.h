#pragma once

#include "model/pattern/cutting_pattern.h"
#include "model/problem.h"
#include "model/spline_space.h"

#include <QCoreApplication>
#include <QString>

namespace devsurf::app {

// A designer's sentences for the problems model/ reports as codes. Translated with whatever
// translator is installed: the desktop application's German or Japanese, none (English) in the
// command line.
class ProblemText {
    Q_DECLARE_TR_FUNCTIONS(ProblemText)

public:
    // One sentence, starting with a capital and ending with a full stop.
    static QString of(const model::Problem& problem);
    // `pattern` names the pieces a problem refers to.
    static QString of(const model::PatternProblem& problem, const model::CuttingPattern& pattern);
    // "degree 3, C2, 4 intervals"
    static QString splineSpace(const model::SplineSpace& space);
    // "Surface 2 “Hull”", or "Surface 2" without a name (index counted from 0).
    static QString surface(int index, const std::string& name);
    // "patches 3 and 4" / "patch 3" / "no patch", for finding a vertex or edge.
    static QString patches(const std::vector<model::FaceId>& faces);
};

// A sentence used as a clause: without its final full stop (and trailing spaces).
std::string withoutFinalPeriod(std::string text);

// Every pattern problem worded, in order (for the files and pages that list them).
std::vector<std::string> patternProblemTexts(const model::CuttingPattern& pattern);

} // namespace devsurf::app
