// `devsurf-cli sheet`: holding a surface's sheet, and a drag the held sheet holds back.

#include "cli_run.h"
#include "io/project_file.h"
#include "model/sampled_mesh.h"
#include "test_registry.h"

#include <QFile>
#include <QTemporaryDir>
#include <QTest>

#include <cmath>

using namespace devsurf;

class TstCliSheet : public QObject {
    Q_OBJECT
    QTemporaryDir m_dir;

    QString path(const char* name) const { return m_dir.filePath(QString::fromUtf8(name)); }
    static test::CliRun cli(const QStringList& arguments) { return test::runCli(arguments); }

private slots:
    void sheetIsHeldAndReleased() {
        const QString file = path("square.devsurf");
        QCOMPARE(cli({"example", "sheet", "-o", file}).exitCode, 0);
        QVERIFY(!io::loadProjectFile(file).surfaces[0].keepsDevelopment());
        const QString held = path("held.devsurf");
        QCOMPARE(cli({"sheet", file, "--free", "-o", held}).exitCode, 0);
        const model::CompositeSurface surface = io::loadProjectFile(held).surfaces[0];
        QVERIFY(surface.keepsDevelopment());
        QCOMPARE(surface.development().size(),
                 model::sampledVertexCount(surface, model::kDevelopmentSamplesPerInterval));
        // Its four corners pinned and its middle lifted: the sheet holds the vertices back.
        const QString pinned = path("held-pinned.devsurf");
        QCOMPARE(cli({"pin", held, "--vertices", "0,3,12,15", "-o", pinned}).exitCode, 0);
        const QString lifted = path("held-lifted.devsurf");
        test::CliRun run =
            cli({"drag", pinned, "--vertices", "5,6,9,10", "--by", "0,0,60", "-o", lifted});
        QCOMPARE(run.exitCode, 0);
        QVERIFY2(!run.out.contains(QStringLiteral("replayed")), qPrintable(run.out));
        QVERIFY2(run.out.contains(QStringLiteral("held back")), qPrintable(run.out));
        const model::CompositeSurface after = io::loadProjectFile(lifted).surfaces[0];
        QVERIFY(after.development() == surface.development());
        QVERIFY(std::abs(after.position(5).z - surface.position(5).z) < 1.0);
        // --off lets it stretch again; a cylinder is no flat sheet (exit 2, nothing written).
        QCOMPARE(cli({"sheet", held, "--off", "-o", held}).exitCode, 0);
        QVERIFY(!io::loadProjectFile(held).surfaces[0].keepsDevelopment());
        const QString cylinder = path("tube.devsurf");
        QCOMPARE(cli({"example", "cylinder", "-o", cylinder}).exitCode, 0);
        const QString refused = path("tube-held.devsurf");
        QCOMPARE(cli({"sheet", cylinder, "--free", "-o", refused}).exitCode, 2);
        QVERIFY(!QFile::exists(refused));
        QCOMPARE(cli({"sheet", cylinder, "-o", refused}).exitCode, 1);
    }
};

DEVSURF_REGISTER_TEST(TstCliSheet);
#include "tst_cli_sheet.moc"
