#pragma once

#include <QString>

#include <memory>

class QUndoCommand;

namespace devsurf::document {

class Document;

// What a command factory returns: the command, ready to push, or the sentence that says why the
// edit is refused. A refused edit never reaches the undo stack and leaves the document as it was.
class CommandOrError {
public:
    CommandOrError(std::unique_ptr<QUndoCommand> command);
    CommandOrError(QString error);
    CommandOrError(CommandOrError&&) noexcept;
    CommandOrError& operator=(CommandOrError&&) noexcept;
    ~CommandOrError();

    bool isRefused() const { return !m_command; }
    explicit operator bool() const { return static_cast<bool>(m_command); }
    // Empty unless refused.
    const QString& error() const { return m_error; }
    QUndoCommand* command() const { return m_command.get(); }
    std::unique_ptr<QUndoCommand> takeCommand() { return std::move(m_command); }

private:
    std::unique_ptr<QUndoCommand> m_command;
    QString m_error;
};

// Pushes the command on the document's undo stack (which applies it) and returns an empty
// string, or returns the refusal message and changes nothing.
QString pushOrExplain(Document& document, CommandOrError result);

} // namespace devsurf::document
