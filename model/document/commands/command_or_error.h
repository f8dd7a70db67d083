#pragma once

#include "model/problem.h"

#include <QString>

#include <memory>
#include <optional>

class QUndoCommand;

namespace devsurf::document {

class Document;

// What a command factory returns: the command, ready to push, or why the edit is refused: a
// heading ("The vertices cannot be rotated") and, where the model said why, its problem, which
// the application words (app/gui/edit_refusal.h). A refused edit never reaches the undo stack
// and leaves the document as it was.
class CommandOrError {
public:
    CommandOrError(std::unique_ptr<QUndoCommand> command);
    CommandOrError(QString error, std::optional<model::Problem> problem = {});
    CommandOrError(CommandOrError&&) noexcept;
    CommandOrError& operator=(CommandOrError&&) noexcept;
    ~CommandOrError();

    bool isRefused() const { return !m_command; }
    explicit operator bool() const { return static_cast<bool>(m_command); }
    // Empty unless refused.
    const QString& error() const { return m_error; }
    const std::optional<model::Problem>& problem() const { return m_problem; }
    QUndoCommand* command() const { return m_command.get(); }
    std::unique_ptr<QUndoCommand> takeCommand() { return std::move(m_command); }

private:
    std::unique_ptr<QUndoCommand> m_command;
    QString m_error;
    std::optional<model::Problem> m_problem;
};

// Pushes the command on the document's undo stack (which applies it) and returns true, or
// returns false and changes nothing.
bool push(Document& document, CommandOrError& result);

} // namespace devsurf::document
