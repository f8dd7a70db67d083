#include "cli_run.h"
#include "io/project_file.h"
#include "model/examples.h"
#include "test_registry.h"

#include <QFile>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QTest>

#include <cmath>
#include <cstring>

using namespace devsurf;

namespace {

using Run = test::CliRun;
using test::runCli;

} // namespace

// `devsurf-cli drag`: vertices moved with pins kept, lengths kept by default, a crease slid.
class TstCliDrag : public QObject {
    Q_OBJECT
    QTemporaryDir m_dir;

    QString path(const char* name) const { return m_dir.filePath(QString::fromUtf8(name)); }

private slots:
    void dragMovesTheVerticesAndKeepsThePins() {
        const QString file = path("drag.devsurf");
        QCOMPARE(runCli({"example", "annulus", "--as-built", "-o", file}).exitCode, 0);
        const model::CompositeSurface before = io::loadProjectFile(file).surfaces[0];
        // The outer boundary of the annulus is pinned, an inner boundary vertex lifted 10 mm.
        const QString out = path("dragged.devsurf");
        Run run = runCli({"drag", file, "--vertices", "0", "--by", "0,0,10", "--pin",
                          "48,49,50,51,52,53,54,55", "--steps", "5", "--after", "3", "-o", out});
        QCOMPARE(run.exitCode, 0);
        QCOMPARE(run.out.count(QRegularExpression("^step +\\d+/5  residual \\S+  time \\S+ ms  ",
                                                  QRegularExpression::MultilineOption)),
                 5);
        QCOMPARE(run.out.count(QRegularExpression("^after +\\d+/3  residual ",
                                                  QRegularExpression::MultilineOption)),
                 3);
        const model::CompositeSurface after = io::loadProjectFile(out).surfaces[0];
        const model::Vec3 moved = after.position(0) - before.position(0);
        QVERIFY2(std::abs(moved.x) < 1.0 && std::abs(moved.y) < 1.0 &&
                     std::abs(moved.z - 10.0) < 1.0,
                 qPrintable(QString("%1 %2 %3").arg(moved.x).arg(moved.y).arg(moved.z)));
        for (model::VertexId id = 48; id <= 55; ++id) {
            QVERIFY(after.isPinned(id));
            const model::Vec3 a = before.position(id);
            const model::Vec3 b = after.position(id);
            QVERIFY(std::memcmp(&a, &b, sizeof a) == 0);
        }

        // A rotation about the vertical axis through the centre.
        run = runCli({"drag", file, "--vertices", "0,1", "--rotate", "0,0,0,0,0,1,5", "--steps",
                      "2", "--after", "1", "-o", path("rotated.devsurf")});
        QCOMPARE(run.exitCode, 0);

        // Bad ids and pinned vertices: exit 2, one sentence naming them, nothing written.
        const QString never = path("never.devsurf");
        run = runCli({"drag", file, "--vertices", "0,999", "--by", "0,0,1", "-o", never});
        QCOMPARE(run.exitCode, 2);
        QVERIFY(run.err.contains("999"));
        QCOMPARE(run.err.count('\n'), 1);
        run = runCli({"drag", out, "--vertices", "48", "--by", "0,0,1", "-o", never});
        QCOMPARE(run.exitCode, 2);
        QVERIFY(run.err.contains("pinned"));
        QVERIFY(!QFile::exists(never));

        // Bad usage: exit 1.
        for (const QStringList& args : QList<QStringList>{
                 {"drag", file, "--vertices", "0", "-o", never},
                 {"drag", file, "--vertices", "0", "--by", "0,0,1", "--rotate", "0,0,0,0,0,1,5",
                  "-o", never},
                 {"drag", file, "--vertices", "0", "--by", "1,2", "-o", never},
                 {"drag", file, "--vertices", "0", "--rotate", "0,0,0,0,0,0,5", "-o", never},
                 {"drag", file, "--vertices", "0", "--by", "0,0,1", "--steps", "0", "-o", never},
                 {"drag", file, "--vertices", "a", "--by", "0,0,1", "-o", never},
                 {"drag", file, "--vertices", "0", "--by", "0,0,1", "--surface", "2", "-o", never},
                 {"drag", file, "--vertices", "0", "--by", "0,0,1", "--pin", "0", "-o", never},
                 {"drag", file, "--vertices", "0", "--by", "0,0,1"}}) {
            run = runCli(args);
            QVERIFY2(run.exitCode == 1, qPrintable(args.join(' ')));
            QCOMPARE(run.err.count('\n'), 1);
        }
        QVERIFY(!QFile::exists(never));
    }

    void dragKeepsLengthsByDefault() {
        // As the desktop application by default: the annulus with its outer rim pinned and an
        // inner vertex lifted 100 mm bends without stretching its rulings. Measured from the
        // vertices: the shortest R-edge keeps 0.98 of its length; with --stretch 0.07.
        const QString file = path("keep.devsurf");
        QCOMPARE(runCli({"example", "annulus", "--as-built", "-o", file}).exitCode, 0);
        const model::CompositeSurface before = io::loadProjectFile(file).surfaces[0];
        const QStringList drag = {"drag", file,      "--vertices", "0",
                                  "--by", "0,0,100", "--pin",      "48,49,50,51,52,53,54,55"};
        const QString kept = path("kept.devsurf");
        Run run = runCli(drag + QStringList{"-o", kept});
        QCOMPARE(run.exitCode, 0);
        QVERIFY2(run.out.contains("keeping lengths in 20 steps, then 20 iterations"),
                 qPrintable(run.out.left(200)));
        const QString stretched = path("stretched.devsurf");
        run = runCli(drag + QStringList{"--stretch", "-o", stretched});
        QCOMPARE(run.exitCode, 0);
        QVERIFY2(run.out.contains("dragging 1 vertex in 20 steps, then 10 iterations"),
                 qPrintable(run.out.left(200)));
        // Naming the default explicitly is the default, bit for bit: the factorisation is
        // chosen by the structure alone (FactorizationMethod::Calibrated), never by timing.
        const QString named = path("named.devsurf");
        QCOMPARE(runCli(drag + QStringList{"--keep-lengths", "-o", named}).exitCode, 0);
        QVERIFY(io::loadProjectFile(named).surfaces[0] == io::loadProjectFile(kept).surfaces[0]);

        auto shortestRuling = [&](const model::CompositeSurface& after) {
            double shortest = 1e9;
            for (const auto& [id, edge] : before.edges()) {
                if (!edge.isSpline()) {
                    const double start =
                        (before.position(edge.to) - before.position(edge.from)).norm();
                    const double now = (after.position(edge.to) - after.position(edge.from)).norm();
                    shortest = std::min(shortest, now / start);
                }
            }
            return shortest;
        };
        const model::CompositeSurface keptSurface = io::loadProjectFile(kept).surfaces[0];
        const double keptRuling = shortestRuling(keptSurface);
        const double stretchedRuling = shortestRuling(io::loadProjectFile(stretched).surfaces[0]);
        qInfo("shortest R-edge after the drag: %.3f keeping lengths, %.3f stretching", keptRuling,
              stretchedRuling);
        QVERIFY2(keptRuling > 0.9, qPrintable(QString::number(keptRuling)));
        QVERIFY(!(io::loadProjectFile(stretched).surfaces[0] == keptSurface));
        QVERIFY(std::abs(keptSurface.position(0).z - 100.0) < 1e-3);

        // Without --keep-lengths or --stretch (Automatic) a drag that fails keeping lengths is
        // replayed stretching: fig8 with all four corners pinned cannot keep lengths while its
        // middle rises 85 mm (the corners keep the flat sheet's distances). The replay is the
        // --stretch drag, bit for bit.
        const QString fig8 = path("fig8.devsurf");
        QCOMPARE(runCli({"example", "fig8", "--as-built", "-o", fig8}).exitCode, 0);
        const QStringList lift = {"drag", fig8,     "--vertices", "5,6,9,10",
                                  "--by", "0,0,85", "--pin",      "0,3,12,15"};
        const QString automatic = path("fig8-automatic.devsurf");
        run = runCli(lift + QStringList{"-o", automatic});
        QCOMPARE(run.exitCode, 0);
        QVERIFY2(run.out.contains(QRegularExpression(
                     "dragging 4 vertices keeping lengths in 20 steps, then 20 iterations; 4 "
                     "pinned\n(.*\n)*Keeping lengths, the drag (did not converge|[^\n]*folded "
                     "over in \\d+ places?)[^\n]*; replayed letting the sheet stretch\\.\n"
                     "Letting the sheet stretch, the drag ended without a "
                     "problem: taken \\(0 problems against [2-5]\\)\\.\n")),
                 qPrintable(run.out));
        QVERIFY(run.out.contains("Vertex 5 lies inside the triangle of the pinned vertices 0, 3 "
                                 "and 12, which are as far apart as in the flat sheet, so "
                                 "bending cannot move it; only stretching can.\n"));
        const QString stretchedFig8 = path("fig8-stretched.devsurf");
        run = runCli(lift + QStringList{"--stretch", "-o", stretchedFig8});
        QCOMPARE(run.exitCode, 0);
        QVERIFY(!run.out.contains("keeping lengths") && !run.out.contains("replaying") &&
                !run.out.contains("bending cannot"));
        QVERIFY(io::loadProjectFile(automatic).surfaces[0] ==
                io::loadProjectFile(stretchedFig8).surfaces[0]);
        run = runCli(lift + QStringList{"--keep-lengths", "-o", path("fig8-kept.devsurf")});
        QCOMPARE(run.exitCode, 0);
        QVERIFY2(run.out.contains("dragging 4 vertices keeping lengths in 20 steps") &&
                     !run.out.contains("replaying"),
                 qPrintable(run.out.left(200)));
        // fig6 with a free corner lifted 75 mm keeps lengths: nothing replayed.
        const QString fig6 = path("fig6.devsurf");
        QCOMPARE(runCli({"example", "fig6", "--as-built", "-o", fig6}).exitCode, 0);
        run = runCli({"drag", fig6, "--vertices", "4", "--by", "0,0,75", "-o", automatic});
        QCOMPARE(run.exitCode, 0);
        QVERIFY2(run.out.contains("dragging 1 vertex keeping lengths in 20 steps") &&
                     !run.out.contains("replaying"),
                 qPrintable(run.out));

        // Both at once: bad usage (exit 1), nothing written.
        const QString never = path("never-keep.devsurf");
        run = runCli(drag + QStringList{"--keep-lengths", "--stretch", "-o", never});
        QCOMPARE(run.exitCode, 1);
        QVERIFY(run.err.contains("--stretch"));
        QVERIFY(!QFile::exists(never));
    }

    void dragSlidesACrease() {
        const QString file = path("fig6.devsurf");
        QCOMPARE(runCli({"example", "fig6", "--as-built", "-o", file}).exitCode, 0);
        const model::CompositeSurface before = io::loadProjectFile(file).surfaces[0];
        const QString out = path("slid.devsurf");
        // Crease 2 slides 20 mm across the flat sheet; the 5 mm out of it are dropped.
        Run run =
            runCli({"drag", file, "--crease", "2", "--by", "0,20,5", "--steps", "5", "-o", out});
        QCOMPARE(run.exitCode, 0);
        QVERIFY2(run.out.contains("Crease 2 slides by 0.000,20.000,0.000"), qPrintable(run.out));
        const model::CompositeSurface after = io::loadProjectFile(out).surfaces[0];
        const auto& from = before.edge(2).controlPoints;
        const auto& to = after.edge(2).controlPoints;
        // Every point within a thousandth of the motion (the pull towards the press holds the
        // crease back by about that much, see solver::creaseDragSessionOptions).
        for (std::size_t i = 0; i < to.size(); ++i) {
            const model::Vec3 miss = to[i] - (from[i] + model::Vec3{0.0, 20.0, 0.0});
            QVERIFY2(miss.norm() < 0.05, qPrintable(QString::number(miss.norm())));
        }

        // Not a crease, or an unknown edge: exit 2 with one sentence; bad usage: exit 1.
        const QString never = path("never.devsurf");
        for (const char* edge : {"0", "1", "999"}) {
            run = runCli({"drag", file, "--crease", edge, "--by", "0,1,0", "-o", never});
            QCOMPARE(run.exitCode, 2);
            QVERIFY2(run.err.contains(QStringLiteral("edge %1").arg(edge)), qPrintable(run.err));
            QCOMPARE(run.err.count('\n'), 1);
        }
        for (const QStringList& args : QList<QStringList>{
                 {"drag", file, "--crease", "2", "--vertices", "3", "--by", "0,1,0", "-o", never},
                 {"drag", file, "--crease", "2", "--rotate", "0,0,0,0,0,1,5", "-o", never},
                 {"drag", file, "--crease", "2,5", "--by", "0,1,0", "-o", never}}) {
            run = runCli(args);
            QVERIFY2(run.exitCode == 1, qPrintable(args.join(' ')));
            QCOMPARE(run.err.count('\n'), 1);
        }
        QVERIFY(!QFile::exists(never));
    }
};

DEVSURF_REGISTER_TEST(TstCliDrag);
#include "tst_cli_drag.moc"
