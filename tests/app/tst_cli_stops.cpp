#include "cli_run.h"
#include "test_registry.h"

#include <QRegularExpression>
#include <QTemporaryDir>
#include <QTest>

using namespace devsurf;

// devsurf-cli solve and drag where the solver heads for a degenerate surface: the session
// refuses that iterate, the command says so and writes the last valid state.
class TstCliStops : public QObject {
    Q_OBJECT
    QTemporaryDir m_dir;

    QString path(const char* name) const { return m_dir.filePath(QString::fromUtf8(name)); }

private slots:
    void solveStopsAtTheLastValidState() {
        // Shaken by 2 % of its diameter (seed 9), the annulus converges towards a surface in
        // which a patch has zero area: the 18th iteration gets there. The command says so and
        // writes the 17th.
        const QString file = path("collapse.devsurf");
        QCOMPARE(test::runCli({"example", "annulus", "-o", file}).exitCode, 0);
        const QString out = path("collapse-solved.devsurf");
        const test::CliRun run = test::runCli(
            {"solve", file, "--perturb", "0.02", "--seed", "9", "--iterations", "30", "-o", out});
        QCOMPARE(run.exitCode, 0);
        QVERIFY2(run.out.contains(QRegularExpression(
                     "\\nAfter iteration \\d+: stopped at the last valid state: the next "
                     "iteration gave a degenerate surface, face \\d+ has zero area\\.\\n")),
                 qPrintable(run.out));
        QVERIFY(!run.out.contains("iteration  30 "));
        QCOMPARE(test::runCli({"validate", out}).exitCode, 0);
    }

    void dragStopsAtTheLastValidState() {
        // fig8 with its four middle vertices lifted 85 mm (stretching, its two pinned corners
        // kept), then turned by −30° about the vertical through their centre: in the 7th
        // iteration after the release patch 1 flattens to a line. The drag stops at the 6th,
        // says so and writes it (before, nothing was written; the desktop application dropped
        // the whole drag).
        const QString flat = path("fig8.devsurf");
        QCOMPARE(test::runCli({"example", "fig8", "-o", flat}).exitCode, 0);
        const QString lifted = path("fig8-lifted.devsurf");
        QCOMPARE(test::runCli({"drag", flat, "--vertices", "5,6,9,10", "--by", "0,0,85",
                               "--stretch", "-o", lifted})
                     .exitCode,
                 0);
        const QString turned = path("fig8-turned.devsurf");
        const test::CliRun run =
            test::runCli({"drag", lifted, "--vertices", "5,6,9,10", "--rotate",
                          "150,171.650635094611,85,0,0,1,-30", "--stretch", "-o", turned});
        QCOMPARE(run.exitCode, 0);
        QVERIFY2(run.out.contains(QRegularExpression(
                     "\\nAt after \\d+: stopped at the last valid state: the next iteration "
                     "gave a degenerate surface, face \\d+ has zero area\\.\\n")),
                 qPrintable(run.out + run.err));
        QVERIFY(run.out.contains("Largest residual "));
        QVERIFY(run.out.endsWith("Wrote " + turned + "\n"));
        QCOMPARE(test::runCli({"validate", turned}).exitCode, 0);
    }
};

DEVSURF_REGISTER_TEST(TstCliStops);
#include "tst_cli_stops.moc"
