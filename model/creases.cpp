#include "creases.h"

#include <algorithm>
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

// True if the face's loop contains the step from → to.
bool loopRunsAlong(const CompositeSurface& surface, FaceId face, VertexId from, VertexId to) {
    const auto& loop = surface.faceLoop(face);
    for (std::size_t i = 0; i < loop.size(); ++i) {
        if (loop[i] == from && loop[(i + 1) % loop.size()] == to) {
            return true;
        }
    }
    return false;
}

// The side of one face at the crease: its strip, which curve, and how its normal is oriented
// against the face loop's normal (the sum of its sampled faces' normals).
CreaseSide sideOf(FaceId face, EdgeId edge, const std::vector<Strip>& strips,
                  const std::map<FaceId, std::size_t>& stripIndex,
                  const std::map<FaceId, Vec3>& loopNormals) {
    CreaseSide side;
    side.face = face;
    const auto it = stripIndex.find(face);
    if (it == stripIndex.end()) {
        return side;
    }
    side.strip = it->second;
    const Strip& strip = strips[it->second];
    side.sideA = strip.aSide.edge == edge;
    side.reversed = side.sideA ? strip.aSide.reversed : strip.bSide.reversed;
    const auto normal = loopNormals.find(face);
    if (normal != loopNormals.end()) {
        // The strip's normal at a few parameters: one is enough unless a′ or b − a vanishes
        // there (the pointed end of an SRS face), so take the largest.
        Vec3 best;
        for (double u : {0.5, 0.25, 0.75}) {
            const Vec3 n = cross(strip.a.derivative(u, 1), strip.bPoint(u) - strip.aPoint(u));
            if (n.norm() > best.norm()) {
                best = n;
            }
        }
        side.flipNormal = dot(best, normal->second) < 0.0;
    }
    return side;
}

} // namespace

const char* foldAssignmentLetter(FoldAssignment assignment) {
    switch (assignment) {
    case FoldAssignment::Mountain:
        return "M";
    case FoldAssignment::Valley:
        return "V";
    case FoldAssignment::Flat:
        break;
    }
    return "F";
}

std::vector<Crease> creasesOf(const CompositeSurface& surface, const std::vector<Strip>& strips,
                              const SampledMesh& mesh) {
    std::map<FaceId, std::size_t> stripIndex;
    for (std::size_t i = 0; i < strips.size(); ++i) {
        stripIndex[strips[i].face] = i;
    }
    // The sampled face on the left of every directed mesh edge (faces are oriented like the
    // coarse faces, so a face's own edges have it on their left), and every coarse face's
    // normal as the sum of its sampled faces' normals.
    std::map<std::pair<int, int>, int> leftFace;
    std::map<FaceId, Vec3> loopNormals;
    for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
        const auto& face = mesh.faces[f];
        for (std::size_t i = 0; i < face.size(); ++i) {
            leftFace[{face[i], face[(i + 1) % face.size()]}] = static_cast<int>(f);
        }
        loopNormals[mesh.faceOrigin[f]] += newellNormal(mesh, face);
    }
    std::vector<Crease> creases;
    for (const auto& line : mesh.splineEdges) {
        const std::vector<FaceId> faces = surface.facesOfEdge(line.edge);
        if (faces.size() != 2) {
            continue;
        }
        const EdgeRecord& record = surface.edge(line.edge);
        Crease crease;
        crease.edge = line.edge;
        // The face whose loop runs along the edge's orientation lies on its left.
        const FaceId left =
            loopRunsAlong(surface, faces[0], record.from, record.to) ? faces[0] : faces[1];
        const FaceId right = left == faces[0] ? faces[1] : faces[0];
        crease.left = sideOf(left, line.edge, strips, stripIndex, loopNormals);
        crease.right = sideOf(right, line.edge, strips, stripIndex, loopNormals);

        double weighted = 0.0;
        double totalLength = 0.0;
        for (std::size_t i = 0; i + 1 < line.vertices.size(); ++i) {
            const int a = line.vertices[i];
            const int b = line.vertices[i + 1];
            const auto l = leftFace.find({a, b});
            const auto r = leftFace.find({b, a});
            if (l == leftFace.end() || r == leftFace.end()) {
                continue;
            }
            const Vec3 nl = newellNormal(mesh, mesh.faces[static_cast<std::size_t>(l->second)]);
            const Vec3 nr = newellNormal(mesh, mesh.faces[static_cast<std::size_t>(r->second)]);
            const Vec3 t = mesh.vertices[static_cast<std::size_t>(b)] -
                           mesh.vertices[static_cast<std::size_t>(a)];
            const double length = t.norm();
            if (length <= 0.0 || nl.norm() <= 0.0 || nr.norm() <= 0.0) {
                continue;
            }
            // Turning the left normal into the right one about the edge direction: negative
            // when both faces rise towards the normal side (a valley seen from there).
            const double angle =
                std::atan2(dot(cross(nl, nr), t / length), dot(nl, nr)) * kDegreesPerRadian;
            weighted += angle * length;
            totalLength += length;
            crease.maxFoldAngleDegrees = std::max(crease.maxFoldAngleDegrees, std::abs(angle));
        }
        crease.foldAngleDegrees = totalLength > 0.0 ? weighted / totalLength : 0.0;
        if (std::abs(crease.foldAngleDegrees) >= kFlatFoldDegrees) {
            crease.assignment =
                crease.foldAngleDegrees > 0.0 ? FoldAssignment::Mountain : FoldAssignment::Valley;
        }
        creases.push_back(crease);
    }
    return creases;
}

} // namespace devsurf::model
