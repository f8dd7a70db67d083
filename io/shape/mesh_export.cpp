#include "mesh_export.h"

#include "patch_surfaces.h"
#include "shape_export_error.h"

#include "io/output_file.h"
#include "model/sampled_mesh.h"

#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <sstream>
#include <utility>

namespace devsurf::io {

namespace {

using model::Vec3;

struct DoubleTraits : public OpenMesh::DefaultTraits {
    using Point = OpenMesh::Vec3d;
};
using TriangleMesh = OpenMesh::TriMesh_ArrayKernelT<DoubleTraits>;

Vec3 midpoint(const Vec3& a, const Vec3& b) {
    return (a + b) * 0.5;
}

// How far the two triangles of the quad p0 p1 q1 q0 (split along p0 q1) stray from the quad's
// bilinear surface: half the distance between its diagonals (0 for a planar quad).
double twist(const Vec3& p0, const Vec3& p1, const Vec3& q0, const Vec3& q1) {
    const Vec3 normal = model::cross(q1 - p0, q0 - p1);
    const double length = normal.norm();
    return length > 0.0 ? 0.5 * std::abs(model::dot(normal, p1 - p0)) / length : 0.0;
}

// Whether N samples per interval keep every S-edge's chords within the tolerance (checked at
// their midpoints) and every strip's quads planar within it. The ruled surface between two
// chords strays from the bilinear quad by at most the chords' error, since it is linear along
// the rulings.
bool fineEnough(const model::CompositeSurface& surface, const std::vector<PatchSurface>& patches,
                int samples, double tolerance) {
    for (const auto& [id, record] : surface.edges()) {
        if (!record.isSpline()) {
            continue;
        }
        const model::BSplineCurve curve =
            model::BSplineCurve::uniform(record.space, record.controlPoints);
        const int count = record.space.intervals * samples;
        Vec3 previous = curve.evaluate(0.0);
        for (int i = 0; i < count; ++i) {
            const Vec3 next = curve.evaluate(static_cast<double>(i + 1) / count);
            const Vec3 middle = curve.evaluate((i + 0.5) / count);
            if ((middle - midpoint(previous, next)).norm() > tolerance) {
                return false;
            }
            previous = next;
        }
    }
    for (const PatchSurface& patch : patches) {
        if (patch.isPlanar()) {
            continue;
        }
        std::vector<double> breaks = patch.a.knots();
        breaks.erase(std::unique(breaks.begin(), breaks.end()), breaks.end());
        const int count = static_cast<int>(breaks.size() - 1) * samples;
        for (int i = 0; i < count; ++i) {
            const double u0 = static_cast<double>(i) / count;
            const double u1 = static_cast<double>(i + 1) / count;
            if (twist(patch.a.evaluate(u0), patch.a.evaluate(u1), patch.b.evaluate(u0),
                      patch.b.evaluate(u1)) > tolerance) {
                return false;
            }
        }
    }
    return true;
}

std::string groupName(model::SurfaceId surface, model::FaceId face, bool severalSurfaces) {
    const std::string name = "patch_" + std::to_string(face);
    return severalSurfaces ? "surface_" + std::to_string(surface) + "_" + name : name;
}

// Both sides offset by half the thickness along the vertex normals (area-weighted), the lower
// side reversed, and the rim: a band of two triangles on every boundary edge.
void thicken(ShapeMesh& mesh, double thickness) {
    const std::size_t n = mesh.vertices.size();
    std::vector<Vec3> normals(n);
    for (const auto& t : mesh.triangles) {
        const Vec3 normal = model::cross(mesh.vertices[t[1]] - mesh.vertices[t[0]],
                                         mesh.vertices[t[2]] - mesh.vertices[t[0]]);
        for (int corner : t) {
            normals[static_cast<std::size_t>(corner)] += normal;
        }
    }
    std::vector<Vec3> vertices;
    for (std::size_t i = 0; i < n; ++i) {
        const double length = normals[i].norm();
        const Vec3 offset = length > 0.0 ? normals[i] * (0.5 * thickness / length) : Vec3{};
        vertices.push_back(mesh.vertices[i] + offset);
    }
    for (std::size_t i = 0; i < n; ++i) {
        vertices.push_back(vertices[i] - (vertices[i] - mesh.vertices[i]) * 2.0);
    }
    std::map<std::pair<int, int>, int> directed;
    for (const auto& t : mesh.triangles) {
        for (int k = 0; k < 3; ++k) {
            ++directed[{t[k], t[(k + 1) % 3]}];
        }
    }
    const int offset = static_cast<int>(n);
    const std::size_t sides = mesh.triangles.size();
    for (std::size_t i = 0; i < sides; ++i) {
        const auto& t = mesh.triangles[i];
        mesh.triangles.push_back({t[0] + offset, t[2] + offset, t[1] + offset});
        mesh.triangleGroup.push_back(mesh.triangleGroup[i]);
    }
    const int rim = static_cast<int>(mesh.groups.size());
    mesh.groups.push_back("rim");
    for (const auto& [edge, count] : directed) {
        if (directed.count({edge.second, edge.first}) != 0) {
            continue;
        }
        const int a = edge.first;
        const int b = edge.second;
        mesh.triangles.push_back({b, a, a + offset});
        mesh.triangles.push_back({b, a + offset, b + offset});
        mesh.triangleGroup.insert(mesh.triangleGroup.end(), 2, rim);
    }
    mesh.vertices = std::move(vertices);
}

QByteArray objBytes(const ShapeMesh& mesh) {
    std::string text = "# DevSurf: the 3D shape, units mm\n";
    char line[128];
    for (const Vec3& v : mesh.vertices) {
        std::snprintf(line, sizeof line, "v %.17g %.17g %.17g\n", v.x, v.y, v.z);
        text += line;
    }
    for (std::size_t g = 0; g < mesh.groups.size(); ++g) {
        text += "g " + mesh.groups[g] + "\n";
        for (std::size_t i = 0; i < mesh.triangles.size(); ++i) {
            if (mesh.triangleGroup[i] != static_cast<int>(g)) {
                continue;
            }
            const auto& t = mesh.triangles[i];
            std::snprintf(line, sizeof line, "f %d %d %d\n", t[0] + 1, t[1] + 1, t[2] + 1);
            text += line;
        }
    }
    return QByteArray::fromStdString(text);
}

// Through OpenMesh's writers. A triangle OpenMesh's half-edge mesh cannot take (where the shape
// is not a manifold) gets vertices of its own, so the file still holds every triangle.
QByteArray openMeshBytes(const ShapeMesh& mesh, const char* extension) {
    TriangleMesh out;
    std::vector<TriangleMesh::VertexHandle> handles;
    for (const Vec3& v : mesh.vertices) {
        handles.push_back(out.add_vertex({v.x, v.y, v.z}));
    }
    for (const auto& t : mesh.triangles) {
        const TriangleMesh::FaceHandle face =
            out.add_face(handles[t[0]], handles[t[1]], handles[t[2]]);
        if (!face.is_valid()) {
            std::vector<TriangleMesh::VertexHandle> own;
            for (int corner : t) {
                own.push_back(out.add_vertex(out.point(handles[corner])));
            }
            out.add_face(own);
        }
    }
    std::ostringstream stream;
    OpenMesh::IO::Options options = OpenMesh::IO::Options::Binary;
    options += OpenMesh::IO::Options::LSB;
    // OpenMesh's writers note on its log what they write; an export says that itself.
    omlog().disable();
    const bool written = OpenMesh::IO::write_mesh(out, stream, extension, options);
    omlog().enable();
    if (!written) {
        return {};
    }
    const std::string bytes = stream.str();
    return QByteArray(bytes.data(), static_cast<qsizetype>(bytes.size()));
}

} // namespace

int samplesForTolerance(const model::CompositeSurface& surface, double tolerance) {
    const std::vector<PatchSurface> patches = patchSurfaces(surface);
    if (!fineEnough(surface, patches, kMaxMeshSamples, tolerance)) {
        return kMaxMeshSamples + 1;
    }
    int coarse = 0; // known too coarse
    int fine = 1;
    while (!fineEnough(surface, patches, fine, tolerance)) {
        coarse = fine;
        fine = std::min(kMaxMeshSamples, fine * 2);
    }
    while (fine - coarse > 1) {
        const int middle = (coarse + fine) / 2;
        if (fineEnough(surface, patches, middle, tolerance)) {
            fine = middle;
        } else {
            coarse = middle;
        }
    }
    return fine;
}

ShapeMesh shapeMesh(const model::Project& project, const MeshExportOptions& options) {
    if (project.surfaces.empty()) {
        throw ShapeExportError(ShapeExportError::Code::NoSurface);
    }
    ShapeMesh mesh;
    const bool several = project.surfaces.size() > 1;
    const double share = 1.0 / static_cast<double>(project.surfaces.size());
    for (std::size_t s = 0; s < project.surfaces.size(); ++s) {
        const model::CompositeSurface& surface = project.surfaces[s];
        if (options.progress && !options.progress(share * static_cast<double>(s))) {
            throw ShapeExportError(ShapeExportError::Code::Cancelled);
        }
        int samples = samplesForTolerance(surface, options.tolerance);
        if (samples > kMaxMeshSamples) {
            samples = kMaxMeshSamples;
            mesh.toleranceMet = false;
        }
        mesh.samplesPerInterval = std::max(mesh.samplesPerInterval, samples);
        if (options.progress && !options.progress(share * (static_cast<double>(s) + 0.5))) {
            throw ShapeExportError(ShapeExportError::Code::Cancelled);
        }
        const model::SampledMesh sampled = model::sampleSurface(surface, samples);
        const int first = static_cast<int>(mesh.vertices.size());
        mesh.vertices.insert(mesh.vertices.end(), sampled.vertices.begin(), sampled.vertices.end());
        std::map<model::FaceId, int> groupOf;
        for (std::size_t f = 0; f < sampled.faces.size(); ++f) {
            const model::FaceId face = sampled.faceOrigin[f];
            auto group = groupOf.find(face);
            if (group == groupOf.end()) {
                group = groupOf.emplace(face, static_cast<int>(mesh.groups.size())).first;
                mesh.groups.push_back(groupName(surface.id(), face, several));
            }
            const std::vector<int>& corners = sampled.faces[f];
            for (std::size_t k = 1; k + 1 < corners.size(); ++k) {
                mesh.triangles.push_back(
                    {first + corners[0], first + corners[k], first + corners[k + 1]});
                mesh.triangleGroup.push_back(group->second);
            }
        }
    }
    if (options.thickness > 0.0) {
        thicken(mesh, options.thickness);
    }
    return mesh;
}

QByteArray meshBytes(const ShapeMesh& mesh, MeshFormat format) {
    switch (format) {
    case MeshFormat::Obj:
        return objBytes(mesh);
    case MeshFormat::Stl:
        return openMeshBytes(mesh, ".stl");
    case MeshFormat::Ply:
        return openMeshBytes(mesh, ".ply");
    }
    return {};
}

ShapeMesh saveMeshFile(const model::Project& project, const QString& path,
                       const MeshExportOptions& options) {
    ShapeMesh mesh = shapeMesh(project, options);
    const QByteArray bytes = meshBytes(mesh, options.format);
    if (bytes.isEmpty()) {
        throw ShapeExportError(ShapeExportError::Code::Translate);
    }
    if (options.progress && !options.progress(1.0)) {
        throw ShapeExportError(ShapeExportError::Code::Cancelled);
    }
    writeFileAtomically(path, bytes);
    return mesh;
}

bool meshFormatFromName(const std::string& name, MeshFormat& format) {
    if (name == "obj") {
        format = MeshFormat::Obj;
    } else if (name == "stl") {
        format = MeshFormat::Stl;
    } else if (name == "ply") {
        format = MeshFormat::Ply;
    } else {
        return false;
    }
    return true;
}

} // namespace devsurf::io
