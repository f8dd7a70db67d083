#include "cli_run.h"
#include "test_registry.h"

#include <QCryptographicHash>
#include <QFile>
#include <QFileInfo>
#include <QTemporaryDir>
#include <QTest>

using namespace devsurf;

namespace {

using test::contents;

} // namespace

// devsurf-cli export of the 3D shape: every format, its options, refusals and exit codes.
class TstShapeCli : public QObject {
    Q_OBJECT
    QTemporaryDir m_dir;

    QString path(const QString& name) const { return m_dir.filePath(name); }

private slots:
    void initTestCase() {
        QCOMPARE(
            test::runCli({"example", "fig8", "--as-built", "-o", path("fig8.devsurf")}).exitCode,
            0);
    }

    void meshes() {
        for (const QString format : {"obj", "stl", "ply"}) {
            const QString out = path("fig8." + format);
            const test::CliRun run =
                test::runCli({"export", path("fig8.devsurf"), "--tolerance", "0.1", "-o", out});
            QVERIFY2(run.exitCode == 0, qPrintable(run.err));
            QVERIFY(run.out.startsWith("Wrote " + out + " (" + format.toUpper()));
            QVERIFY(run.err.isEmpty());
        }
        QVERIFY(contents(path("fig8.obj")).contains("\ng patch_"));
        QVERIFY(contents(path("fig8.ply")).startsWith("ply\nformat binary_little_endian"));
        // 84 bytes of header and count, 50 per triangle.
        const QByteArray stl = contents(path("fig8.stl"));
        QVERIFY(stl.size() > 84 && (stl.size() - 84) % 50 == 0);
        const test::CliRun thick = test::runCli({"export", path("fig8.devsurf"), "--format", "stl",
                                                 "--thickness", "1", "-o", path("thick.stl")});
        QVERIFY2(thick.exitCode == 0, qPrintable(thick.err));
        QVERIFY(QFileInfo(path("thick.stl")).size() > 2 * stl.size());
    }

    void cadFormats() {
        const struct {
            const char* format;
            const char* file;
            const char* marker;
        } cases[] = {{"step", "fig8.step", "AP242_MANAGED_MODEL_BASED_3D_ENGINEERING"},
                     {"step214", "fig8.stp", "AUTOMOTIVE_DESIGN"},
                     {"iges", "fig8.igs", "S      1"}};
        for (const auto& c : cases) {
            const test::CliRun run = test::runCli(
                {"export", path("fig8.devsurf"), "--format", c.format, "-o", path(c.file)});
#ifdef DEVSURF_CAD_EXPORT
            QVERIFY2(run.exitCode == 0, qPrintable(run.err));
            QVERIFY(run.out.contains("9 faces in 1 shell, sewn"));
            QVERIFY(contents(path(c.file)).contains(c.marker));
#else
            // The sanitizer build has no OpenCASCADE: one sentence, nothing written.
            QCOMPARE(run.exitCode, 2);
            QVERIFY(run.err.contains("without STEP and IGES"));
            QVERIFY(!QFile::exists(path(c.file)));
#endif
        }
        // The format follows the extension.
        const test::CliRun byExtension =
            test::runCli({"export", path("fig8.devsurf"), "-o", path("plain.step")});
#ifdef DEVSURF_CAD_EXPORT
        QVERIFY2(byExtension.exitCode == 0, qPrintable(byExtension.err));
#else
        QCOMPARE(byExtension.exitCode, 2);
#endif
    }

    void refusals() {
        const QByteArray before = contents(path("fig8.devsurf"));
        // Onto its own input: refused before anything is computed, the project unchanged.
        const test::CliRun same = test::runCli(
            {"export", path("fig8.devsurf"), "--format", "stl", "-o", path("fig8.devsurf")});
        QCOMPARE(same.exitCode, 2);
        QVERIFY(same.err.contains("Refusing"));
        QCOMPARE(contents(path("fig8.devsurf")), before);
        const QStringList usage[] = {
            {"--format", "step", "--tolerance", "0.1", "-o", path("a.step")},
            {"--format", "iges", "--thickness", "1", "-o", path("a.igs")},
            {"--format", "dxf", "--thickness", "1", "-o", path("a.dxf")},
            {"--format", "stl", "--paper", "A4", "-o", path("a.stl")},
            {"--format", "stl", "-o", "-"},
            {"--format", "stl", "-o", path("a.obj")},
            {"--format", "stl", "--thickness", "-1", "-o", path("a.stl")},
            {"--format", "brep", "-o", path("a.brep")},
        };
        for (const QStringList& options : usage) {
            const test::CliRun run =
                test::runCli(QStringList{"export", path("fig8.devsurf")} + options);
            QVERIFY2(run.exitCode == 1, qPrintable(options.join(' ')));
            QVERIFY(run.out.isEmpty());
        }
        QVERIFY(!QFile::exists(path("a.stl")) && !QFile::exists(path("a.step")));
        // An unreadable project: one sentence, exit 2.
        QFile broken(path("broken.devsurf"));
        QVERIFY(broken.open(QIODevice::WriteOnly));
        broken.write("not a project");
        broken.close();
        const test::CliRun bad =
            test::runCli({"export", path("broken.devsurf"), "-o", path("broken.stl")});
        QCOMPARE(bad.exitCode, 2);
        QVERIFY(!QFile::exists(path("broken.stl")));
    }
};

DEVSURF_REGISTER_TEST(TstShapeCli);

#include "tst_shape_cli.moc"
