#include "io/project_file.h"
#include "model/examples.h"
#include "test_registry.h"

#include <QFile>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTemporaryDir>
#include <QTest>

using namespace devsurf;

namespace {

struct Run {
    int exitCode = -1;
    QString out;
    QString err;
};

Run cli(const QStringList& arguments) {
    QProcess process;
    process.start(QStringLiteral(DEVSURF_CLI_PATH), arguments);
    Run run;
    if (!process.waitForFinished(120000) || process.exitStatus() != QProcess::NormalExit) {
        return run;
    }
    run.exitCode = process.exitCode();
    run.out = QString::fromUtf8(process.readAllStandardOutput());
    run.err = QString::fromUtf8(process.readAllStandardError());
    return run;
}

} // namespace

class TstCli : public QObject {
    Q_OBJECT
    QTemporaryDir m_dir;

    QString path(const char* name) const { return m_dir.filePath(QString::fromUtf8(name)); }

private slots:
    void helpAndVersion() {
        Run run = cli({"--help"});
        QCOMPARE(run.exitCode, 0);
        QVERIFY(run.out.contains("export-json"));
        run = cli({"info", "--help"});
        QCOMPARE(run.exitCode, 0);
        run = cli({"--version"});
        QCOMPARE(run.exitCode, 0);
        QVERIFY(run.out.startsWith("devsurf-cli "));
    }

    void badUsageExitsWithOne() {
        for (const QStringList& args :
             QList<QStringList>{{},
                                {"frobnicate"},
                                {"example", "annulus"},
                                {"example", "torus", "-o", path("t.devsurf")},
                                {"example", "sheet", "--size", "abc", "-o", path("t.devsurf")},
                                {"example", "sheet", "--size", "0", "-o", path("t.devsurf")},
                                {"info"},
                                {"info", "a", "b"},
                                {"export-json", path("x.devsurf")},
                                {"validate", "--bogus", "x"}}) {
            const Run run = cli(args);
            QVERIFY2(run.exitCode == 1, qPrintable(args.join(' ')));
            QVERIFY(run.err.startsWith("devsurf-cli: "));
            QCOMPARE(run.err.count('\n'), 1);
        }
    }

    void exampleInfoValidateExport() {
        const QString file = path("a.devsurf");
        Run run = cli({"example", "annulus", "-o", file});
        QCOMPARE(run.exitCode, 0);
        QVERIFY(io::loadProjectFile(file) == model::makeExample("annulus"));

        run = cli({"info", file});
        QCOMPARE(run.exitCode, 0);
        QVERIFY(run.out.contains(
            "Faces: 48 (48 SRSR strips, 0 SRS strips, 0 SRR cones, 0 planar faces)"));
        QVERIFY(run.out.contains("Spline spaces: degree 3, C2, 3 intervals (56 S-edges)"));
        QVERIFY(run.out.contains("Control points: 280"));
        QVERIFY(run.out.contains("Vertices: 56"));
        QVERIFY(run.out.contains("Edges: 56 S, 48 R"));

        run = cli({"validate", file});
        QCOMPARE(run.exitCode, 0);
        QVERIFY(run.out.contains("valid"));

        const QString json = path("a.json");
        run = cli({"export-json", file, "-o", json, "--samples", "3"});
        QCOMPARE(run.exitCode, 0);
        QFile jsonFile(json);
        QVERIFY(jsonFile.open(QIODevice::ReadOnly));
        const QJsonDocument doc = QJsonDocument::fromJson(jsonFile.readAll());
        QCOMPARE(doc.object()["format"].toString(), QString("devsurf-interchange"));

        run = cli({"example", "mixed", "--size", "3", "-o", path("m.devsurf")});
        QCOMPARE(run.exitCode, 0);
        run = cli({"info", path("m.devsurf")});
        QVERIFY(run.out.contains("1 SRSR strip, 1 SRS strip, 1 SRR cone, 1 planar face"));
    }

    void damagedInputExitsWithTwo() {
        const QString file = path("d.devsurf");
        QCOMPARE(cli({"example", "sheet", "-o", file}).exitCode, 0);
        QFile f(file);
        QVERIFY(f.open(QIODevice::ReadWrite));
        QByteArray bytes = f.readAll();
        bytes[bytes.size() / 2] = static_cast<char>(bytes[bytes.size() / 2] ^ 0x10);
        f.seek(0);
        f.write(bytes);
        f.close();
        for (const char* command : {"info", "validate", "export-json"}) {
            QStringList args{command, file};
            if (QString(command) == "export-json") {
                args << "-o" << path("d.json");
            }
            const Run run = cli(args);
            QCOMPARE(run.exitCode, 2);
            QVERIFY(run.err.contains("d.devsurf"));
            QVERIFY(run.err.contains("checksum"));
            QCOMPARE(run.err.count('\n'), 1);
        }
        QVERIFY(!QFile::exists(path("d.json")));
        const Run missing = cli({"info", path("nothing-here.devsurf")});
        QCOMPARE(missing.exitCode, 2);
        QVERIFY(missing.err.contains("nothing-here.devsurf"));
    }

    void invalidSurfaceListsEveryProblem() {
        // Written by the encoder (which does not validate), refused by every reader.
        model::Project project = model::makeExample("sheet", 2);
        model::CompositeSurface& surface = project.surfaces[0];
        surface.setRuling(surface.faceEdges(0)[0]); // SRSR → RRSR
        surface.setRuling(surface.faceEdges(3)[2]); // another face broken
        const QString file = path("invalid.devsurf");
        QFile f(file);
        QVERIFY(f.open(QIODevice::WriteOnly));
        const std::string bytes = io::encodeProject(project);
        f.write(bytes.data(), static_cast<qint64>(bytes.size()));
        f.close();
        const Run run = cli({"validate", file});
        QCOMPARE(run.exitCode, 2);
        QVERIFY(run.err.contains("face 0 is labelled RRSR"));
        QVERIFY(run.err.contains("face 3 is labelled"));
        QCOMPARE(cli({"info", file}).exitCode, 2);
    }
};

DEVSURF_REGISTER_TEST(TstCli);
#include "tst_cli.moc"
