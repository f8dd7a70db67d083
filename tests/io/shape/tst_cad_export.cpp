#include "freecad_reader.h"
#include "patch_distance.h"
#include "test_registry.h"

#include "io/project_file.h"
#include "io/shape/cad_export.h"
#include "io/shape/patch_surfaces.h"
#include "model/examples.h"

#include <QFile>
#include <QTemporaryDir>
#include <QTest>

#include <cmath>
#include <map>

using namespace devsurf;

namespace {

const char* formatName(io::CadFormat format) {
    switch (format) {
    case io::CadFormat::StepAP214:
        return "step214";
    case io::CadFormat::StepAP242:
        return "step242";
    case io::CadFormat::Iges:
        return "iges";
    }
    return "";
}

// A built-in example, or "fig8-folded": fig8 folded by devsurf-cli drag --vertices 12,13,14,15
// --by 0,-60,150 (valley folds of 47°, mountain folds of 15°).
model::Project projectNamed(const QString& name) {
    if (name == QLatin1String("fig8-folded")) {
        return io::loadProjectFile(QStringLiteral(DEVSURF_TEST_DATA_DIR "/fig8-folded.devsurf"));
    }
    return model::makeExample(name.toStdString());
}

} // namespace

// Every built-in example as STEP (AP242), and several as AP214 and IGES, read back by FreeCAD
// and measured against the patches' exact surfaces.
class TstCadExport : public QObject {
    Q_OBJECT

    // Every file is written first and FreeCAD reads them all in one run (it takes 0.4 s to
    // start); each row then checks its own.
    struct Written {
        io::CadExportResult result;
        QString path;
        test::CadReadBack back;
    };
    QTemporaryDir m_dir;
    std::map<QString, Written> m_written;
    QStringList m_names;

    static QString key(const QString& example, io::CadFormat format) {
        return example + QLatin1Char(' ') + QLatin1String(formatName(format));
    }

private slots:
    void initTestCase() {
        m_names = QStringList{QStringLiteral("fig8-folded")};
        for (const model::ExampleInfo& info : model::builtInExamples()) {
            m_names << QString::fromStdString(info.name);
        }
        QStringList paths;
        for (const QString& name : m_names) {
            const model::Project project = projectNamed(name);
            for (io::CadFormat format :
                 {io::CadFormat::StepAP242, io::CadFormat::StepAP214, io::CadFormat::Iges}) {
                Written& w = m_written[key(name, format)];
                w.path = m_dir.filePath(key(name, format) +
                                        (format == io::CadFormat::Iges ? ".igs" : ".step"));
                io::CadExportOptions options;
                options.format = format;
                w.result = io::saveCadFile(project, w.path, options);
                paths << w.path;
            }
        }
        const std::vector<test::CadReadBack> backs = test::readWithFreeCad(paths);
        for (std::size_t i = 0; i < backs.size(); ++i) {
            for (auto& [name, w] : m_written) {
                if (w.path == paths[static_cast<int>(i)]) {
                    w.back = backs[i];
                }
            }
        }
    }

    void readBack_data() {
        QTest::addColumn<QString>("example");
        QTest::addColumn<int>("format");
        for (const QString& name : m_names) {
            for (io::CadFormat format :
                 {io::CadFormat::StepAP242, io::CadFormat::StepAP214, io::CadFormat::Iges}) {
                QTest::newRow(qPrintable(key(name, format))) << name << static_cast<int>(format);
            }
        }
    }

    void readBack() {
        QFETCH(QString, example);
        QFETCH(int, format);
        const model::Project project = projectNamed(example);
        std::vector<io::PatchSurface> patches;
        double area = 0.0;
        for (const model::CompositeSurface& surface : project.surfaces) {
            for (io::PatchSurface& patch : io::patchSurfaces(surface)) {
                area += io::patchArea(patch);
                patches.push_back(std::move(patch));
            }
        }
        const double diameter = io::projectDiameter(project);

        const bool iges = static_cast<io::CadFormat>(format) == io::CadFormat::Iges;
        const Written& written = m_written.at(key(example, static_cast<io::CadFormat>(format)));
        const QString& path = written.path;
        const io::CadExportResult& result = written.result;
        QCOMPARE(result.faces(), patches.size());
        QVERIFY(result.sewn());
        QCOMPARE(result.surfaces.size(), project.surfaces.size());
        for (const io::CadExportSurface& surface : result.surfaces) {
            QCOMPARE(surface.shells, std::size_t{1});
            QCOMPARE(surface.closedShell, surface.closedDesign);
        }

        const test::CadReadBack& back = written.back;
        QVERIFY2(back.ok, qPrintable(back.error));
        QCOMPARE(back.faces, static_cast<int>(patches.size()));
        QCOMPARE(back.shells, static_cast<int>(project.surfaces.size()));
        for (std::size_t i = 0; i < back.shellClosed.size(); ++i) {
            QCOMPARE(back.shellClosed[i], result.surfaces[i].closedDesign);
        }
        const double areaError = std::abs(back.area - area) / area;
        QVERIFY2(areaError <= 1e-6, qPrintable(QString::number(areaError)));
        QVERIFY(std::abs(back.freeCadArea - area) / area <= 1e-4);
        QVERIFY(back.points.size() >= patches.size());
        double farthest = 0.0;
        for (const model::Vec3& p : back.points) {
            farthest = std::max(farthest, test::distanceToPatches(p, patches));
        }
        QVERIFY2(farthest <= 1e-6 * diameter, qPrintable(QString::number(farthest / diameter)));
        qInfo("%s %s: %d faces, %s, area error %.2g (FreeCAD's Shape.Area %.2g), largest "
              "distance %.2g of the diameter",
              qPrintable(example), formatName(static_cast<io::CadFormat>(format)), back.faces,
              result.surfaces.front().closedShell ? "one closed shell" : "one open shell",
              areaError, std::abs(back.freeCadArea - area) / area, farthest / diameter);

        if (!iges) {
            // The faces carry their patches' names (STEP keeps names of sub-shapes).
            QFile file(path);
            QVERIFY(file.open(QIODevice::ReadOnly));
            const QByteArray text = file.readAll();
            QVERIFY(text.contains(static_cast<io::CadFormat>(format) == io::CadFormat::StepAP214
                                      ? "AUTOMOTIVE_DESIGN"
                                      : "AP242_MANAGED_MODEL_BASED_3D_ENGINEERING"));
            QVERIFY(text.contains("'patch " + QByteArray::number(patches.front().face) + "'"));
            if (example == QLatin1String("fig8-folded")) {
                QCOMPARE(result.surfaces.front().namedCreases, std::size_t{6});
                QVERIFY(text.contains("mountain'") && text.contains("valley'"));
            }
        }
    }

    // A closed design (a tetrahedron of planar patches) becomes one closed shell, in our report
    // and as FreeCAD reads it; a design of two surfaces, two shells with surface-qualified names.
    void closedAndSeveralSurfaces() {
        model::CompositeSurface tetrahedron;
        const model::VertexId a = tetrahedron.addVertex({0, 0, 0});
        const model::VertexId b = tetrahedron.addVertex({100, 0, 0});
        const model::VertexId c = tetrahedron.addVertex({0, 100, 0});
        const model::VertexId d = tetrahedron.addVertex({0, 0, 100});
        tetrahedron.addFace({a, c, b});
        tetrahedron.addFace({a, b, d});
        tetrahedron.addFace({b, c, d});
        tetrahedron.addFace({c, a, d});
        QVERIFY(tetrahedron.validate().empty());
        model::Project project = model::makeExample("annulus");
        project.addSurface(tetrahedron);
        QTemporaryDir folder;
        const QString path = folder.filePath("two.step");
        const io::CadExportResult result = io::saveCadFile(project, path, {});
        QCOMPARE(result.surfaces.size(), std::size_t{2});
        QVERIFY(!result.surfaces[0].closedShell);
        QVERIFY(result.surfaces[1].closedDesign);
        QVERIFY(result.surfaces[1].closedShell);
        const test::CadReadBack back = test::readWithFreeCad(path);
        QVERIFY2(back.ok, qPrintable(back.error));
        QCOMPARE(back.shells, 2);
        QCOMPARE(back.shellClosed, (std::vector<bool>{false, true}));
        QCOMPARE(back.faces, 48 + 4);
        const double expected = 3 * 5000.0 + 0.5 * std::sqrt(3.0) * 2 * 100.0 * 100.0 / 2;
        double annulus = 0.0;
        for (const io::PatchSurface& patch : io::patchSurfaces(project.surfaces[0])) {
            annulus += io::patchArea(patch);
        }
        QVERIFY(std::abs(back.area - annulus - expected) / (annulus + expected) < 1e-9);
        QFile file(path);
        QVERIFY(file.open(QIODevice::ReadOnly));
        QVERIFY(file.readAll().contains("'surface 2 patch 3'"));
    }

    // A fold of 90° along a straight crease: the crease is a named edge of the STEP file.
    void namedCrease() {
        model::CompositeSurface folded;
        const model::SplineSpace space{3, 2, 1};
        auto line = [](const model::Vec3& from, const model::Vec3& to) {
            std::vector<model::Vec3> points;
            for (int i = 0; i < 4; ++i) {
                points.push_back(from + (to - from) * (i / 3.0));
            }
            return points;
        };
        const model::Vec3 q0{0, -50, 0}, q1{100, -50, 0}, p0{0, 0, 0}, p1{100, 0, 0}, r0{0, 0, 50},
            r1{100, 0, 50};
        const auto vq0 = folded.addVertex(q0), vq1 = folded.addVertex(q1),
                   vp0 = folded.addVertex(p0), vp1 = folded.addVertex(p1),
                   vr0 = folded.addVertex(r0), vr1 = folded.addVertex(r1);
        folded.addFace({vq0, vq1, vp1, vp0});
        folded.addFace({vp0, vp1, vr1, vr0});
        folded.setSpline(vq0, vq1, space, line(q0, q1));
        const model::EdgeId crease = folded.setSpline(vp0, vp1, space, line(p0, p1));
        folded.setSpline(vr0, vr1, space, line(r0, r1));
        QVERIFY(folded.validate().empty());
        model::Project project;
        project.addSurface(folded);
        QTemporaryDir folder;
        const QString path = folder.filePath("folded.step");
        const io::CadExportResult result = io::saveCadFile(project, path, {});
        QCOMPARE(result.surfaces.front().namedCreases, std::size_t{1});
        QFile file(path);
        QVERIFY(file.open(QIODevice::ReadOnly));
        const QByteArray text = file.readAll();
        const QByteArray name = "crease " + QByteArray::number(crease);
        QVERIFY(text.contains("'" + name + " mountain'") || text.contains("'" + name + " valley'"));
        const test::CadReadBack back = test::readWithFreeCad(path);
        QVERIFY2(back.ok, qPrintable(back.error));
        QCOMPARE(back.faces, 2);
        QVERIFY(std::abs(back.area - 10000.0) < 1e-9 * 10000.0);
    }

    // Cancelling from the progress callback stops the export and writes nothing.
    void cancel() {
        QTemporaryDir folder;
        const QString path = folder.filePath("cancelled.step");
        io::CadExportOptions options;
        int calls = 0;
        options.progress = [&calls](double) { return ++calls < 3; };
        try {
            io::saveCadFile(model::makeExample("annulus"), path, options);
            QFAIL("not cancelled");
        } catch (const io::ShapeExportError& error) {
            QCOMPARE(error.code(), io::ShapeExportError::Code::Cancelled);
        }
        QVERIFY(!QFile::exists(path));
    }
};

DEVSURF_REGISTER_TEST(TstCadExport);

#include "tst_cad_export.moc"
