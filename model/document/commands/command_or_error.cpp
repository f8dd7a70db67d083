#include "command_or_error.h"

#include "model/document/document.h"

#include <QUndoCommand>
#include <QUndoStack>

namespace devsurf::document {

CommandOrError::CommandOrError(std::unique_ptr<QUndoCommand> command)
    : m_command(std::move(command)) {}

CommandOrError::CommandOrError(QString error) : m_error(std::move(error)) {}

CommandOrError::CommandOrError(CommandOrError&&) noexcept = default;
CommandOrError& CommandOrError::operator=(CommandOrError&&) noexcept = default;
CommandOrError::~CommandOrError() = default;

QString pushOrExplain(Document& document, CommandOrError result) {
    if (result.isRefused()) {
        return result.error();
    }
    document.undoStack()->push(result.takeCommand().release());
    return QString();
}

} // namespace devsurf::document
