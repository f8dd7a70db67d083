// Tools ▸ Measure: two points clicked in the 3D view, their distance in space and along the
// sheet, against known distances: on the flat sheet both are the plane's distance; on the
// folded fig8 the sheet distance is the one on its development.
#include "cli_run.h"
#include "io/project_file.h"
#include "main_window.h"
#include "measure_tool.h"
#include "model/bspline_curve.h"
#include "model/derived_geometry.h"
#include "model/document/commands/pin_vertices_command.h"
#include "model/document/document.h"
#include "model/document/selection.h"
#include "model/edge_measure.h"
#include "model/examples.h"
#include "model/sampled_mesh.h"
#include "model/sheet_position.h"
#include "test_registry.h"
#include "views/surface_view.h"
#include "views/vtk_opengl_widget.h"
#include "window_test_support.h"
#include "workspace.h"

#include <QAction>
#include <QClipboard>
#include <QGuiApplication>
#include <QLocale>
#include <QSettings>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QTest>
#include <QUndoStack>

#include <cmath>
#include <set>

using namespace devsurf;

class TstMeasure : public QObject {
    Q_OBJECT

    // Clicks vertex a, then vertex b of surface 0 in the 3D view with the Measure tool on.
    static app::MeasureTool* measure(app::MainWindow& window, model::VertexId a,
                                     model::VertexId b) {
        QAction* action = window.action(QStringLiteral("actionMeasureTool"));
        action->setChecked(true);
        views::SurfaceView* view = window.surfaceView();
        view->grabImage();
        for (model::VertexId v : {a, b}) {
            QTest::mouseClick(view->glWidget(), Qt::LeftButton, {},
                              view->projectVertexToWidget(0, v));
        }
        return action->findChild<app::MeasureTool*>();
    }

private slots:
    void init() { QSettings().clear(); }

    void onTheFlatSheetBothDistancesAreThePlanes() {
        // sheetPosition alone: the flat sheet develops onto itself (up to a rigid motion).
        const model::CompositeSurface sheet = model::makeExample("sheet").surfaces.front();
        const model::FaceId face = sheet.faces().begin()->first;
        const auto a = model::sheetPosition(sheet, face, sheet.position(0));
        const auto b = model::sheetPosition(sheet, face, sheet.position(5));
        QVERIFY(a && b);
        QVERIFY(std::abs((*a - *b).norm() - distance(sheet.position(0), sheet.position(5))) < 1e-9);

        app::MainWindow window;
        QVERIFY(test::showActiveWithExample(window, QStringLiteral("sheet")));
        const model::CompositeSurface& surface = window.workspace()->document()->surface(0);
        app::MeasureTool* tool = measure(window, 5, 10); // two interior vertices
        QVERIFY(tool != nullptr);
        QVERIFY(!tool->text().isEmpty());
        const double known = distance(surface.position(5), surface.position(10));
        // Within what a pixel of the click makes.
        QVERIFY2(std::abs(tool->spaceDistance() - known) < 2.0,
                 qPrintable(QStringLiteral("%1 vs %2").arg(tool->spaceDistance()).arg(known)));
        QVERIFY(std::abs(tool->sheetDistance() - tool->spaceDistance()) < 1e-6 * known);
        QCOMPARE(window.surfaceView()->measurementPoints().size(), std::size_t(2));
        QVERIFY(window.statusBar()->currentMessage().contains(tool->text()));
        // Ctrl+C copies it.
        QAction* copy = window.action(QStringLiteral("actionCopyMeasurement"));
        QVERIFY(copy->isEnabled());
        QCOMPARE(copy->shortcut(), QKeySequence(QStringLiteral("Ctrl+C")));
        window.action(QStringLiteral("actionCopyMeasurement"))->trigger(); // Ctrl+C
        QCOMPARE(QGuiApplication::clipboard()->text(), tool->text());
        // Turning the tool off takes the measurement away.
        window.action(QStringLiteral("actionMeasureTool"))->setChecked(false);
        QVERIFY(window.surfaceView()->measurementPoints().empty());
        QVERIFY(!copy->isEnabled());
    }

    void edgeLengthsAndAngles() {
        // The flat fig8: its boundary edge from vertex 0 to 1 is 100 mm long and meets the
        // boundary ruling from vertex 0 to 4 at a right angle.
        app::MainWindow window;
        QVERIFY(test::showActiveWithExample(window, QStringLiteral("fig8")));
        const model::CompositeSurface& surface = window.workspace()->document()->surface(0);
        model::EdgeId bottom = model::kInvalidId, side = model::kInvalidId;
        for (const auto& [id, record] : surface.edges()) {
            const std::set<model::VertexId> ends{record.from, record.to};
            bottom = ends == std::set<model::VertexId>{0, 1} ? id : bottom;
            side = ends == std::set<model::VertexId>{0, 4} ? id : side;
        }
        QVERIFY(bottom != model::kInvalidId && side != model::kInvalidId);
        window.action(QStringLiteral("actionMeasureTool"))->setChecked(true);
        auto* tool =
            window.action(QStringLiteral("actionMeasureTool"))->findChild<app::MeasureTool*>();
        window.workspace()->selection()->set({{document::Pick::Kind::Edge, 0, bottom}});
        QVERIFY2(tool->text().contains(QLocale().toString(100.0, 'f', 2)),
                 qPrintable(tool->text()));
        window.workspace()->selection()->set(
            {{document::Pick::Kind::Edge, 0, bottom}, {document::Pick::Kind::Edge, 0, side}});
        QVERIFY2(tool->text().contains(QLocale().toString(90.0, 'f', 2)), qPrintable(tool->text()));
        // Written in the view at the common vertex.
        QCOMPARE(window.surfaceView()->measurementPoints(),
                 std::vector<model::Vec3>{surface.position(0)});
        window.action(QStringLiteral("actionCopyMeasurement"))->trigger(); // Ctrl+C
        QCOMPARE(QGuiApplication::clipboard()->text(), tool->text());
        // Measured independently on a curved crease: longer than its chord, as long as a fine
        // polyline of its spline.
        for (const auto& [id, record] : surface.edges()) {
            if (record.isSpline() && surface.facesOfEdge(id).size() == 2) {
                const double length = model::edgeLength(surface, id);
                QVERIFY(length >
                        distance(surface.position(record.from), surface.position(record.to)));
                const model::BSplineCurve spline =
                    model::BSplineCurve::uniform(record.space, record.controlPoints);
                double polyline = 0.0;
                for (int k = 1; k <= 20000; ++k) {
                    const auto at = [&](int j) {
                        return spline.evaluate(spline.domainBegin() +
                                               (spline.domainEnd() - spline.domainBegin()) * j /
                                                   20000.0);
                    };
                    polyline += distance(at(k - 1), at(k));
                }
                QVERIFY(std::abs(length - polyline) < 1e-6 * polyline);
                break;
            }
        }
    }

    void onTheFoldedFig8TheSheetDistanceIsTheDevelopments() {
        QTemporaryDir dir;
        const QString flat = dir.filePath(QStringLiteral("fig8.devsurf"));
        const QString folded = dir.filePath(QStringLiteral("folded.devsurf"));
        QCOMPARE(test::runCli({"example", "fig8", "--as-built", "-o", flat}).exitCode, 0);
        QCOMPARE(test::runCli({"drag", flat, "--vertices", "5,6,9,10", "--by", "0,0,85",
                               "--keep-lengths", "-o", folded})
                     .exitCode,
                 0);
        app::MainWindow window;
        window.show();
        window.activateWindow();
        QVERIFY(QTest::qWaitForWindowActive(&window));
        QVERIFY(window.workspace()->open(folded));
        const model::CompositeSurface& surface = window.workspace()->document()->surface(0);
        // A point in the middle of patch 0 (lower left) and of patch 8 (upper right), across
        // both folds: a sampled quad's centre, in space and on the development.
        const auto derived = model::DerivedGeometry::of(surface, model::kSheetSamples);
        const model::SampledMesh& mesh = derived->mesh();
        auto middleOf = [&](model::FaceId patch) {
            std::vector<std::size_t> quads;
            for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
                if (mesh.faceOrigin[f] == patch) {
                    quads.push_back(f);
                }
            }
            const auto& loop = mesh.faces[quads[quads.size() / 2]];
            model::Vec3 space;
            model::Vec2 sheet;
            for (int v : loop) {
                space += mesh.vertices[static_cast<std::size_t>(v)] / double(loop.size());
                sheet = sheet + derived->development().vertices[static_cast<std::size_t>(v)] *
                                    (1.0 / double(loop.size()));
            }
            return std::make_pair(space, sheet);
        };
        const auto [spaceA, sheetA] = middleOf(0);
        const auto [spaceB, sheetB] = middleOf(8);
        const double space = distance(spaceA, spaceB);
        const double sheet = (sheetA - sheetB).norm();
        qInfo("fig8 folded: patches 0 and 8 %.2f mm apart in space, %.2f mm on the sheet", space,
              sheet);
        QVERIFY(sheet > space + 5.0); // folded: closer in space than on the sheet

        QAction* action = window.action(QStringLiteral("actionMeasureTool"));
        action->setChecked(true);
        views::SurfaceView* view = window.surfaceView();
        view->grabImage();
        for (const model::Vec3& point : {spaceA, spaceB}) {
            QTest::mouseClick(view->glWidget(), Qt::LeftButton, {}, view->projectToWidget(point));
        }
        app::MeasureTool* tool = action->findChild<app::MeasureTool*>();
        QVERIFY(tool != nullptr);
        // Within what a pixel of the click makes.
        QVERIFY2(std::abs(tool->spaceDistance() - space) < 2.0,
                 qPrintable(QString::number(tool->spaceDistance())));
        QVERIFY2(std::abs(tool->sheetDistance() - sheet) < 2.0,
                 qPrintable(QString::number(tool->sheetDistance())));
        // An edit clears the measurement: it belonged to the shape it was taken on.
        window.workspace()->document()->undoStack()->push(
            document::PinVerticesCommand::create(*window.workspace()->document(), 0, {5}, true)
                .takeCommand()
                .release());
        QVERIFY(tool->text().isEmpty());
        QVERIFY(window.surfaceView()->measurementPoints().empty());
    }
};

DEVSURF_REGISTER_TEST(TstMeasure);
#include "tst_measure.moc"
