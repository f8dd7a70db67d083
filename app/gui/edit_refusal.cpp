#include "edit_refusal.h"

#include "problem_text.h"

#include <QCoreApplication>
#include <QUndoCommand>

namespace devsurf::app {

QString refusalText(const document::CommandOrError& result) {
    if (!result.isRefused()) {
        return QString();
    }
    if (!result.problem()) {
        return result.error();
    }
    return QCoreApplication::translate("EditRefusal", "%1: %2")
        .arg(result.error(), ProblemText::of(*result.problem()));
}

QString pushOrExplain(document::Document& document, document::CommandOrError result) {
    if (document::push(document, result)) {
        return QString();
    }
    return refusalText(result);
}

} // namespace devsurf::app
