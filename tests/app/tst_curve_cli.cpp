#include "cli_run.h"
#include "test_registry.h"

#include <QFile>
#include <QFileInfo>
#include <QProcess>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QTest>

using namespace devsurf;

namespace {

using test::contents;

} // namespace

// devsurf-cli import-curves: curves of DXF (written by ezdxf) and STEP files into a project,
// refusals that write nothing, and info's count.
class TstCurveCli : public QObject {
    Q_OBJECT
    QTemporaryDir m_dir;

    QString path(const QString& name) const { return m_dir.filePath(name); }

private slots:
    void initTestCase() {
        QCOMPARE(
            test::runCli({"example", "fig8", "--as-built", "-o", path("fig8.devsurf")}).exitCode,
            0);
        QProcess python;
        python.start(
            QStringLiteral("/usr/bin/python3"),
            {QStringLiteral(DEVSURF_SOURCE_DIR "/tests/io/write_curves_dxf.py"), m_dir.path()});
        QVERIFY(python.waitForFinished(60000));
        QVERIFY2(python.exitCode() == 0, python.readAllStandardError().constData());
    }

    void importsDxfCurves() {
        const QByteArray input = contents(path("fig8.devsurf"));
        const test::CliRun run = test::runCli({"import-curves", path("fig8.devsurf"),
                                               path("curves.dxf"), "-o", path("with.devsurf")});
        QVERIFY2(run.exitCode == 0, qPrintable(run.err));
        QVERIFY2(
            run.out.startsWith("Wrote " + path("with.devsurf") + " (9 reference curves imported, "),
            qPrintable(run.out));
        QVERIFY(run.out.contains("2 other entities skipped"));
        QCOMPARE(contents(path("fig8.devsurf")), input); // the input is not touched
        const test::CliRun info = test::runCli({"info", path("with.devsurf")});
        QCOMPARE(info.exitCode, 0);
        QVERIFY2(info.out.contains("Reference curves: 9\n"), qPrintable(info.out));
        QVERIFY(test::runCli({"info", path("fig8.devsurf")}).out.contains("Reference curves: 0\n"));
        // Importing again adds to them; a tolerance ten times finer gives more points.
        const test::CliRun again =
            test::runCli({"import-curves", path("with.devsurf"), path("curves.dxf"), "--tolerance",
                          "0.005", "-o", path("twice.devsurf")});
        QVERIFY2(again.exitCode == 0, qPrintable(again.err));
        QVERIFY(again.out.contains("; 18 in the project)"));
        QVERIFY(test::runCli({"info", path("twice.devsurf")}).out.contains("Reference curves: 18"));
        auto pointsOf = [](const QString& out) {
            const int at = out.indexOf(" imported, ");
            return out.mid(at + 11).section(' ', 0, 0).toInt();
        };
        QVERIFY(pointsOf(again.out) > 2 * pointsOf(run.out));
    }

    void editsTheProjectInPlaceOnlyWhenAsked() {
        QVERIFY(QFile::copy(path("fig8.devsurf"), path("inplace.devsurf")));
        const test::CliRun run = test::runCli({"import-curves", path("inplace.devsurf"),
                                               path("cm.dxf"), "-o", path("inplace.devsurf")});
        QVERIFY2(run.exitCode == 0, qPrintable(run.err));
        QVERIFY(QFileInfo::exists(path("inplace.devsurf.bak")));
        QVERIFY(
            test::runCli({"info", path("inplace.devsurf")}).out.contains("Reference curves: 1"));
    }

    void refusalsWriteNothing() {
        const QByteArray dxf = contents(path("curves.dxf"));
        // Never over the curve file.
        test::CliRun run = test::runCli(
            {"import-curves", path("fig8.devsurf"), path("curves.dxf"), "-o", path("curves.dxf")});
        QCOMPARE(run.exitCode, 2);
        QVERIFY(run.err.contains("curve file being read"));
        QCOMPARE(contents(path("curves.dxf")), dxf);
        // Unknown extension, missing file, damaged file: one sentence, exit 2, no output.
        QVERIFY(QFile::copy(path("curves.dxf"), path("curves.txt")));
        QFile damaged(path("damaged.dxf"));
        QVERIFY(damaged.open(QIODevice::WriteOnly));
        damaged.write(QByteArray("0\nSECTION\n2\nENTITIES\n0\nLWPOLYLINE\n90\n999999999\n"));
        damaged.close();
        for (const QString& curves :
             {path("curves.txt"), path("missing.dxf"), path("damaged.dxf"), path("cm.step")}) {
            run = test::runCli(
                {"import-curves", path("fig8.devsurf"), curves, "-o", path("refused.devsurf")});
            QVERIFY2(run.exitCode == 2, qPrintable(curves + ": " + run.err));
            QVERIFY2(run.err.startsWith("devsurf-cli: ") && run.err.count('\n') == 1,
                     qPrintable(run.err));
            QVERIFY(run.out.isEmpty());
            QVERIFY(!QFileInfo::exists(path("refused.devsurf")));
        }
        // Usage: two files and -o.
        QCOMPARE(test::runCli({"import-curves", path("fig8.devsurf"), path("curves.dxf")}).exitCode,
                 1);
        QCOMPARE(
            test::runCli({"import-curves", path("curves.dxf"), "-o", path("x.devsurf")}).exitCode,
            1);
        QVERIFY(
            test::runCli({"import-curves", "--help"}).out.contains("import-curves FILE CURVES"));
    }

#ifdef DEVSURF_CAD_EXPORT
    void importsTheEdgesOfAStepFile() {
        // fig8's own STEP export (its patches' B-spline faces): every edge a reference curve.
        QCOMPARE(test::runCli({"export", path("fig8.devsurf"), "-o", path("fig8.step")}).exitCode,
                 0);
        const test::CliRun run = test::runCli({"import-curves", path("fig8.devsurf"),
                                               path("fig8.step"), "-o", path("edges.devsurf")});
        QVERIFY2(run.exitCode == 0, qPrintable(run.err));
        QVERIFY2(run.out.contains(" reference curves imported"), qPrintable(run.out));
        // 9 patches sewn into one shell: 24 edges of the coarse mesh.
        QVERIFY2(run.out.contains("(24 reference curves"), qPrintable(run.out));
    }
#endif

    void fitsAnEdgeToACurve() {
        // fig8's crease 6 runs from (100, 121.65) to (200, 121.65) in the plane z = 0; an SVG
        // curve drawn 10 mm beside it, bulging 5 mm further in the middle.
        const QString svg = path("guide.svg");
        QFile file(svg);
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write("<svg xmlns='http://www.w3.org/2000/svg' width='400mm' height='400mm' "
                   "viewBox='0 -400 400 400'><path d='M 80 -131.65 Q 150 -141.65 220 -131.65' "
                   "fill='none' stroke='black'/></svg>");
        file.close();
        const QString with = path("guide.devsurf");
        QCOMPARE(test::runCli({"import-curves", path("fig8.devsurf"), svg, "-o", with}).exitCode,
                 0);
        const test::CliRun run =
            test::runCli({"fit-edge", with, "--edge", "6", "-o", path("fitted.devsurf")});
        QVERIFY2(run.exitCode == 0, qPrintable(run.err));
        QVERIFY2(run.out.contains("edge 6 laid onto reference curve 1"), qPrintable(run.out));
        const test::CliRun info = test::runCli({"info", path("fitted.devsurf"), "--vertices"});
        // Vertices 5 and 6 moved onto the curve: about 12 mm in +y, still in the plane.
        for (const char* vertex : {"5", "6"}) {
            const QRegularExpressionMatch at =
                QRegularExpression(QStringLiteral(R"(\n\s+%1 (\S+) (\S+) (\S+) )").arg(vertex))
                    .match(info.out);
            QVERIFY2(at.hasMatch(), qPrintable(info.out));
            QVERIFY(at.captured(2).toDouble() > 131.0 && at.captured(2).toDouble() < 137.0);
            QCOMPARE(at.captured(3).toDouble(), 0.0);
        }
        // A ruling, and a project without curves, are refused; nothing is written.
        QCOMPARE(test::runCli({"fit-edge", with, "--edge", "1", "-o", path("no.devsurf")}).exitCode,
                 2);
        QCOMPARE(test::runCli(
                     {"fit-edge", path("fig8.devsurf"), "--edge", "6", "-o", path("no.devsurf")})
                     .exitCode,
                 2);
        QVERIFY(!QFile::exists(path("no.devsurf")));
    }
};

DEVSURF_REGISTER_TEST(TstCurveCli);

#include "tst_curve_cli.moc"
