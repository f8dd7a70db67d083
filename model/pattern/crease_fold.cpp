#include "crease_fold.h"

#include <cmath>
#include <map>

namespace devsurf::model {

namespace {

constexpr double kDegreesPerRadian = 57.295779513082320876798;

// Newell's normal of a polygon (unnormalised): robust for slightly non-planar quads.
Vec3 newellNormal(const SampledMesh& mesh, const std::vector<int>& face) {
    Vec3 normal;
    for (std::size_t i = 0; i < face.size(); ++i) {
        normal += cross(mesh.vertices[static_cast<std::size_t>(face[i])],
                        mesh.vertices[static_cast<std::size_t>(face[(i + 1) % face.size()])]);
    }
    return normal;
}

} // namespace

std::vector<CreaseFold> creaseFolds(const CompositeSurface& surface, const SampledMesh& mesh) {
    // The sampled face on the left of every directed mesh edge (faces are oriented like the
    // coarse faces, so a face's own edges have it on their left).
    std::map<std::pair<int, int>, int> leftFace;
    for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
        const auto& face = mesh.faces[f];
        for (std::size_t i = 0; i < face.size(); ++i) {
            leftFace[{face[i], face[(i + 1) % face.size()]}] = static_cast<int>(f);
        }
    }
    std::vector<CreaseFold> folds;
    for (const auto& line : mesh.splineEdges) {
        const std::vector<FaceId> faces = surface.facesOfEdge(line.edge);
        if (faces.size() != 2) {
            continue;
        }
        CreaseFold fold;
        fold.edge = line.edge;
        double weighted = 0.0;
        double totalLength = 0.0;
        for (std::size_t i = 0; i + 1 < line.vertices.size(); ++i) {
            const int a = line.vertices[i];
            const int b = line.vertices[i + 1];
            const auto left = leftFace.find({a, b});
            const auto right = leftFace.find({b, a});
            if (left == leftFace.end() || right == leftFace.end()) {
                continue;
            }
            fold.left = mesh.faceOrigin[static_cast<std::size_t>(left->second)];
            fold.right = mesh.faceOrigin[static_cast<std::size_t>(right->second)];
            const Vec3 nl = newellNormal(mesh, mesh.faces[static_cast<std::size_t>(left->second)]);
            const Vec3 nr = newellNormal(mesh, mesh.faces[static_cast<std::size_t>(right->second)]);
            const Vec3 t = mesh.vertices[static_cast<std::size_t>(b)] -
                           mesh.vertices[static_cast<std::size_t>(a)];
            const double length = t.norm();
            if (length <= 0.0 || nl.norm() <= 0.0 || nr.norm() <= 0.0) {
                continue;
            }
            // Turning the left normal into the right one about the edge direction: negative
            // when both patches rise towards the normal side (a valley seen from there).
            const double angle =
                std::atan2(dot(cross(nl, nr), t / length), dot(nl, nr)) * kDegreesPerRadian;
            weighted += angle * length;
            totalLength += length;
            fold.maxFoldAngleDegrees = std::max(fold.maxFoldAngleDegrees, std::abs(angle));
        }
        if (fold.left == kInvalidId) {
            // The samples do not tell the sides apart (a degenerate crease): use the loops.
            const EdgeRecord& record = surface.edge(line.edge);
            for (FaceId face : faces) {
                const auto& loop = surface.faceLoop(face);
                for (std::size_t i = 0; i < loop.size(); ++i) {
                    if (loop[i] == record.from && loop[(i + 1) % loop.size()] == record.to) {
                        fold.left = face;
                    }
                }
            }
            fold.right = fold.left == faces[0] ? faces[1] : faces[0];
        }
        fold.foldAngleDegrees = totalLength > 0.0 ? weighted / totalLength : 0.0;
        folds.push_back(fold);
    }
    return folds;
}

} // namespace devsurf::model
