#include "../io/dxf_check.h"
#include "cli_run.h"
#include "io/project_file.h"
#include "model/pattern/cutting_pattern.h"
#include "test_registry.h"

#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QTest>

using namespace devsurf;

namespace {

using Run = test::CliRun;
using test::runCli;

} // namespace

// devsurf-cli export and report: formats, options, exit codes, warnings.
class TstPatternCli : public QObject {
    Q_OBJECT
    QTemporaryDir m_dir;

    QString path(const QString& name) const { return m_dir.filePath(name); }

private slots:
    void initTestCase() {
        QCOMPARE(
            runCli({"example", "annulus", "--as-built", "-o", path("annulus.devsurf")}).exitCode,
            0);
        QCOMPARE(
            runCli({"example", "cylinder", "--as-built", "-o", path("cylinder.devsurf")}).exitCode,
            0);
    }

    void exportWritesEveryFormat() {
        for (const QString format : {"dxf", "svg", "pdf", "fold"}) {
            const QString out = path("annulus." + format);
            const Run run = runCli({"export", path("annulus.devsurf"), "--format", format,
                                    "--paper", "A4", "-o", out});
            QVERIFY2(run.exitCode == 0, qPrintable(run.err));
            QVERIFY(run.out.startsWith("Wrote " + out));
            QVERIFY(QFileInfo(out).size() > 1000);
        }
        // The format follows the output's extension when --format is not given.
        const Run run = runCli({"export", path("cylinder.devsurf"), "--splines", "--seam", "5",
                                "--rulings", "--tolerance", "0.02", "-o", path("cylinder.dxf")});
        QVERIFY2(run.exitCode == 0, qPrintable(run.err));
        QFile dxf(path("cylinder.dxf"));
        QVERIFY(dxf.open(QIODevice::ReadOnly));
        const QByteArray bytes = dxf.readAll();
        QVERIFY(bytes.contains("SPLINE") && bytes.contains("SEAM") && bytes.contains("AC1015"));
    }

    void problemsOfThePatternAreWarnings() {
        // The 500 mm annulus does not fit the default 600 × 400 mm sheet.
        const Run run =
            runCli({"export", path("annulus.devsurf"), "--format", "svg", "-o", path("w.svg")});
        QCOMPARE(run.exitCode, 0);
        QVERIFY(run.err.startsWith("devsurf-cli: warning: "));
        QVERIFY(run.err.contains("does not fit"));
        QVERIFY(!run.err.contains("QStandardPaths"));
    }

    void reportAsTextAndJson() {
        Run run = runCli({"report", path("cylinder.devsurf"), "--sheet", "700,300"});
        QCOMPARE(run.exitCode, 0);
        QVERIFY(run.out.contains("1 piece on 1 sheet"));
        QVERIFY(run.out.contains("yes"));
        run = runCli({"report", path("annulus.devsurf"), "--json"});
        QCOMPARE(run.exitCode, 0);
        const QJsonObject json = QJsonDocument::fromJson(run.out.toUtf8()).object();
        const QJsonArray pieces = json["pieces"].toArray();
        QCOMPARE(pieces.size(), qsizetype(1));
        QVERIFY(!pieces[0].toObject()["fitsSheet"].toBool());
        // Exactly developable as built.
        QVERIFY(json["maxIsometryError"].toDouble() < 1e-6);
        QCOMPARE(json["problems"].toArray().size(), qsizetype(1));
    }

    void solvedCurvedDesignReadsBackWithEzdxf() {
        const QString solved = path("solved.devsurf");
        Run run = runCli({"solve", path("cylinder.devsurf"), "--perturb", "0.002", "--seed", "5",
                          "--iterations", "8", "-o", solved});
        QVERIFY2(run.exitCode == 0, qPrintable(run.err));
        const QString dxf = path("solved.dxf");
        run = runCli(
            {"export", solved, "--format", "dxf", "--sheet", "2000,2000", "--splines", "-o", dxf});
        QVERIFY2(run.exitCode == 0, qPrintable(run.err));
        model::PatternOptions options;
        options.sheetSize = {2000.0, 2000.0};
        const model::CuttingPattern pattern =
            model::buildCuttingPattern(io::loadProjectFile(solved), options);
        for (const model::PatternPiece& piece : pattern.pieces) {
            QCOMPARE(piece.sheet, 0);
        }
        test::verifyDxf(test::readBackDxf(dxf, pattern, 0.01, [](int) { return 0.0; }), "AC1015",
                        "SPLINE", 0.01);
    }

    void badUsageExitsWithOne() {
        const QString in = path("annulus.devsurf");
        const QString out = path("bad.dxf");
        for (const QStringList& args :
             QList<QStringList>{{"export"},
                                {"export", in},
                                {"export", in, "-o", path("bad.txt")},
                                {"export", in, "--format", "png", "-o", out},
                                {"export", in, "--sheet", "abc", "-o", out},
                                {"export", in, "--sheet", "600,-4", "-o", out},
                                {"export", in, "--sheet", "600,400", "--paper", "A4", "-o", out},
                                {"export", in, "--paper", "B5", "-o", out},
                                {"export", in, "--tolerance", "0", "-o", out},
                                {"export", in, "--format", "svg", "--r12", "-o", path("bad.svg")},
                                {"export", in, "--bogus", "-o", out},
                                {"report"},
                                {"report", in, "--splines"}}) {
            const Run run = runCli(args);
            QVERIFY2(run.exitCode == 1, qPrintable(args.join(' ') + ": " + run.err));
            QVERIFY(run.err.startsWith("devsurf-cli: "));
            QCOMPARE(run.err.count('\n'), 1);
        }
        QVERIFY(!QFile::exists(out));
    }

    void badInputExitsWithTwo() {
        Run run =
            runCli({"export", path("missing.devsurf"), "--format", "dxf", "-o", path("m.dxf")});
        QCOMPARE(run.exitCode, 2);
        QVERIFY(run.err.contains("missing.devsurf"));
        QCOMPARE(run.err.count('\n'), 1);
        run = runCli({"export", path("cylinder.devsurf"), "--sheet", "2000,2000", "-o",
                      path("no/such/folder/c.pdf")});
        QCOMPARE(run.exitCode, 2);
        QVERIFY(run.err.contains("c.pdf"));
        QCOMPARE(run.err.count('\n'), 1);
        QCOMPARE(runCli({"report", path("missing.devsurf")}).exitCode, 2);
    }
};

DEVSURF_REGISTER_TEST(TstPatternCli);
#include "tst_pattern_cli.moc"
