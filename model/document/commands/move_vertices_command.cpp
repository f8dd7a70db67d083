#include "move_vertices_command.h"

#include "command_ids.h"
#include "model/model_error.h"

namespace devsurf::document {

MoveVerticesCommand::MoveVerticesCommand(Document& document, int surfaceIndex,
                                         model::CompositeSurface before,
                                         model::CompositeSurface after, const QString& text,
                                         std::set<model::VertexId> vertices)
    : SurfaceEditCommand(document, surfaceIndex, std::move(before), std::move(after),
                         Change::Geometry, text),
      m_vertices(std::move(vertices)) {}

CommandOrError MoveVerticesCommand::createTranslation(Document& document, int surfaceIndex,
                                                      std::set<model::VertexId> vertices,
                                                      const model::Vec3& offset) {
    if (!offset.isFinite()) {
        return CommandOrError(tr("The vertices cannot be moved by an offset that is not a "
                                 "finite number."));
    }
    const QString text = tr("Move %n vertices", nullptr, static_cast<int>(vertices.size()));
    return create(document, surfaceIndex, std::move(vertices),
                  model::RigidMotion::translationBy(offset), text);
}

CommandOrError MoveVerticesCommand::createRotation(Document& document, int surfaceIndex,
                                                   std::set<model::VertexId> vertices,
                                                   const model::Vec3& point,
                                                   const model::Vec3& direction, double angle) {
    model::RigidMotion motion;
    try {
        motion = model::RigidMotion::rotationAbout(point, direction, angle);
    } catch (const model::ModelError& e) {
        return CommandOrError(tr("The vertices cannot be rotated"), e.problem());
    }
    const QString text = tr("Rotate %n vertices", nullptr, static_cast<int>(vertices.size()));
    return create(document, surfaceIndex, std::move(vertices), motion, text);
}

CommandOrError MoveVerticesCommand::create(Document& document, int surfaceIndex,
                                           std::set<model::VertexId> vertices,
                                           const model::RigidMotion& motion, const QString& text) {
    return attempt(
        document, surfaceIndex, tr("The vertices cannot be moved"),
        [&](const model::CompositeSurface& s) { return model::moveVertices(s, vertices, motion); },
        [&](model::CompositeSurface before, model::CompositeSurface after) {
            return std::unique_ptr<QUndoCommand>(new MoveVerticesCommand(
                document, surfaceIndex, std::move(before), std::move(after), text, vertices));
        });
}

int MoveVerticesCommand::id() const {
    return kMoveVerticesCommandId;
}

bool MoveVerticesCommand::mergeWith(const QUndoCommand* other) {
    const auto* next = dynamic_cast<const MoveVerticesCommand*>(other);
    if (next == nullptr || next->surfaceIndex() != surfaceIndex() ||
        next->m_vertices != m_vertices) {
        return false;
    }
    setAfter(next->after(), next->changes());
    return true;
}

} // namespace devsurf::document
