#include "command_or_error.h"

#include "model/document/document.h"

#include <QUndoCommand>
#include <QUndoStack>

namespace devsurf::document {

CommandOrError::CommandOrError(std::unique_ptr<QUndoCommand> command)
    : m_command(std::move(command)) {}

CommandOrError::CommandOrError(QString error, std::optional<model::Problem> problem)
    : m_error(std::move(error)), m_problem(std::move(problem)) {}

CommandOrError::CommandOrError(CommandOrError&&) noexcept = default;
CommandOrError& CommandOrError::operator=(CommandOrError&&) noexcept = default;
CommandOrError::~CommandOrError() = default;

bool push(Document& document, CommandOrError& result) {
    if (result.isRefused()) {
        return false;
    }
    document.undoStack()->push(result.takeCommand().release());
    return true;
}

} // namespace devsurf::document
