#include "cli_run.h"
#include "test_registry.h"

#include <QRegularExpression>
#include <QTemporaryDir>
#include <QTest>

using namespace devsurf;

// devsurf-cli solve and drag where the result is not simply the last iterate: where the solver
// heads for a degenerate surface the session refuses that iterate, the command says so and
// writes the last valid state; a Solve ends on its iterate of smallest residual.
class TstCliStops : public QObject {
    Q_OBJECT
    QTemporaryDir m_dir;

    QString path(const char* name) const { return m_dir.filePath(QString::fromUtf8(name)); }

    // fig8 with its middle vertices lifted 85 mm by devsurf-cli drag with `lengths`
    // (--stretch or --keep-lengths); the file written, or empty if a command failed.
    QString liftedFig8(const QString& lengths) const {
        const QString flat = path("fig8.devsurf");
        const QString lifted = m_dir.filePath(QStringLiteral("fig8-lifted%1.devsurf").arg(lengths));
        const bool ok = test::runCli({"example", "fig8", "--as-built", "-o", flat}).exitCode == 0 &&
                        test::runCli({"drag", flat, "--vertices", "5,6,9,10", "--by", "0,0,85",
                                      lengths, "-o", lifted})
                                .exitCode == 0;
        return ok ? lifted : QString();
    }

private slots:
    void solveStopsAtTheLastValidState() {
        // Shaken by 2 % of its diameter (seed 9), the annulus converges towards a surface in
        // which a patch has zero area: the 18th iteration gets there. The command says so and
        // writes the 17th.
        const QString file = path("collapse.devsurf");
        QCOMPARE(test::runCli({"example", "annulus", "--as-built", "-o", file}).exitCode, 0);
        const QString out = path("collapse-solved.devsurf");
        const test::CliRun run = test::runCli(
            {"solve", file, "--perturb", "0.02", "--seed", "9", "--iterations", "30", "-o", out});
        QCOMPARE(run.exitCode, 0);
        QVERIFY2(run.out.contains(QRegularExpression(
                     "\\nAfter iteration \\d+: stopped at the last valid state, before the next "
                     "iteration broke it: Patch \\d+ has zero area\\.\\n")),
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
        const QString lifted = liftedFig8("--stretch");
        QVERIFY(!lifted.isEmpty());
        const QString turned = path("fig8-turned.devsurf");
        const test::CliRun run =
            test::runCli({"drag", lifted, "--vertices", "5,6,9,10", "--rotate",
                          "150,171.650635094611,85,0,0,1,-30", "--stretch", "-o", turned});
        QCOMPARE(run.exitCode, 0);
        QVERIFY2(run.out.contains(QRegularExpression(
                     "\\nAt after \\d+: stopped at the last valid state, before the next "
                     "iteration broke it: Patch \\d+ has zero area\\.\\n")),
                 qPrintable(run.out + run.err));
        QVERIFY(run.out.contains("Largest residual "));
        QVERIFY(run.out.endsWith("Wrote " + turned + "\n"));
        QCOMPARE(test::runCli({"validate", turned}).exitCode, 0);
    }

    void solveEndsOnItsBestIterateAndGivesTheSampledCreaseResidual() {
        // fig8 folded by a drag keeping lengths (its bottom corners pinned): Solve's residual
        // cycles (about 2.6e-8, 1.7e-6, 1.8e-6), so 10 iterations end on an earlier one.
        const QString folded = liftedFig8("--keep-lengths");
        QVERIFY(!folded.isEmpty());
        const QString out = path("fig8-solved.devsurf");
        const test::CliRun run = test::runCli({"solve", folded, "--iterations", "10", "-o", out});
        QCOMPARE(run.exitCode, 0);
        const QRegularExpressionMatch ended =
            QRegularExpression("\\nEnded on iteration (\\d+), the one with the smallest "
                               "residual\\.\\n")
                .match(run.out);
        QVERIFY2(ended.hasMatch(), qPrintable(run.out));
        QVERIFY(ended.captured(1).toInt() < 10);
        QVERIFY2(run.out.contains(QRegularExpression(
                     "\\nCreases: 6 with a condition, sampled along them: residual max \\S+ "
                     "mean \\S+\\.\\n")),
                 qPrintable(run.out));
    }
};

DEVSURF_REGISTER_TEST(TstCliStops);
#include "tst_cli_stops.moc"
