#pragma once

#include "model/document/commands/command_or_error.h"

#include <QString>

namespace devsurf::app {

// Why an edit was refused, as one sentence: the command's heading and, where the model said
// why, its problem worded (app/text). Empty when the edit was not refused.
QString refusalText(const document::CommandOrError& result);

// Pushes the edit onto the document's undo stack and returns an empty string, or returns why it
// was refused and changes nothing.
QString pushOrExplain(document::Document& document, document::CommandOrError result);

} // namespace devsurf::app
