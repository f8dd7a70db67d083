#include "cli_run.h"
#include "io/project_file.h"
#include "test_registry.h"

#include <QFile>
#include <QFileInfo>
#include <QTemporaryDir>
#include <QTest>

using namespace devsurf;

namespace {

QByteArray contents(const QString& path) {
    QFile file(path);
    return file.open(QIODevice::ReadOnly) ? file.readAll() : QByteArray();
}

bool writeFile(const QString& path, const QByteArray& bytes) {
    QFile file(path);
    return file.open(QIODevice::WriteOnly) && file.write(bytes) == bytes.size();
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
        QCOMPARE(test::runCli({"example", "sheet", "-o", path("sheet.devsurf")}).exitCode, 0);
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
};

DEVSURF_REGISTER_TEST(TstReferenceCli);
#include "tst_reference_cli.moc"
