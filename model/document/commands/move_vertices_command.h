#pragma once

#include "surface_edit_command.h"

#include "model/topology_edits.h"
#include "model/vec3.h"

#include <set>

namespace devsurf::document {

// Translates or rotates a set of vertices of one surface together with the control points next
// to them (model::moveVertices). Consecutive moves of the same vertex set of the same surface
// merge into one undo step whose "after" is the latest state.
class MoveVerticesCommand : public SurfaceEditCommand {
    Q_DECLARE_TR_FUNCTIONS(MoveVerticesCommand)
public:
    static CommandOrError createTranslation(Document& document, int surfaceIndex,
                                            std::set<model::VertexId> vertices,
                                            const model::Vec3& offset);
    // Right-handed rotation by angle (radians) about the axis through point along direction.
    static CommandOrError createRotation(Document& document, int surfaceIndex,
                                         std::set<model::VertexId> vertices,
                                         const model::Vec3& point, const model::Vec3& direction,
                                         double angle);

    const std::set<model::VertexId>& vertices() const { return m_vertices; }
    int id() const override;
    bool mergeWith(const QUndoCommand* other) override;

private:
    MoveVerticesCommand(Document& document, int surfaceIndex, model::CompositeSurface before,
                        model::CompositeSurface after, const QString& text,
                        std::set<model::VertexId> vertices);
    static CommandOrError create(Document& document, int surfaceIndex,
                                 std::set<model::VertexId> vertices,
                                 const model::RigidMotion& motion, const QString& text);

    std::set<model::VertexId> m_vertices;
};

} // namespace devsurf::document
