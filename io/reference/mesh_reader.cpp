#include "reference_readers.h"

#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>

#include <cmath>
#include <new>

namespace devsurf::io::reference {

namespace {

using Code = ReferenceImportError::Code;

// Double precision points and normals: a scan in mm keeps its digits.
struct Traits : public OpenMesh::DefaultTraits {
    using Point = OpenMesh::Vec3d;
    using Normal = OpenMesh::Vec3d;
};
using Mesh = OpenMesh::TriMesh_ArrayKernelT<Traits>;

// OpenMesh writes its warnings ("complex edge", "unknown keyword") to standard error; the
// command line's stderr carries one sentence only, so they are silenced while a file is read.
class QuietOpenMesh {
public:
    QuietOpenMesh()
        : m_err(::omerr().is_enabled()), m_log(::omlog().is_enabled()),
          m_out(::omout().is_enabled()) {
        ::omerr().disable();
        ::omlog().disable();
        ::omout().disable();
    }
    ~QuietOpenMesh() {
        if (m_err) {
            ::omerr().enable();
        }
        if (m_log) {
            ::omlog().enable();
        }
        if (m_out) {
            ::omout().enable();
        }
    }
    QuietOpenMesh(const QuietOpenMesh&) = delete;
    QuietOpenMesh& operator=(const QuietOpenMesh&) = delete;

private:
    bool m_err;
    bool m_log;
    bool m_out;
};

} // namespace

// Polygons come out as triangle fans (OpenMesh's triangle mesh); faces that would make an edge
// shared by more than two faces are left out by OpenMesh.
ReferenceImportResult readMeshFile(const std::string& path, std::uint64_t expectedPoints,
                                   bool pointNormals) {
    Mesh mesh;
    OpenMesh::IO::Options options;
    if (pointNormals) {
        mesh.request_vertex_normals();
        options += OpenMesh::IO::Options::VertexNormal;
    }
    bool read = false;
    try {
        const QuietOpenMesh quiet;
        read = OpenMesh::IO::read_mesh(mesh, path, options);
    } catch (const std::bad_alloc&) {
        return failure(Code::TooLarge, "there is not enough memory");
    } catch (const std::exception& error) {
        return failure(Code::Damaged, error.what());
    }
    if (!read) {
        return failure(Code::Damaged);
    }
    if (mesh.n_vertices() == 0) {
        return failure(Code::NoPoints);
    }
    if (expectedPoints != 0 && mesh.n_vertices() != expectedPoints) {
        return failure(Code::Damaged, "it holds " + std::to_string(expectedPoints) +
                                          " points, of which " + std::to_string(mesh.n_vertices()) +
                                          " could be read");
    }
    model::ReferenceShape shape;
    shape.points.reserve(mesh.n_vertices());
    for (const auto vertex : mesh.vertices()) {
        const OpenMesh::Vec3d& p = mesh.point(vertex);
        shape.points.emplace_back(p[0], p[1], p[2]);
        if (!isSane(shape.points.back())) {
            return failure(Code::NotANumber, "point " + std::to_string(vertex.idx() + 1));
        }
    }
    if (pointNormals && options.check(OpenMesh::IO::Options::VertexNormal)) {
        shape.normals.reserve(mesh.n_vertices());
        for (const auto vertex : mesh.vertices()) {
            const OpenMesh::Vec3d& n = mesh.normal(vertex);
            if (!std::isfinite(n[0]) || !std::isfinite(n[1]) || !std::isfinite(n[2])) {
                return failure(Code::NotANumber,
                               "the normal of point " + std::to_string(vertex.idx() + 1));
            }
            shape.normals.emplace_back(n[0], n[1], n[2]);
        }
    }
    shape.triangles.reserve(mesh.n_faces());
    for (const auto face : mesh.faces()) {
        std::array<int, 3> corners{};
        std::size_t k = 0;
        for (const auto vertex : mesh.fv_range(face)) {
            if (k < 3) {
                corners[k] = vertex.idx();
            }
            ++k;
        }
        if (k == 3) {
            shape.triangles.push_back(corners);
        }
    }
    ReferenceImportResult result;
    result.shape = std::move(shape);
    return result;
}

} // namespace devsurf::io::reference
