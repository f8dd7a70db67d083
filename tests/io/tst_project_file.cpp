#include "io/crc32.h"
#include "io/file_error.h"
#include "io/project_file.h"
#include "model/development.h"
#include "model/examples.h"
#include "model/sampled_mesh.h"
#include "model/surface_statistics.h"
#include "test_registry.h"

#include <QFile>
#include <QTemporaryDir>
#include <QTest>

#include <functional>
#include <limits>
#include <set>

using namespace devsurf;

namespace {

std::string readAll(const QString& path) {
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) {
        return {};
    }
    const QByteArray data = file.readAll();
    return std::string(data.constData(), static_cast<std::size_t>(data.size()));
}

void writeAll(const QString& path, const std::string& bytes) {
    QFile file(path);
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write(bytes.data(), static_cast<qint64>(bytes.size()));
}

std::string messageOf(const std::string& bytes) {
    try {
        io::decodeProject(bytes);
    } catch (const io::FileError& error) {
        return error.what();
    }
    return {};
}

} // namespace

class TstProjectFile : public QObject {
    Q_OBJECT
private slots:
    void crcMatchesTheStandardCheckValue() {
        const char text[] = "123456789";
        QCOMPARE(io::crc32(text, 9), 0xCBF43926u);
        QCOMPARE(io::crc32(text, 0), 0u);
    }

    void roundTripIsByteIdenticalForEveryExample() {
        for (const model::ExampleInfo& info : model::builtInExamples()) {
            for (int size : {0, info.minSize}) {
                const model::Project project = model::makeExample(info.name, size);
                const std::string first = io::encodeProject(project);
                const model::Project loaded = io::decodeProject(first);
                QVERIFY(loaded == project);
                QCOMPARE(io::encodeProject(loaded), first);
            }
        }
    }

    void savingKeepsThePreviousFileAsBackup() {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const QString path = dir.filePath("design.devsurf");
        const model::Project sheet = model::makeExample("sheet");
        const model::Project annulus = model::makeExample("annulus");
        io::saveProjectFile(sheet, path);
        QVERIFY(!QFile::exists(path + ".bak"));
        io::saveProjectFile(annulus, path);
        QVERIFY(io::loadProjectFile(path) == annulus);
        QVERIFY(io::loadProjectFile(path + ".bak") == sheet);
        QCOMPARE(readAll(path), io::encodeProject(annulus));
    }

    void unreadableFilesGiveOneSentenceNamingTheFile() {
        QTemporaryDir dir;
        const QString path = dir.filePath("broken.devsurf");
        const std::string good = io::encodeProject(model::makeExample("mixed"));
        writeAll(path, good.substr(0, good.size() / 2));
        try {
            io::loadProjectFile(path);
            QFAIL("a truncated file loaded");
        } catch (const io::FileError& error) {
            const std::string message = error.what();
            QVERIFY(message.find("broken.devsurf") != std::string::npos);
            QVERIFY(message.find("truncated") != std::string::npos);
            QCOMPARE(message.back(), '.');
            QVERIFY(message.find('\n') == std::string::npos);
        }
        QVERIFY_THROWS_EXCEPTION(io::FileError,
                                 io::loadProjectFile(dir.filePath("missing.devsurf")));
    }

    void eachEnvelopeFaultHasItsOwnMessage() {
        const std::string good = io::encodeProject(model::makeExample("mixed"));
        QVERIFY(messageOf("hello world, this is not a project").find("not a DevSurf") !=
                std::string::npos);
        std::string newer = good;
        newer[8] = 8;
        QVERIFY(messageOf(newer).find("newer version") != std::string::npos);
        std::string zero = good;
        zero[8] = 0;
        QVERIFY(messageOf(zero).find("version 0") != std::string::npos);
        std::string flipped = good;
        flipped[flipped.size() - 10] ^= 0x20;
        QVERIFY(messageOf(flipped).find("checksum") != std::string::npos);
        QVERIFY(messageOf(good + "x").find("unexpected bytes") != std::string::npos);
        QVERIFY(messageOf(good.substr(0, 30)).find("truncated") != std::string::npos);
        QVERIFY(messageOf(good).empty());
    }

    void newerClassVersionsAreRefused() {
        // Change the project's class version inside the archive and fix up the envelope, so
        // only our own version check can refuse it.
        std::string bytes = io::encodeProject(model::makeExample("sheet"));
        std::string payload = bytes.substr(io::kProjectHeaderSize);
        const std::string header = "serialization::archive ";
        const std::size_t at = payload.find(header);
        QVERIFY(at != std::string::npos);
        // "22 serialization::archive 19 0 3 ..." : tracking 0, version 3 of Project.
        std::size_t pos = payload.find(' ', at + header.size()); // after library version
        pos = payload.find(' ', pos + 1);                        // after tracking level
        QCOMPARE(payload[pos + 1], '3');
        payload[pos + 1] = '9';
        std::string patched = bytes.substr(0, 20);
        const std::uint32_t crc = io::crc32(payload.data(), payload.size());
        for (int i = 0; i < 4; ++i) {
            patched.push_back(static_cast<char>((crc >> (8 * i)) & 0xFF));
        }
        patched += payload;
        const std::string message = messageOf(patched);
        QVERIFY2(message.find("newer version of DevSurf (project version 9") != std::string::npos,
                 message.c_str());
    }

    void versionOneSampleStaysLoadable() {
        // Committed once with format version 1; it must load with every later version.
        const QString path = QStringLiteral(DEVSURF_TEST_DATA_DIR "/sample-v1.devsurf");
        const model::Project project = io::loadProjectFile(path);
        QCOMPARE(project.units, std::string("mm"));
        QCOMPARE(project.surfaces.size(), std::size_t(1));
        const model::SurfaceStatistics stats = model::surfaceStatistics(project.surfaces[0]);
        QCOMPARE(stats.faces(), std::size_t(4));
        QCOMPARE(stats.controlPoints, std::size_t(22));
        QCOMPARE(stats.splineEdges, std::size_t(5));
        QVERIFY(project.surfaces[0].validate().empty());
        // Version 1 had no pins; it reads as the same design with none pinned.
        QVERIFY(project.surfaces[0].pinnedVertices().empty());
        QVERIFY(project == model::makeExample("mixed", 0));
        // Saved again it becomes a file of the current version holding the same project.
        QVERIFY(io::encodeProject(project) != readAll(path));
        QVERIFY(io::decodeProject(io::encodeProject(project)) == project);
    }

    void versionTwoSampleStaysLoadable() {
        // Committed once with format version 2 (the mixed example, vertices 0 and 3 pinned);
        // it must load with every later version.
        const QString path = QStringLiteral(DEVSURF_TEST_DATA_DIR "/sample-v2.devsurf");
        const std::string bytes = readAll(path);
        QCOMPARE(bytes.substr(8, 4), std::string("\x02\x00\x00\x00", 4));
        const model::Project project = io::loadProjectFile(path);
        QCOMPARE(project.surfaces.size(), std::size_t(1));
        QCOMPARE(project.surfaces[0].pinnedVertices(), (std::set<model::VertexId>{0, 3}));
        model::Project expected = model::makeExample("mixed", 0);
        expected.surfaces[0].setPinned(0, true);
        expected.surfaces[0].setPinned(3, true);
        QVERIFY(project == expected);
    }

    void versionThreeSampleStaysLoadable() {
        // Committed once with format version 3 (the sheet example, surface id 1, with vertex 0
        // pinned, its inner rulings 1 and 5 smooth and its crease 9 a geodesic); it must load
        // with every later version.
        const QString path = QStringLiteral(DEVSURF_TEST_DATA_DIR "/sample-v3.devsurf");
        const std::string bytes = readAll(path);
        QCOMPARE(bytes.substr(8, 4), std::string("\x03\x00\x00\x00", 4));
        const model::Project project = io::loadProjectFile(path);
        model::Project expected = model::makeExample("sheet", 0);
        model::CompositeSurface& s = expected.surfaces[0];
        s.setPinned(0, true);
        s.setSmooth(1, true);
        s.setSmooth(5, true);
        s.setCreaseCondition(9, model::CreaseCondition::Geodesic);
        QVERIFY(project.surfaces[0].edge(1).smooth && !project.surfaces[0].edge(10).smooth);
        QCOMPARE(project.surfaces[0].id(), model::SurfaceId(1));
        QVERIFY(project == expected);
    }

    void surfaceIdsRoundTripAndOldFilesGetThem() {
        model::Project project;
        project.addSurface(model::makeExample("sheet", 2).surfaces[0]);
        project.addSurface(model::makeExample("mixed", 1).surfaces[0]);
        project.surfaces[0].setId(9);
        project.surfaces[1].setId(4);
        const model::Project loaded = io::decodeProject(io::encodeProject(project));
        QCOMPARE(loaded.surfaces[0].id(), model::SurfaceId(9));
        QCOMPARE(loaded.surfaces[1].id(), model::SurfaceId(4));
        QVERIFY(loaded == project);
        QCOMPARE(loaded.indexOf(4), 1);
        QCOMPARE(loaded.indexOf(5), -1);
        // Files of formats 1 and 2 hold no ids: their surfaces are numbered from 1 on loading.
        const model::Project v2 =
            io::loadProjectFile(QStringLiteral(DEVSURF_TEST_DATA_DIR "/sample-v2.devsurf"));
        QCOMPARE(v2.surfaces[0].id(), model::SurfaceId(1));
        // Missing or repeated ids get new ones; unique ones are kept.
        model::Project repeated = project;
        repeated.surfaces[1].setId(9);
        repeated.addSurface(model::makeExample("sheet", 1).surfaces[0]);
        repeated.surfaces[2].setId(0);
        repeated.assignSurfaceIds();
        QCOMPARE(repeated.surfaces[0].id(), model::SurfaceId(9));
        QCOMPARE(repeated.surfaces[1].id(), model::SurfaceId(10));
        QCOMPARE(repeated.surfaces[2].id(), model::SurfaceId(11));
    }

    void smoothRulingsRoundTrip() {
        model::Project project = model::makeExample("annulus", 0);
        model::CompositeSurface& surface = project.surfaces[0];
        std::set<model::EdgeId> smooth;
        for (const auto& [id, record] : surface.edges()) {
            if (!record.isSpline() && surface.facesOfEdge(id).size() == 2 && id % 2 == 0) {
                surface.setSmooth(id, true);
                smooth.insert(id);
            }
        }
        QVERIFY(smooth.size() > 5);
        const model::Project loaded = io::decodeProject(io::encodeProject(project));
        QVERIFY(loaded == project);
        for (const auto& [id, record] : loaded.surfaces[0].edges()) {
            QCOMPARE(record.smooth, smooth.count(id) != 0);
        }
        // The flag is part of the design: clearing one changes what is saved.
        model::Project sharp = project;
        sharp.surfaces[0].setSmooth(*smooth.begin(), false);
        QVERIFY(!(sharp == project));
        QVERIFY(io::encodeProject(sharp) != io::encodeProject(project));
    }

    void pinsRoundTrip() {
        model::Project project = model::makeExample("annulus", 0);
        model::CompositeSurface& surface = project.surfaces[0];
        for (const auto& entry : surface.vertices()) {
            if (entry.first % 3 == 0) {
                surface.setPinned(entry.first, true);
            }
        }
        QVERIFY(surface.pinnedVertices().size() > 10);
        const model::Project loaded = io::decodeProject(io::encodeProject(project));
        QCOMPARE(loaded.surfaces[0].pinnedVertices(), surface.pinnedVertices());
        QVERIFY(loaded == project);
        // A pin is part of the design: unpinning one changes what is saved.
        model::Project unpinned = project;
        unpinned.surfaces[0].setPinned(*surface.pinnedVertices().begin(), false);
        QVERIFY(!(unpinned == project));
        QVERIFY(io::encodeProject(unpinned) != io::encodeProject(project));
    }

    void sheetShapesRoundTrip() {
        // Every shape, with sizes and a placement that are not round numbers, survives bit for
        // bit; an unusable size is refused with the problem's code.
        model::Project project = model::makeExample("fig8", 0);
        model::CompositeSurface& surface = project.surfaces[0];
        QVERIFY(!model::keepDevelopment(surface).has_value());
        model::SheetDomain d;
        d.centre = {1.0 / 3.0, -2.0 / 7.0};
        d.angle = 0.1;
        for (model::SheetShape shape :
             {model::SheetShape::Rectangle, model::SheetShape::Disk, model::SheetShape::Annulus,
              model::SheetShape::Outline, model::SheetShape::Cylinder}) {
            d.shape = shape;
            d.width = 300.0 / 7.0;
            d.height = 200.0 / 3.0;
            d.radius = 250.0 / 3.0;
            d.innerRadius = 100.0 / 3.0;
            d.outline = {{{0, 0}, {310.0 / 3.0, 0}, {100, 100}}, {{10, 10}, {20, 10}, {20, 20}}};
            // Crease curves (format 7): an open one and a closed one, an edge on each.
            d.creaseCurves = {{{{0, 0}, {1.0 / 3.0, 5e-300}}, false},
                              {{{1, 1}, {2, 1}, {2, 2.0 / 7.0}}, true}};
            d.creaseCurveOf = {{4, 1}, {7, 0}};
            surface.setSheetDomain(d);
            const std::string bytes = io::encodeProject(project);
            const model::Project loaded = io::decodeProject(bytes);
            QVERIFY(loaded.surfaces[0].sheetDomain() == d);
            QCOMPARE(io::encodeProject(loaded), bytes);
        }
        d.shape = model::SheetShape::Annulus;
        d.innerRadius = 2.0 * d.radius;
        surface.setSheetDomain(d);
        bool refused = false;
        try {
            io::decodeProject(io::encodeProject(project));
        } catch (const io::FileError& error) {
            refused = !error.problems().empty() &&
                      error.problems().front().code == model::ProblemCode::SheetDomainInvalid;
        }
        QVERIFY(refused);
        // A crease assigned to a curve that is not there is refused the same way.
        d.innerRadius = 0.5 * d.radius;
        d.creaseCurveOf[9] = 2;
        surface.setSheetDomain(d);
        refused = false;
        try {
            io::decodeProject(io::encodeProject(project));
        } catch (const io::FileError& error) {
            refused = !error.problems().empty() &&
                      error.problems().front().code == model::ProblemCode::SheetDomainInvalid &&
                      error.problems().front().count == 4;
        }
        QVERIFY(refused);
    }

    void keptDevelopmentRoundTrips() {
        model::Project project = model::makeExample("fig8", 0);
        model::CompositeSurface& surface = project.surfaces[0];
        surface.setKeepsDevelopment(true);
        const model::Development unfolded = model::unfoldSampledMesh(
            model::sampleSurface(surface, model::kDevelopmentSamplesPerInterval));
        std::vector<model::Vec2> points = unfolded.vertices;
        points.front().x += 1.0 / 3.0; // not a round number: the bits must survive
        surface.setDevelopment(points);
        const std::string bytes = io::encodeProject(project);
        const model::Project loaded = io::decodeProject(bytes);
        QVERIFY(loaded.surfaces[0].keepsDevelopment());
        QVERIFY(loaded.surfaces[0].development() == points);
        QVERIFY(loaded == project);
        QCOMPARE(io::encodeProject(loaded), bytes);
        // The setting alone (nothing derived yet) is saved too.
        model::Project settingOnly = project;
        settingOnly.surfaces[0].setDevelopment({});
        QVERIFY(io::decodeProject(io::encodeProject(settingOnly)) == settingOnly);
        // A development that does not fit the surface is refused with a sentence.
        model::Project damaged = project;
        points.pop_back();
        damaged.surfaces[0].setDevelopment(points);
        bool refused = false;
        try {
            io::decodeProject(io::encodeProject(damaged));
        } catch (const io::FileError& error) {
            refused = !error.problems().empty() &&
                      error.problems().front().code == model::ProblemCode::DevelopmentSize;
        }
        QVERIFY(refused);
    }

    void versionFourSampleStaysLoadable() {
        // Committed once with format version 4 (fig8 with vertex 0 pinned, holding its sheet:
        // its kept development); it must load with every later version, without curves.
        const QString path = QStringLiteral(DEVSURF_TEST_DATA_DIR "/sample-v4.devsurf");
        const std::string bytes = readAll(path);
        QCOMPARE(bytes.substr(8, 4), std::string("\x04\x00\x00\x00", 4));
        const model::Project project = io::loadProjectFile(path);
        QCOMPARE(project.surfaces.size(), std::size_t(1));
        QVERIFY(project.referenceCurves.empty());
        const model::CompositeSurface& s = project.surfaces[0];
        QVERIFY(s.keepsDevelopment());
        QVERIFY(s.sheetDomain().isFree());
        QCOMPARE(s.development().size(), std::size_t(76));
        QVERIFY(s.isPinned(0));
        model::Project expected = model::makeExample("fig8", 0);
        expected.surfaces[0].setPinned(0, true);
        expected.surfaces[0].setKeepsDevelopment(true);
        expected.surfaces[0].setDevelopment(s.development());
        QVERIFY(project == expected);
        // Saved again it is a file of the current format holding the same project.
        const std::string again = io::encodeProject(project);
        QCOMPARE(again.substr(8, 4), std::string("\x07\x00\x00\x00", 4));
        QVERIFY(io::decodeProject(again) == project);
    }

    void versionFiveSampleStaysLoadable() {
        // Committed once with format version 5 (fig8 with vertices 0 and 3 pinned, holding its
        // sheet on a 300 x 300 mm rectangle, and the two curves of an SVG drawing: a line and a
        // circle); it must load with every later version.
        const QString path = QStringLiteral(DEVSURF_TEST_DATA_DIR "/sample-v5.devsurf");
        const std::string bytes = readAll(path);
        QCOMPARE(bytes.substr(8, 4), std::string("\x05\x00\x00\x00", 4));
        const model::Project project = io::loadProjectFile(path);
        QCOMPARE(project.surfaces.size(), std::size_t(1));
        const model::CompositeSurface& s = project.surfaces[0];
        QCOMPARE(s.name(), std::string("fig8"));
        QCOMPARE(s.pinnedVertices(), (std::set<model::VertexId>{0, 3}));
        QVERIFY(s.keepsDevelopment());
        QCOMPARE(s.development().size(), std::size_t(76));
        QVERIFY(s.sheetDomain().shape == model::SheetShape::Rectangle);
        QCOMPARE(s.sheetDomain().width, 300.0);
        QCOMPARE(s.sheetDomain().height, 300.0);
        QCOMPARE(project.referenceCurves.size(), std::size_t(2));
        QCOMPARE(project.referenceCurves[0].name, std::string("SVG path 1"));
        QCOMPARE(project.referenceCurves[0].points.size(), std::size_t(2));
        QVERIFY(project.referenceCurves[0].points[0] == model::Vec3(0, 0, 0));
        QCOMPARE(project.referenceCurves[1].points.size(), std::size_t(49));
        QVERIFY(project.referenceCurves[1].points[0] == model::Vec3(70, -25, 0));
        QVERIFY(s.validate().empty());
        QVERIFY(project.referenceShapes.empty()); // format 5 had none
        // Saved again it holds the same project.
        QVERIFY(io::decodeProject(io::encodeProject(project)) == project);
    }

    void versionSixSampleStaysLoadable() {
        // Committed once with format version 6 (the annulus with vertex 0 pinned, holding its
        // sheet on an annulus of radii 90 and 260 mm); it must load with every later version,
        // without crease curves.
        const QString path = QStringLiteral(DEVSURF_TEST_DATA_DIR "/sample-v6.devsurf");
        const std::string bytes = readAll(path);
        QCOMPARE(bytes.substr(8, 4), std::string("\x06\x00\x00\x00", 4));
        const model::Project project = io::loadProjectFile(path);
        QCOMPARE(project.surfaces.size(), std::size_t(1));
        const model::CompositeSurface& s = project.surfaces[0];
        QCOMPARE(s.name(), std::string("annulus"));
        QCOMPARE(s.pinnedVertices(), (std::set<model::VertexId>{0}));
        QVERIFY(s.keepsDevelopment());
        QCOMPARE(s.development().size(), std::size_t(336));
        QVERIFY(s.sheetDomain().shape == model::SheetShape::Annulus);
        QCOMPARE(s.sheetDomain().radius, 260.0);
        QCOMPARE(s.sheetDomain().innerRadius, 90.0);
        QVERIFY(s.sheetDomain().creaseCurves.empty());
        QVERIFY(s.sheetDomain().creaseCurveOf.empty());
        QVERIFY(s.validate().empty());
        const std::string again = io::encodeProject(project);
        QCOMPARE(again.substr(8, 4), std::string("\x07\x00\x00\x00", 4));
        QVERIFY(io::decodeProject(again) == project);
    }

    void referenceCurvesRoundTripByteIdentical() {
        model::Project project = model::makeExample("sheet", 0);
        project.referenceCurves.push_back(
            {"SPLINE 1", "GUIDES", {{0, 0, 0}, {1.0 / 3.0, 2e-300, -7.25}, {1e6, -0.1, 5}}});
        project.referenceCurves.push_back({"Edge 2", "", {{1, 2, 3}, {4, 5, 6}}});
        const std::string bytes = io::encodeProject(project);
        const model::Project loaded = io::decodeProject(bytes);
        QCOMPARE(loaded.referenceCurves.size(), std::size_t(2));
        QVERIFY(loaded.referenceCurves[0] == project.referenceCurves[0]); // every bit
        QVERIFY(loaded == project);
        QCOMPARE(io::encodeProject(loaded), bytes);
        // Curves are part of the project: without them the file differs.
        model::Project without = project;
        without.referenceCurves.pop_back();
        QVERIFY(!(without == project));
        QVERIFY(io::encodeProject(without) != bytes);
        // A project with no curves still round-trips.
        model::Project none = model::makeExample("annulus", 0);
        QVERIFY(io::decodeProject(io::encodeProject(none)) == none);
    }

    void damagedReferenceCurvesAreRefused() {
        model::Project project = model::makeExample("sheet", 0);
        project.referenceCurves.push_back({"L", "", {{0, 0, 0}, {1, 1, 1}}});
        // A curve of one point (as a damaged file may hold) is refused with a sentence.
        model::Project onePoint = project;
        onePoint.referenceCurves[0].points.pop_back();
        const std::string message = messageOf(io::encodeProject(onePoint));
        QVERIFY2(message.find("fewer than two points") != std::string::npos, message.c_str());
        model::Project notANumber = project;
        notANumber.referenceCurves[0].points[1].x = std::numeric_limits<double>::infinity();
        QVERIFY(!messageOf(io::encodeProject(notANumber)).empty());
    }
};

namespace {

// A tetrahedron (a mesh with normals) and a point cloud without normals, with coordinates that
// a decimal round trip could change.
model::Project withReferenceShapes(model::Project project) {
    model::ReferenceShape mesh;
    mesh.name = "tetrahedron";
    mesh.source = "/data/tet.obj";
    mesh.points = {{0, 0, 0}, {1.0 / 3.0, 0, 0}, {0, 2e-300, 0}, {0, 0, -1e6}};
    mesh.normals = {{0, 0, 1}, {0.6, 0.8, 0}, {0, -1, 0}, {-1.0 / 7.0, 0, 0}};
    mesh.triangles = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}};
    project.referenceShapes.push_back(mesh);
    model::ReferenceShape cloud;
    cloud.name = "scan";
    cloud.points = {{0.1, 0.2, 0.3}, {-4.5, 5.25, 6}, {7, 8, 9.125}};
    project.referenceShapes.push_back(cloud);
    return project;
}

} // namespace

class TstProjectShapes : public QObject {
    Q_OBJECT
private slots:
    void referenceShapesRoundTripByteIdentical() {
        const model::Project project = withReferenceShapes(model::makeExample("sheet", 0));
        const std::string bytes = io::encodeProject(project);
        QCOMPARE(bytes.substr(8, 4), std::string("\x07\x00\x00\x00", 4));
        const model::Project loaded = io::decodeProject(bytes);
        QCOMPARE(loaded.referenceShapes.size(), std::size_t(2));
        QVERIFY(loaded.referenceShapes[0] == project.referenceShapes[0]); // every bit
        QVERIFY(!loaded.referenceShapes[0].isPointCloud());
        QVERIFY(loaded.referenceShapes[1].isPointCloud());
        QVERIFY(loaded.referenceShapes[1].normals.empty());
        QVERIFY(loaded == project);
        QCOMPARE(io::encodeProject(loaded), bytes);
        // Shapes are part of the project: without one the file differs.
        model::Project without = project;
        without.referenceShapes.pop_back();
        QVERIFY(!(without == project));
        QVERIFY(io::encodeProject(without) != bytes);
        // Through a file on disk as well.
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("shapes.devsurf"));
        io::saveProjectFile(project, path);
        QVERIFY(io::loadProjectFile(path) == project);
        QCOMPARE(readAll(path), bytes);
    }

    void damagedReferenceShapesAreRefused() {
        const model::Project good = withReferenceShapes(model::makeExample("sheet", 0));
        auto refusal = [&good](const std::function<void(model::ReferenceShape&)>& damage) {
            model::Project project = good;
            damage(project.referenceShapes[0]);
            return messageOf(io::encodeProject(project));
        };
        std::string message = refusal([](model::ReferenceShape& s) { s.triangles[2][1] = 4; });
        QVERIFY2(message.find("triangle corner 4") != std::string::npos, message.c_str());
        message = refusal([](model::ReferenceShape& s) { s.triangles[0][0] = -1; });
        QVERIFY2(message.find("triangle corner -1") != std::string::npos, message.c_str());
        // The text archive cannot even read a NaN or an infinity back: refused all the same.
        message = refusal([](model::ReferenceShape& s) {
            s.points[3].y = std::numeric_limits<double>::quiet_NaN();
        });
        QVERIFY2(message.find("damaged") != std::string::npos, message.c_str());
        message = refusal([](model::ReferenceShape& s) {
            s.normals[0].z = std::numeric_limits<double>::infinity();
        });
        QVERIFY2(message.find("damaged") != std::string::npos, message.c_str());
        message = refusal([](model::ReferenceShape& s) { s.normals.pop_back(); });
        QVERIFY2(message.find("3 normals for 4 points") != std::string::npos, message.c_str());
        message = refusal([](model::ReferenceShape& s) {
            s.points.clear();
            s.normals.clear();
            s.triangles.clear();
        });
        QVERIFY2(message.find("without points") != std::string::npos, message.c_str());
    }
};

DEVSURF_REGISTER_TEST(TstProjectFile);
DEVSURF_REGISTER_TEST(TstProjectShapes);
#include "tst_project_file.moc"
