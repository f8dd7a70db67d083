#include "cli_run.h"
#include "io/project_file.h"
#include "model/reference/distance_report.h"
#include "model/strip_joining.h"
#include "sampled_developability.h"
#include "test_registry.h"

#include <QFile>
#include <QFileInfo>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QTest>

#include <cmath>

using namespace devsurf;

namespace {

using test::contents;

bool writeFile(const QString& path, const QByteArray& bytes) {
    QFile file(path);
    return file.open(QIODevice::WriteOnly) && file.write(bytes) == bytes.size();
}

// A cylinder over the parabola y = x² / 100, x in [−50, 50], z in [0, 60]: 41 × 25 points.
std::vector<model::Vec3> parabolicCylinderPoints() {
    std::vector<model::Vec3> points;
    for (int i = 0; i <= 40; ++i) {
        for (int j = 0; j <= 24; ++j) {
            const double x = -50.0 + 2.5 * i;
            points.emplace_back(x, 0.01 * x * x, 2.5 * j);
        }
    }
    return points;
}

// A tall patch of the circular cylinder of radius 100 about the z-axis: the angle within ±60°,
// z in [0, 240], 61 × 49 points. Two k-means clusters split it into a lower and an upper half,
// whose strips run around the cylinder and face each other along a curve near z = 120.
std::vector<model::Vec3> circularCylinder() {
    std::vector<model::Vec3> points;
    for (int i = 0; i <= 60; ++i) {
        const double phi = (2.0 * i / 60 - 1.0) * 1.0471975511965976;
        for (int j = 0; j <= 48; ++j) {
            points.emplace_back(100.0 * std::cos(phi), 100.0 * std::sin(phi), 5.0 * j);
        }
    }
    return points;
}

QByteArray xyz(const std::vector<model::Vec3>& points) {
    QByteArray text;
    for (const model::Vec3& p : points) {
        text += QByteArray::number(p.x, 'g', 17) + ' ' + QByteArray::number(p.y, 'g', 17) + ' ' +
                QByteArray::number(p.z, 'g', 17) + '\n';
    }
    return text;
}

} // namespace

// devsurf-cli import-reference: a mesh and a point cloud into a project, info's list of them,
// and refusals that write nothing.
class TstReferenceCli : public QObject {
    Q_OBJECT
    QTemporaryDir m_dir;

    QString path(const QString& name) const { return m_dir.filePath(name); }

private slots:
    void initTestCase() {
        QCOMPARE(
            test::runCli({"example", "sheet", "--as-built", "-o", path("sheet.devsurf")}).exitCode,
            0);
        // A tetrahedron of 10 x 20 x 30.5 mm, a quad of it split into two triangles.
        QVERIFY(writeFile(path("tet.obj"), "v 0 0 0\nv 10 0 0\nv 0 20 0\nv 0 0 30.5\n"
                                           "f 1 3 2\nf 1 2 4\nf 2 3 4\nf 1 4 3\n"));
        QVERIFY(writeFile(path("scan.pts"), "3\n1 2 3 0 0 1\n4 5 6 0 1 0\n-7 8 9 1 0 0\n"));
    }

    void importsAMeshAndACloud() {
        const QByteArray input = contents(path("sheet.devsurf"));
        test::CliRun run = test::runCli({"import-reference", path("sheet.devsurf"), path("tet.obj"),
                                         "-o", path("tet.devsurf")});
        QVERIFY2(run.exitCode == 0, qPrintable(run.err));
        QCOMPARE(run.out, "Wrote " + path("tet.devsurf") +
                              " (reference shape 'tet': 4 points, 4 triangles, 10 x 20 x 30.5 mm; "
                              "1 in the project)\n");
        QCOMPARE(contents(path("sheet.devsurf")), input); // the input is not touched
        run = test::runCli({"import-reference", path("tet.devsurf"), path("scan.pts"), "--name",
                            "front scan", "-o", path("both.devsurf")});
        QVERIFY2(run.exitCode == 0, qPrintable(run.err));
        QVERIFY2(run.out.contains("'front scan': 3 points, 0 triangles, 11 x 6 x 6 mm; 2 in the"),
                 qPrintable(run.out));
        const test::CliRun info = test::runCli({"info", path("both.devsurf")});
        QCOMPARE(info.exitCode, 0);
        QVERIFY2(info.out.contains("Reference shapes: 2\n"
                                   "Reference shape 1: tet (4 points, 4 triangles)\n"
                                   "Reference shape 2: front scan (3 points, 0 triangles, with "
                                   "normals)\n"),
                 qPrintable(info.out));
        QVERIFY(
            test::runCli({"info", path("sheet.devsurf")}).out.contains("Reference shapes: 0\n"));
        // What was written is what the file held, in the current format.
        const model::Project project = io::loadProjectFile(path("both.devsurf"));
        QCOMPARE(project.referenceShapes.size(), std::size_t(2));
        QCOMPARE(project.referenceShapes[0].points[3], model::Vec3(0, 0, 30.5));
        QCOMPARE(project.referenceShapes[0].source, std::string("tet.obj"));
        QCOMPARE(project.referenceShapes[1].normals[2], model::Vec3(1, 0, 0));
        QCOMPARE(project.referenceShapes[1].source, std::string("scan.pts"));
    }

    void refusalsWriteNothing() {
        QVERIFY(writeFile(path("bad.obj"), "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 7\n"));
        QVERIFY(writeFile(path("nan.xyz"), "0 0 0\nnan 1 2\n"));
        QVERIFY(writeFile(path("cut.off"), "OFF\n4 4 6\n0 0 0\n1 0 0\n"));
        QVERIFY(writeFile(path("shape.txt"), "0 0 0\n"));
        for (const QString& target : {path("bad.obj"), path("nan.xyz"), path("cut.off"),
                                      path("shape.txt"), path("missing.stl")}) {
            const test::CliRun run = test::runCli(
                {"import-reference", path("sheet.devsurf"), target, "-o", path("refused.devsurf")});
            QVERIFY2(run.exitCode == 2, qPrintable(target + ": " + run.err));
            QVERIFY2(run.err.startsWith("devsurf-cli: ") && run.err.count('\n') == 1,
                     qPrintable(run.err));
            QVERIFY2(run.err.contains(target), qPrintable(run.err));
            QVERIFY(run.out.isEmpty());
            QVERIFY(!QFileInfo::exists(path("refused.devsurf")));
        }
        // Never over the shape being read.
        const QByteArray tet = contents(path("tet.obj"));
        const test::CliRun run = test::runCli(
            {"import-reference", path("sheet.devsurf"), path("tet.obj"), "-o", path("tet.obj")});
        QCOMPARE(run.exitCode, 2);
        QVERIFY(run.err.contains("reference shape being read"));
        QCOMPARE(contents(path("tet.obj")), tet);
        // Usage: two files and -o.
        QCOMPARE(
            test::runCli({"import-reference", path("sheet.devsurf"), path("tet.obj")}).exitCode, 1);
        QVERIFY(test::runCli({"import-reference", "--help"})
                    .out.contains("import-reference FILE TARGET [--name NAME] -o OUT.devsurf"));
        QVERIFY(test::runCli({"--help"}).out.contains("import-reference"));
    }

    void distanceToACloudAboveTheSheet() {
        // 300 points 5 mm above the flat 300 × 300 mm sheet, inside its square, and 100 points
        // 50 mm above: target to surface is 5 mm for the first and 50 mm for the others, so
        // the mean is 16.25 mm, the max 50 mm, and a 6 mm tolerance covers three quarters.
        QByteArray cloud;
        for (int i = 0; i < 400; ++i) {
            const double x = 10.0 + (i % 20) * 14.0;
            const double y = 10.0 + (i / 20) * 14.0;
            cloud += QByteArray::number(x) + ' ' + QByteArray::number(y) + ' ' +
                     (i < 300 ? "5" : "50") + '\n';
        }
        QVERIFY(writeFile(path("above.xyz"), cloud));
        const test::CliRun run = test::runCli(
            {"distance", path("sheet.devsurf"), path("above.xyz"), "--json", "--tolerance", "6"});
        QCOMPARE(run.exitCode, 0);
        const QJsonObject report = QJsonDocument::fromJson(run.out.toUtf8()).object();
        const QJsonObject toSurface = report.value("targetToSurface").toObject();
        QVERIFY(std::abs(toSurface.value("mean").toDouble() - 16.25) < 1e-9);
        QVERIFY(std::abs(toSurface.value("max").toDouble() - 50.0) < 1e-9);
        QVERIFY(std::abs(report.value("coverage").toDouble() - 0.75) < 1e-12);
        QCOMPARE(report.value("targetPoints").toInt(), 400);
        // The surface's far corners are farther from the cloud than any cloud point is from it.
        QVERIFY(report.value("hausdorff").toDouble() >= 50.0);
        const test::CliRun text =
            test::runCli({"distance", path("sheet.devsurf"), path("above.xyz")});
        QCOMPARE(text.exitCode, 0);
        QVERIFY(text.out.contains("Target to surface: mean 16.25 mm"));
        // A target that cannot be read is said in one sentence.
        const test::CliRun missing =
            test::runCli({"distance", path("sheet.devsurf"), path("missing.xyz")});
        QCOMPARE(missing.exitCode, 2);
        QVERIFY(missing.err.contains("cannot read"));
    }

    void approximateFitsAStripToACloud() {
        const std::vector<model::Vec3> points = parabolicCylinderPoints();
        QVERIFY(writeFile(path("cylinder.xyz"), xyz(points)));
        const test::CliRun run =
            test::runCli({"approximate", path("cylinder.xyz"), "-o", path("approximated.devsurf")});
        QVERIFY2(run.exitCode == 0, qPrintable(run.err));
        QVERIFY2(run.out.contains("Surface 1: 40 iterations"), qPrintable(run.out));
        QVERIFY2(run.out.contains("(within the tolerance"), qPrintable(run.out));
        QVERIFY(run.out.contains("Target to surface: mean "));
        QVERIFY(run.out.contains("coverage 100.0 %"));
        // The result holds one strip and the target, and lies on the cloud (measured here).
        const model::Project project = io::loadProjectFile(path("approximated.devsurf"));
        QCOMPARE(project.surfaces.size(), std::size_t(1));
        QVERIFY(project.surfaces.front().validate().empty());
        QCOMPARE(project.referenceShapes.size(), std::size_t(1));
        QCOMPARE(project.referenceShapes.front().points.size(), points.size());
        const auto report = model::reference::measureDistance(project.surfaces, points);
        QVERIFY2(report.targetToSurface.max < 1e-5 * report.diagonal,
                 qPrintable(QString::number(report.targetToSurface.max)));
        // The other commands work on it.
        QCOMPARE(test::runCli({"solve", path("approximated.devsurf"), "-o", path("solved.devsurf")})
                     .exitCode,
                 0);
        QCOMPARE(
            test::runCli({"distance", path("approximated.devsurf"), path("cylinder.xyz")}).exitCode,
            0);
        QCOMPARE(test::runCli({"drag", path("approximated.devsurf"), "--vertices", "1", "--by",
                               "0,0,5", "-o", path("dragged.devsurf")})
                     .exitCode,
                 0);
    }

    void approximateWithSeveralStripsAndFromAProject() {
        QVERIFY(writeFile(path("cylinder.xyz"), xyz(parabolicCylinderPoints())));
        // One patch curved one way: the two strips are laid side by side as one surface.
        test::CliRun run = test::runCli({"approximate", path("cylinder.xyz"), "--strips", "2",
                                         "--iterations", "10", "-o", path("one.devsurf")});
        QVERIFY2(run.exitCode == 0, qPrintable(run.err));
        QVERIFY2(run.out.contains("The target is one patch: 2 strips laid side by side as one "
                                  "surface"),
                 qPrintable(run.out));
        const model::Project one = io::loadProjectFile(path("one.devsurf"));
        QCOMPARE(one.surfaces.size(), std::size_t(1));
        QCOMPARE(one.surfaces.front().faces().size(), std::size_t(2));
        // --separate: two strips over two patches.
        run = test::runCli({"approximate", path("cylinder.xyz"), "--strips", "2", "--separate",
                            "--iterations", "10", "-o", path("two.devsurf")});
        QVERIFY2(run.exitCode == 0, qPrintable(run.err));
        QVERIFY(!run.out.contains("The target is one patch"));
        QCOMPARE(io::loadProjectFile(path("two.devsurf")).surfaces.size(), std::size_t(2));
        run = test::runCli({"approximate", path("cylinder.xyz"), "--from", path("two.devsurf"),
                            "--iterations", "5", "-o", path("again.devsurf")});
        QVERIFY2(run.exitCode == 0, qPrintable(run.err));
        const model::Project again = io::loadProjectFile(path("again.devsurf"));
        QCOMPARE(again.surfaces.size(), std::size_t(2));
        QCOMPARE(again.referenceShapes.size(), std::size_t(1)); // not stored twice
    }

    void approximateJoinsStripsIntoOneSurface() {
        const std::vector<model::Vec3> points = circularCylinder();
        QVERIFY(writeFile(path("circular.xyz"), xyz(points)));
        const test::CliRun run =
            test::runCli({"approximate", path("circular.xyz"), "--strips", "2", "--separate",
                          "--join", "-o", path("joined.devsurf")});
        QVERIFY2(run.exitCode == 0, qPrintable(run.err));
        QVERIFY2(run.out.contains(
                     "Join: 1 of 1 pairs of facing edges welded; 2 surfaces now one of 1 part(s)"),
                 qPrintable(run.out));
        // One surface of two patches sharing one curve, valid, on the cloud (measured here).
        const model::Project project = io::loadProjectFile(path("joined.devsurf"));
        QCOMPARE(project.surfaces.size(), std::size_t(1));
        const model::CompositeSurface& joined = project.surfaces.front();
        QVERIFY(joined.validate().empty());
        QCOMPARE(joined.faces().size(), std::size_t(2));
        int sharedCurves = 0;
        for (const auto& [id, record] : joined.edges()) {
            sharedCurves += record.isSpline() && joined.facesOfEdge(id).size() == 2 ? 1 : 0;
        }
        QCOMPARE(sharedCurves, 1);
        const auto report = model::reference::measureDistance(project.surfaces, points);
        QVERIFY2(report.targetToSurface.max < 0.5,
                 qPrintable(QString::number(report.targetToSurface.max)));
        QVERIFY(test::runCli({"approximate", "--help"}).out.contains("--join"));
        QVERIFY(test::runCli({"approximate", "--help"}).out.contains("--separate"));
    }

    void joinCommandMakesFourStripsOneSurface() {
        // `join` on a project of four strips fitted to the cylinder (a 2 × 2 grid): one
        // watertight surface, pulled to the project's reference shape, which the test measures.
        const std::vector<model::Vec3> points = circularCylinder();
        QVERIFY(writeFile(path("circular.xyz"), xyz(points)));
        test::CliRun run = test::runCli({"approximate", path("circular.xyz"), "--strips", "4",
                                         "--separate", "-o", path("four.devsurf")});
        QVERIFY2(run.exitCode == 0, qPrintable(run.err));
        run = test::runCli({"join", path("four.devsurf"), "-o", path("joined.devsurf")});
        QVERIFY2(run.exitCode == 0, qPrintable(run.err));
        QVERIFY2(run.out.contains(
                     "4 of 4 pairs of facing edges welded; 4 surfaces now one of 1 part(s)"),
                 qPrintable(run.out));
        const model::Project project = io::loadProjectFile(path("joined.devsurf"));
        QCOMPARE(project.surfaces.size(), std::size_t(1));
        QCOMPARE(project.referenceShapes.size(), std::size_t(1));
        const model::CompositeSurface& joined = project.surfaces.front();
        QVERIFY(joined.validate().empty());
        QCOMPARE(model::surfaceParts(joined).size(), std::size_t(1));
        int shared = 0;
        for (const auto& [id, record] : joined.edges()) {
            shared += joined.facesOfEdge(id).size() == 2 ? 1 : 0;
        }
        QCOMPARE(shared, 4);
        QVERIFY(test::sampledDevelopability(joined) <= 1e-8);
        const auto report = model::reference::measureDistance(project.surfaces, points);
        QVERIFY2(report.targetToSurface.mean < 0.1,
                 qPrintable(QString::number(report.targetToSurface.mean)));

        // Refused: one surface chosen, a surface number 0, a project of one surface (nothing
        // written).
        QCOMPARE(
            test::runCli({"join", path("four.devsurf"), "--surfaces", "2", "-o", path("x.devsurf")})
                .exitCode,
            2);
        QCOMPARE(test::runCli(
                     {"join", path("four.devsurf"), "--surfaces", "0,1", "-o", path("x.devsurf")})
                     .exitCode,
                 1);
        QCOMPARE(test::runCli({"join", path("joined.devsurf"), "-o", path("x.devsurf")}).exitCode,
                 2);
        QVERIFY(!QFileInfo::exists(path("x.devsurf")));
        QVERIFY(test::runCli({"join", "--help"}).out.contains("--surfaces"));
    }

    void approximateRefusesBadInput() {
        QVERIFY(writeFile(path("cylinder.xyz"), xyz(parabolicCylinderPoints())));
        // Usage: no output, both starts, a bad count.
        QCOMPARE(test::runCli({"approximate", path("cylinder.xyz")}).exitCode, 1);
        QCOMPARE(test::runCli({"approximate", path("cylinder.xyz"), "--from", path("two.devsurf"),
                               "--strips", "2", "-o", path("x.devsurf")})
                     .exitCode,
                 1);
        QCOMPARE(test::runCli({"approximate", path("cylinder.xyz"), "--strips", "0", "-o",
                               path("x.devsurf")})
                     .exitCode,
                 1);
        // A target that cannot be read, or too few points for the strips asked for.
        test::CliRun run =
            test::runCli({"approximate", path("missing.xyz"), "-o", path("x.devsurf")});
        QCOMPARE(run.exitCode, 2);
        QVERIFY(run.err.contains("cannot read"));
        QVERIFY(writeFile(path("three.xyz"), "0 0 0\n1 0 0\n0 1 0\n"));
        run = test::runCli({"approximate", path("three.xyz"), "-o", path("x.devsurf")});
        QVERIFY(run.exitCode != 0);
        QVERIFY2(run.err.startsWith("devsurf-cli: ") && run.err.count('\n') == 1,
                 qPrintable(run.err));
        QVERIFY(!QFileInfo::exists(path("x.devsurf")));
        QVERIFY(test::runCli({"approximate", "--help"}).out.contains("approximate TARGET"));
    }
};

DEVSURF_REGISTER_TEST(TstReferenceCli);
#include "tst_reference_cli.moc"
