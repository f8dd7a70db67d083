#pragma once

namespace devsurf::document {

// QUndoCommand::id() values of the commands that merge; distinct so that only commands of one
// kind merge.
inline constexpr int kMoveVerticesCommandId = 0x4d6f7665; // "Move"
inline constexpr int kApplySurfaceCommandId = 0x41706c79; // "Aply"

} // namespace devsurf::document
