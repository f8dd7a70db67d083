// `devsurf-cli sheet`: holding a surface's sheet, and a drag the held sheet holds back.

#include "cli_run.h"
#include "io/project_file.h"
#include "model/pattern/pattern_geometry.h"
#include "model/sampled_mesh.h"
#include "model/sheet_creases.h"
#include "model/sheet_domain.h"
#include "test_registry.h"

#include <QFile>
#include <QTemporaryDir>
#include <QTest>

#include <algorithm>
#include <cmath>

using namespace devsurf;

class TstCliSheet : public QObject {
    Q_OBJECT
    QTemporaryDir m_dir;

    QString path(const char* name) const { return m_dir.filePath(QString::fromUtf8(name)); }
    // Writes `text` to the file `name` in the test's directory and returns its path.
    QString written(const char* name, const QByteArray& text) const {
        QFile file(path(name));
        return file.open(QIODevice::WriteOnly) && file.write(text) == text.size() ? path(name)
                                                                                  : QString();
    }
    static test::CliRun cli(const QStringList& arguments) { return test::runCli(arguments); }

private slots:
    void sheetIsHeldAndReleased() {
        const QString file = path("square.devsurf");
        QCOMPARE(cli({"example", "sheet", "--as-built", "-o", file}).exitCode, 0);
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
        // Why: two of its pins hold a straight line of the sheet (the first pair is named).
        QVERIFY2(run.out.contains(QStringLiteral("The pinned vertices 0 and 3 are as far apart")),
                 qPrintable(run.out));
        const model::CompositeSurface after = io::loadProjectFile(lifted).surfaces[0];
        QVERIFY(after.development() == surface.development());
        QVERIFY(std::abs(after.position(5).z - surface.position(5).z) < 1.0);
        // --off lets it stretch again.
        QCOMPARE(cli({"sheet", held, "--off", "-o", held}).exitCode, 0);
        QVERIFY(!io::loadProjectFile(held).surfaces[0].keepsDevelopment());
        // A cylinder holds the cylinder it unrolls onto; a flat shape for it is refused (exit
        // 2, nothing written), and so is a torus, which unrolls onto no one sheet.
        const QString cylinder = path("tube.devsurf");
        QCOMPARE(cli({"example", "cylinder", "--as-built", "-o", cylinder}).exitCode, 0);
        const QString around = path("tube-held.devsurf");
        run = cli({"sheet", cylinder, "--free", "-o", around});
        QCOMPARE(run.exitCode, 0);
        QVERIFY2(run.out.contains(QStringLiteral("around a cylinder of radius")),
                 qPrintable(run.out));
        QCOMPARE(io::loadProjectFile(around).surfaces[0].sheetDomain().shape,
                 model::SheetShape::Cylinder);
        const QString refused = path("tube-flat.devsurf");
        run = cli({"sheet", cylinder, "--rectangle", "700,200", "-o", refused});
        QCOMPARE(run.exitCode, 2);
        QVERIFY2(run.err.contains(QStringLiteral("closes around a cylinder")), qPrintable(run.err));
        QVERIFY(!QFile::exists(refused));
        const QString torus = path("torus.devsurf");
        QCOMPARE(cli({"example", "torus", "-o", torus}).exitCode, 0);
        QCOMPARE(cli({"sheet", torus, "--free", "-o", refused}).exitCode, 2);
        QVERIFY(!QFile::exists(refused));
        QCOMPARE(cli({"sheet", cylinder, "-o", refused}).exitCode, 1);
    }

    void examplesHoldTheSheetTheyStartAs() {
        // `example`, as File ▸ New from Example makes it by default: fig6 on its 300 × 200
        // rectangle, only its first bottom corner pinned, its crease kept where it lies; its
        // top edge pulled in and up folds it along the crease from its sheet.
        const QString file = path("fig6-held.devsurf");
        const test::CliRun made = cli({"example", "fig6", "-o", file});
        QCOMPARE(made.exitCode, 0);
        QVERIFY2(made.out.contains(QStringLiteral("holding its sheet")), qPrintable(made.out));
        const model::CompositeSurface fig6 = io::loadProjectFile(file).surfaces[0];
        QVERIFY(fig6.keepsDevelopment());
        QCOMPARE(fig6.sheetDomain().shape, model::SheetShape::Rectangle);
        QCOMPARE(fig6.sheetDomain().width, 300.0);
        QCOMPARE(fig6.pinnedVertices().size(), std::size_t(1));
        QCOMPARE(fig6.sheetDomain().creaseCurveOf.size(), std::size_t(1));
        const QString folded = path("fig6-folded.devsurf");
        const test::CliRun drag =
            cli({"drag", file, "--vertices", "4,5", "--by", "0,-30,60", "-o", folded});
        QCOMPARE(drag.exitCode, 0);
        QVERIFY2(drag.out.contains(QStringLiteral("tolerance 1.0e-08 reached")),
                 qPrintable(drag.out));
        const model::CompositeSurface after = io::loadProjectFile(folded).surfaces[0];
        QVERIFY(after.position(4).z > 40.0);
        QCOMPARE(after.sheetDomain(), fig6.sheetDomain());
        // --hold-sheet writes the same file; --as-built the example as it comes.
        const QString insisted = path("fig6-insisted.devsurf");
        QCOMPARE(cli({"example", "fig6", "--hold-sheet", "-o", insisted}).exitCode, 0);
        QVERIFY(io::loadProjectFile(insisted) == io::loadProjectFile(file));
        QCOMPARE(cli({"example", "fig6", "--as-built", "-o", file}).exitCode, 0);
        QVERIFY(!io::loadProjectFile(file).surfaces[0].keepsDevelopment());
        QCOMPARE(cli({"example", "fig6", "--as-built", "--hold-sheet", "-o", file}).exitCode, 1);
        // A torus holds no one sheet: written as it comes, unless the sheet is insisted on.
        QCOMPARE(cli({"example", "torus", "-o", file}).exitCode, 0);
        QVERIFY(!io::loadProjectFile(file).surfaces[0].keepsDevelopment());
        const test::CliRun torus = cli({"example", "torus", "--hold-sheet", "-o", file});
        QCOMPARE(torus.exitCode, 1);
        QVERIFY2(torus.err.contains(QStringLiteral("no one sheet")), qPrintable(torus.err));
        // The cylinder holds the cylinder its unfolding rolls onto.
        QCOMPARE(cli({"example", "cylinder", "--hold-sheet", "-o", file}).exitCode, 0);
        QCOMPARE(io::loadProjectFile(file).surfaces[0].sheetDomain().shape,
                 model::SheetShape::Cylinder);
    }

    void sheetShapes() {
        // The annulus example on an annulus of radii 100 and 250 mm: placed on its development,
        // written, listed by info; a Solve moves the development's rims onto the circles.
        const QString file = path("ring.devsurf");
        QCOMPARE(cli({"example", "annulus", "--as-built", "--size", "3", "-o", file}).exitCode, 0);
        const QString ring = path("ring-sheet.devsurf");
        test::CliRun run = cli({"sheet", file, "--annulus", "250,100", "-o", ring});
        QCOMPARE(run.exitCode, 0);
        QVERIFY2(run.out.contains(QStringLiteral("next solve")), qPrintable(run.out));
        const model::CompositeSurface held = io::loadProjectFile(ring).surfaces[0];
        QCOMPARE(held.sheetDomain().shape, model::SheetShape::Annulus);
        QCOMPARE(held.sheetDomain().innerRadius, 100.0);
        QCOMPARE(held.sheetDomain().radius, 250.0);
        run = cli({"info", ring});
        QVERIFY2(run.out.contains(QStringLiteral("annulus")), qPrintable(run.out));
        const QString solved = path("ring-solved.devsurf");
        QCOMPARE(cli({"solve", ring, "-o", solved}).exitCode, 0);
        const model::CompositeSurface after = io::loadProjectFile(solved).surfaces[0];
        const model::SampledMesh mesh =
            model::sampleSurface(after, model::kDevelopmentSamplesPerInterval);
        double worst = 0.0; // of every development vertex on a rim, from its circle
        for (const auto& loop : model::pattern::boundaryLoops(mesh.faces)) {
            for (int v : loop) {
                const double r =
                    (after.development()[static_cast<std::size_t>(v)] - held.sheetDomain().centre)
                        .norm();
                worst = std::max(worst, std::min(std::abs(r - 100.0), std::abs(r - 250.0)));
            }
        }
        QVERIFY2(worst < 1e-6, qPrintable(QString::number(worst)));

        // A rectangle and a disk are written; sizes that are no sheet are refused, nothing
        // written.
        const QString square = path("square.devsurf");
        QCOMPARE(cli({"example", "sheet", "--as-built", "-o", square}).exitCode, 0);
        const QString onSquare = path("on-square.devsurf");
        run = cli({"sheet", square, "--rectangle", "300,300", "-o", onSquare});
        QCOMPARE(run.exitCode, 0);
        QVERIFY2(!run.out.contains(QStringLiteral("next solve")), qPrintable(run.out));
        QCOMPARE(io::loadProjectFile(onSquare).surfaces[0].sheetDomain().width, 300.0);
        const QString small = path("small.devsurf");
        run = cli({"sheet", square, "--disk", "100", "-o", small});
        QCOMPARE(run.exitCode, 0);
        QVERIFY2(run.out.contains(QStringLiteral("larger than the sheet")), qPrintable(run.out));
        const QString refused = path("refused.devsurf");
        QCOMPARE(cli({"sheet", square, "--annulus", "100,100", "-o", refused}).exitCode, 1);
        QCOMPARE(cli({"sheet", square, "--disk", "-5", "-o", refused}).exitCode, 1);
        QCOMPARE(cli({"sheet", square, "--disk", "5", "--free", "-o", refused}).exitCode, 1);
        QVERIFY(!QFile::exists(refused));
    }

    void outlineFromTheCuttingPattern() {
        // The square's own cutting pattern, as DXF and as SVG, as the sheet's outline: one loop
        // of 300 × 300 mm, placed on the development. A file without a closed curve writes
        // nothing.
        const QString square = path("outline-square.devsurf");
        QCOMPARE(cli({"example", "sheet", "--as-built", "-o", square}).exitCode, 0);
        for (const char* format : {"dxf", "svg"}) {
            const QString drawing = m_dir.filePath(QStringLiteral("outline-square.") + format);
            QCOMPARE(cli({"export", square, "--format", format, "-o", drawing}).exitCode, 0);
            const QString onOutline =
                m_dir.filePath(QStringLiteral("on-outline-%1.devsurf").arg(format));
            QCOMPARE(cli({"sheet", square, "--outline", drawing, "-o", onOutline}).exitCode, 0);
            const model::CompositeSurface held = io::loadProjectFile(onOutline).surfaces[0];
            QCOMPARE(held.sheetDomain().shape, model::SheetShape::Outline);
            QCOMPARE(static_cast<int>(held.sheetDomain().outline.size()), 1);
            QVERIFY(std::abs(model::domainArea(held.sheetDomain()) - 90000.0) < 1.0);
            const model::SampledMesh mesh =
                model::sampleSurface(held, model::kDevelopmentSamplesPerInterval);
            QVERIFY(model::largestDomainGap(held.sheetDomain(), mesh, held.development()) < 0.01);
        }
        const QString lines = path("open-lines.dxf");
        QFile file(lines);
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write("0\nSECTION\n2\nENTITIES\n0\nLINE\n8\n0\n10\n0\n20\n0\n30\n0\n11\n100\n21\n0\n"
                   "31\n0\n0\nENDSEC\n0\nEOF\n");
        file.close();
        const QString refused = path("outline-refused.devsurf");
        const test::CliRun run = cli({"sheet", square, "--outline", lines, "-o", refused});
        QCOMPARE(run.exitCode, 2);
        QVERIFY2(run.err.contains(QStringLiteral("closed curve")), qPrintable(run.err));
        QVERIFY(!QFile::exists(refused));
    }

    void creasesFollowCurvesDrawnInTheSheet() {
        // The annulus (creases on rings at 125, 150, ..., 225 mm) on an annulus sheet, with
        // circles of radii 130 and 205 mm drawn in a DXF: the rings at 125 and 200 mm are
        // held on them, and a Solve moves their development there (radii computed here).
        const QString annulus = path("creases-annulus.devsurf");
        QCOMPARE(cli({"example", "annulus", "--as-built", "-o", annulus}).exitCode, 0);
        const QString drawing =
            written("creases.dxf", "0\nSECTION\n2\nENTITIES\n"
                                   "0\nCIRCLE\n8\nCREASE\n10\n0\n20\n0\n30\n0\n40\n130\n"
                                   "0\nCIRCLE\n8\nCREASE\n10\n0\n20\n0\n30\n0\n40\n205\n"
                                   "0\nENDSEC\n0\nEOF\n");
        QVERIFY(!drawing.isEmpty());
        const QString held = path("creases-held.devsurf");
        test::CliRun run =
            cli({"sheet", annulus, "--annulus", "100,250", "--creases", drawing, "-o", held});
        QCOMPARE(run.exitCode, 0);
        QVERIFY2(run.out.contains(QStringLiteral("16 creases held on 2 of 2 crease curves")),
                 qPrintable(run.out));
        QCOMPARE(io::loadProjectFile(held).surfaces[0].sheetDomain().creaseCurveOf.size(),
                 std::size_t(16));
        const QString solved = path("creases-solved.devsurf");
        run = cli({"solve", held, "-o", solved});
        QCOMPARE(run.exitCode, 0);
        const model::CompositeSurface s = io::loadProjectFile(solved).surfaces[0];
        const model::SampledMesh mesh =
            model::sampleSurface(s, model::kDevelopmentSamplesPerInterval);
        double worst = 0.0;
        int onCurves = 0;
        for (const model::SampledMesh::Polyline& line : mesh.splineEdges) {
            const auto it = s.sheetDomain().creaseCurveOf.find(line.edge);
            if (it == s.sheetDomain().creaseCurveOf.end()) {
                continue;
            }
            const double r = it->second == 0 ? 130.0 : 205.0;
            for (int v : line.vertices) {
                const model::Vec2 p = s.development()[static_cast<std::size_t>(v)];
                worst = std::max(worst, std::abs((p - s.sheetDomain().centre).norm() - r));
                ++onCurves;
            }
        }
        QCOMPARE(onCurves, 16 * 7);
        // The drawn circles are read as polygons within 0.001 mm of them.
        QVERIFY2(worst < 2e-3, qPrintable(QString::number(worst)));

        // A drawing far from every crease, or creases on a free sheet, writes nothing.
        const QString far =
            written("far.svg", "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"600mm\" "
                               "height=\"600mm\" viewBox=\"-300 -300 600 600\"><line x1=\"-290\" "
                               "y1=\"-290\" x2=\"-280\" y2=\"-290\"/></svg>");
        QVERIFY(!far.isEmpty());
        const QString refused = path("creases-refused.devsurf");
        run = cli({"sheet", annulus, "--annulus", "100,250", "--creases", far, "-o", refused});
        QCOMPARE(run.exitCode, 2);
        QVERIFY2(run.err.contains(QStringLiteral("lies near a curve")), qPrintable(run.err));
        QCOMPARE(cli({"sheet", annulus, "--free", "--creases", drawing, "-o", refused}).exitCode,
                 1);
        QVERIFY(!QFile::exists(refused));
    }

    void creasesKeptWhereTheyLie() {
        // fig8 with one corner pinned on its 300 × 300 mm square, its creases kept where they
        // lie: its six crease S-edges on two curves. Its middle lifted 85 mm then folds along
        // them, the creases still on their curves and the sheet still the square.
        const QString fig8 = path("keep-fig8.devsurf");
        QCOMPARE(cli({"example", "fig8", "--as-built", "-o", fig8}).exitCode, 0);
        const QString oneCorner = path("keep-one-corner.devsurf");
        QCOMPARE(cli({"pin", fig8, "--vertices", "3", "--unpin", "-o", oneCorner}).exitCode, 0);
        const QString held = path("keep-held.devsurf");
        test::CliRun run =
            cli({"sheet", oneCorner, "--rectangle", "300,300", "--keep-creases", "-o", held});
        QCOMPARE(run.exitCode, 0);
        QVERIFY2(run.out.contains(QStringLiteral("6 creases held on 2 of 2 crease curves")),
                 qPrintable(run.out));
        const QString lifted = path("keep-lifted.devsurf");
        run = cli({"drag", held, "--vertices", "5,6,9,10", "--by", "0,0,85", "-o", lifted});
        QCOMPARE(run.exitCode, 0);
        QVERIFY2(run.out.contains(QStringLiteral("tolerance 1.0e-08 reached")),
                 qPrintable(run.out));
        QVERIFY2(!run.out.contains(QStringLiteral("pinned vertices")), qPrintable(run.out));
        const model::CompositeSurface s = io::loadProjectFile(lifted).surfaces[0];
        const model::SampledMesh mesh =
            model::sampleSurface(s, model::kDevelopmentSamplesPerInterval);
        QCOMPARE(s.sheetDomain().creaseCurveOf.size(), std::size_t(6));
        const double onCurves =
            model::largestCreaseCurveGap(s.sheetDomain(), mesh, s.development());
        QVERIFY2(onCurves < 1e-6, qPrintable(QString::number(onCurves)));
        const double onSquare = model::largestDomainGap(s.sheetDomain(), mesh, s.development());
        QVERIFY2(onSquare < 1e-6, qPrintable(QString::number(onSquare)));
        for (model::VertexId v : {5u, 6u, 9u, 10u}) {
            QVERIFY(s.position(v).z > 60.0);
        }

        // Not with a free sheet, nor together with a drawing.
        const QString refused = path("keep-refused.devsurf");
        run = cli({"sheet", oneCorner, "--free", "--keep-creases", "-o", refused});
        QCOMPARE(run.exitCode, 1);
        QVERIFY2(run.err.contains(QStringLiteral("--keep-creases needs a sheet of a shape")),
                 qPrintable(run.err));
        run = cli({"sheet", oneCorner, "--rectangle", "300,300", "--keep-creases", "--creases",
                   fig8, "-o", refused});
        QCOMPARE(run.exitCode, 1);
        QVERIFY(!QFile::exists(refused));
    }
};

DEVSURF_REGISTER_TEST(TstCliSheet);
#include "tst_cli_sheet.moc"
