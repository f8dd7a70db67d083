#include "patch_distance.h"
#include "test_registry.h"

#include "io/project_file.h"
#include "io/shape/mesh_export.h"
#include "io/shape/patch_surfaces.h"
#include "io/shape/shape_export_error.h"
#include "model/examples.h"

#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTemporaryDir>
#include <QTest>

#include <cmath>

using namespace devsurf;

namespace {

// An independent reader: python3 without modules parses binary STL (and OBJ groups), and
// measures triangles, area, signed volume, boundary edges and directed edges used twice.
const char* const kReader = R"(
import json, struct, sys, math
def read(path):
    triangles = []
    groups = set()
    if path.endswith(".stl"):
        data = open(path, "rb").read()
        count = struct.unpack("<I", data[80:84])[0]
        assert len(data) == 84 + 50 * count, "size"
        for i in range(count):
            values = struct.unpack("<12f", data[84 + 50 * i: 84 + 50 * i + 48])
            triangles.append((values[3:6], values[6:9], values[9:12]))
    else:
        vertices = []
        for line in open(path):
            words = line.split()
            if not words:
                continue
            if words[0] == "v":
                vertices.append(tuple(float(w) for w in words[1:4]))
            elif words[0] == "g":
                groups.add(" ".join(words[1:]))
            elif words[0] == "f":
                triangles.append(tuple(vertices[int(w.split("/")[0]) - 1] for w in words[1:4]))
    def sub(a, b): return (a[0] - b[0], a[1] - b[1], a[2] - b[2])
    def cross(a, b): return (a[1]*b[2] - a[2]*b[1], a[2]*b[0] - a[0]*b[2], a[0]*b[1] - a[1]*b[0])
    area = 0.0
    volume = 0.0
    directed = {}
    for a, b, c in triangles:
        n = cross(sub(b, a), sub(c, a))
        area += 0.5 * math.sqrt(n[0]**2 + n[1]**2 + n[2]**2)
        volume += (a[0]*(b[1]*c[2] - b[2]*c[1]) - a[1]*(b[0]*c[2] - b[2]*c[0]) + a[2]*(b[0]*c[1] - b[1]*c[0])) / 6.0
        for p, q in ((a, b), (b, c), (c, a)):
            directed[(p, q)] = directed.get((p, q), 0) + 1
    boundary = sum(1 for (p, q) in directed if (q, p) not in directed)
    twice = sum(1 for k, v in directed.items() if v > 1)
    return {"triangles": len(triangles), "area": area, "volume": volume,
            "boundary": boundary, "twice": twice, "groups": len(groups)}
print(json.dumps([read(path) for path in sys.argv[1:]]))
)";

// One python run for many files (starting python takes about a second here).
QJsonArray readWithPython(const QStringList& paths) {
    QProcess python;
    python.start(QStringLiteral("python3"),
                 QStringList{QStringLiteral("-c"), QString::fromUtf8(kReader)} + paths);
    if (!python.waitForFinished(300000) || python.exitCode() != 0) {
        qWarning("%s", python.readAllStandardError().constData());
        return {};
    }
    return QJsonDocument::fromJson(python.readAllStandardOutput()).array();
}

QJsonObject readWithPython(const QString& path) {
    return readWithPython(QStringList{path}).at(0).toObject();
}

struct Exact {
    std::vector<io::PatchSurface> patches;
    double area = 0.0;
};

Exact exactOf(const model::Project& project) {
    Exact exact;
    for (const model::CompositeSurface& surface : project.surfaces) {
        for (io::PatchSurface& patch : io::patchSurfaces(surface)) {
            exact.area += io::patchArea(patch);
            exact.patches.push_back(std::move(patch));
        }
    }
    return exact;
}

// The boundary segments the mesh must have: the design's boundary edges, sampled.
int boundarySegments(const model::CompositeSurface& surface, int samples) {
    int count = 0;
    for (const auto& [id, record] : surface.edges()) {
        if (surface.facesOfEdge(id).size() == 1) {
            count += record.isSpline() ? record.space.intervals * samples : 1;
        }
    }
    return count;
}

} // namespace

class TstMeshExport : public QObject {
    Q_OBJECT

private slots:
    // Every example and a folded fig8 as binary STL and OBJ, read back by python: the triangles,
    // the area within what the chord tolerance allows, a watertight mesh (boundary only where the
    // design has one, every edge used once per direction), one OBJ group per patch.
    void examples() {
        QStringList names{QStringLiteral("fig8-folded")};
        for (const model::ExampleInfo& info : model::builtInExamples()) {
            names << QString::fromStdString(info.name);
        }
        struct Written {
            QString example;
            io::MeshFormat format;
            io::ShapeMesh mesh;
            model::Project project;
        };
        std::vector<Written> written;
        QStringList paths;
        QTemporaryDir folder;
        for (const QString& example : names) {
            // fig8-folded: see tst_cad_export.cpp.
            const model::Project project = example == QLatin1String("fig8-folded")
                                               ? io::loadProjectFile(QStringLiteral(
                                                     DEVSURF_TEST_DATA_DIR "/fig8-folded.devsurf"))
                                               : model::makeExample(example.toStdString());
            io::MeshExportOptions options;
            options.tolerance = 1e-3 * io::projectDiameter(project);
            for (io::MeshFormat format : {io::MeshFormat::Stl, io::MeshFormat::Obj}) {
                options.format = format;
                const QString path =
                    folder.filePath(example + (format == io::MeshFormat::Stl ? ".stl" : ".obj"));
                written.push_back(
                    {example, format, io::saveMeshFile(project, path, options), project});
                paths << path;
            }
        }
        const QJsonArray read = readWithPython(paths);
        QCOMPARE(read.size(), paths.size());
        for (std::size_t i = 0; i < written.size(); ++i) {
            const Written& w = written[i];
            const QJsonObject back = read[static_cast<int>(i)].toObject();
            const Exact exact = exactOf(w.project);
            QCOMPARE(back["triangles"].toInt(), static_cast<int>(w.mesh.triangles.size()));
            QCOMPARE(back["twice"].toInt(-1), 0);
            QCOMPARE(back["boundary"].toInt(-1),
                     boundarySegments(w.project.surfaces.front(), w.mesh.samplesPerInterval));
            // Inscribed triangles lose area of the order of tolerance / diameter.
            const double areaError = std::abs(back["area"].toDouble() - exact.area) / exact.area;
            QVERIFY2(areaError <= 1e-2, qPrintable(w.example + QString::number(areaError)));
            if (w.format == io::MeshFormat::Obj) {
                QCOMPARE(back["groups"].toInt(), static_cast<int>(exact.patches.size()));
            }
            qInfo("%s %s: %d triangles (%d samples per interval), area error %.2g",
                  qPrintable(w.example), w.format == io::MeshFormat::Stl ? "STL" : "OBJ",
                  back["triangles"].toInt(), w.mesh.samplesPerInterval, areaError);
        }
    }

    // The chord tolerance holds: every triangle's centre lies within it of the exact surface.
    void tolerance() {
        const model::Project project =
            io::loadProjectFile(QStringLiteral(DEVSURF_TEST_DATA_DIR "/fig8-folded.devsurf"));
        const Exact exact = exactOf(project);
        for (double tolerance : {1.0, 0.1, 0.01}) {
            io::MeshExportOptions options;
            options.tolerance = tolerance;
            const io::ShapeMesh mesh = io::shapeMesh(project, options);
            double farthest = 0.0;
            for (std::size_t i = 0; i < mesh.triangles.size(); i += 7) {
                const auto& t = mesh.triangles[i];
                const model::Vec3 centre =
                    (mesh.vertices[t[0]] + mesh.vertices[t[1]] + mesh.vertices[t[2]]) / 3.0;
                farthest = std::max(farthest, test::distanceToPatches(centre, exact.patches));
            }
            QVERIFY2(farthest <= tolerance, qPrintable(QString::number(farthest)));
        }
    }

    // A thickness makes a closed, consistently oriented solid of about area × thickness.
    void thickness() {
        const model::Project project = model::makeExample("annulus");
        const Exact exact = exactOf(project);
        io::MeshExportOptions options;
        options.thickness = 0.5;
        options.tolerance = 0.05;
        QTemporaryDir folder;
        const QString path = folder.filePath("solid.stl");
        io::saveMeshFile(project, path, options);
        const QJsonObject back = readWithPython(path);
        QCOMPARE(back["boundary"].toInt(-1), 0);
        QCOMPARE(back["twice"].toInt(-1), 0);
        const double volume = back["volume"].toDouble();
        QVERIFY2(std::abs(volume - exact.area * options.thickness) <= 0.01 * volume,
                 qPrintable(QString::number(volume)));
    }

    // A tolerance no sampling reaches is said, not hidden; a cancel writes nothing.
    void unreachableToleranceAndCancel() {
        const model::Project project = model::makeExample("cylinder");
        io::MeshExportOptions options;
        options.tolerance = 1e-9;
        const io::ShapeMesh fine = io::shapeMesh(project, options);
        QVERIFY(!fine.toleranceMet);
        QCOMPARE(fine.samplesPerInterval, io::kMaxMeshSamples);
        options.tolerance = 0.01;
        QVERIFY(io::shapeMesh(project, options).toleranceMet);
        QTemporaryDir folder;
        const QString path = folder.filePath("cancelled.stl");
        options.progress = [](double fraction) { return fraction < 0.4; };
        try {
            io::saveMeshFile(project, path, options);
            QFAIL("not cancelled");
        } catch (const io::ShapeExportError& error) {
            QCOMPARE(error.code(), io::ShapeExportError::Code::Cancelled);
        }
        QVERIFY(!QFile::exists(path));
    }

    // PLY and STL through OpenMesh's readers: as many faces, the same area.
    void openMeshReadsBack() {
        using Mesh = OpenMesh::TriMesh_ArrayKernelT<>;
        const model::Project project = model::makeExample("cylinder");
        QTemporaryDir folder;
        io::MeshExportOptions options;
        options.format = io::MeshFormat::Ply;
        const QString path = folder.filePath("shape.ply");
        const io::ShapeMesh mesh = io::saveMeshFile(project, path, options);
        Mesh read;
        QVERIFY(OpenMesh::IO::read_mesh(read, path.toStdString()));
        QCOMPARE(read.n_faces(), mesh.triangles.size());
        QCOMPARE(read.n_vertices(), mesh.vertices.size());
        double area = 0.0;
        for (const auto& t : mesh.triangles) {
            area += 0.5 * model::cross(mesh.vertices[t[1]] - mesh.vertices[t[0]],
                                       mesh.vertices[t[2]] - mesh.vertices[t[0]])
                              .norm();
        }
        double readArea = 0.0;
        for (const Mesh::FaceHandle face : read.faces()) {
            readArea += read.calc_face_area(face);
        }
        QVERIFY(std::abs(readArea - area) <= 1e-5 * area);
    }
};

DEVSURF_REGISTER_TEST(TstMeshExport);

#include "tst_mesh_export.moc"
