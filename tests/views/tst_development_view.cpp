#include "model/bspline_curve.h"
#include "model/development.h"
#include "model/document/document.h"
#include "model/document/selection.h"
#include "model/examples.h"
#include "model/math_constants.h"
#include "model/sampled_mesh.h"
#include "model/sheet_creases.h"
#include "model/sheet_domain.h"
#include "side_by_side_views.h"
#include "straight_control_points.h"
#include "surface_transform.h"
#include "test_registry.h"
#include "views/crease_marks.h"
#include "views/development_view.h"
#include "views/surface_view.h"
#include "views/view_overlay.h"
#include "views/vtk_opengl_widget.h"

#include <QApplication>
#include <QHBoxLayout>
#include <QTest>
#include <QWheelEvent>

#include <cmath>
#include <limits>
#include <optional>

using devsurf::document::Change;
using devsurf::document::Document;
using devsurf::document::Selection;
using devsurf::model::CompositeSurface;
using devsurf::model::Vec3;
using devsurf::model::VertexId;
using devsurf::views::DevelopmentView;
using devsurf::views::SceneView;
using devsurf::views::SurfaceView;

namespace {

using devsurf::model::kPi;

struct DevelopmentViews : devsurf::test::SideBySideViews {
    explicit DevelopmentViews(devsurf::model::Project project)
        : SideBySideViews(std::move(project), 900, 450) {}
};

// Extent {width, height} of the development's drawn vertices, in scene millimetres.
std::pair<double, double> drawnExtent(const DevelopmentViews& views) {
    double lo[2] = {std::numeric_limits<double>::infinity(),
                    std::numeric_limits<double>::infinity()};
    double hi[2] = {-lo[0], -lo[1]};
    for (const auto& [id, p] : views.surface().vertices()) {
        const std::optional<Vec3> q = views.development->vertexScenePoint(0, id);
        if (q) {
            lo[0] = std::min(lo[0], q->x);
            hi[0] = std::max(hi[0], q->x);
            lo[1] = std::min(lo[1], q->y);
            hi[1] = std::max(hi[1], q->y);
        }
    }
    return {hi[0] - lo[0], hi[1] - lo[1]};
}

// Rows and columns of the image that hold something other than the background colour.
std::pair<int, int> paintedExtent(const QImage& image) {
    const QRgb background = image.pixel(1, 1);
    int minX = image.width();
    int maxX = -1;
    int minY = image.height();
    int maxY = -1;
    for (int y = 0; y < image.height(); ++y) {
        for (int x = 0; x < image.width(); ++x) {
            if (image.pixel(x, y) != background) {
                minX = std::min(minX, x);
                maxX = std::max(maxX, x);
                minY = std::min(minY, y);
                maxY = std::max(maxY, y);
            }
        }
    }
    return {maxX - minX, maxY - minY};
}

int redPixels(const QImage& image) {
    int count = 0;
    for (int y = 0; y < image.height(); ++y) {
        for (int x = 0; x < image.width(); ++x) {
            const QColor c = image.pixelColor(x, y);
            count += c.red() > 180 && c.green() < 70 && c.blue() < 70 ? 1 : 0;
        }
    }
    return count;
}

int darkPixelsNear(const QImage& image, const QPoint& widgetPos) {
    const double dpr = image.devicePixelRatio();
    int count = 0;
    for (int dy = -3; dy <= 3; ++dy) {
        for (int dx = -3; dx <= 3; ++dx) {
            const QPoint p(static_cast<int>(std::lround((widgetPos.x() + dx) * dpr)),
                           static_cast<int>(std::lround((widgetPos.y() + dy) * dpr)));
            if (image.rect().contains(p)) {
                const QColor c = image.pixelColor(p);
                count += c.red() < 80 && c.green() < 80 && c.blue() < 80 ? 1 : 0;
            }
        }
    }
    return count;
}

// A band winding one and a half times around the z-axis while rising: its development
// overlaps itself.
CompositeSurface helicalBand() {
    const int steps = 18;
    const devsurf::model::SplineSpace space{3, 2, 1};
    CompositeSurface s;
    std::vector<VertexId> inner;
    std::vector<VertexId> outer;
    for (int i = 0; i <= steps; ++i) {
        const double phi = 3.0 * kPi * i / steps;
        inner.push_back(s.addVertex({100 * std::cos(phi), 100 * std::sin(phi), 2.0 * i}));
        outer.push_back(s.addVertex({160 * std::cos(phi), 160 * std::sin(phi), 2.0 * i}));
    }
    for (int i = 0; i < steps; ++i) {
        s.addFace({inner[i], outer[i], outer[i + 1], inner[i + 1]});
    }
    for (int i = 0; i < steps; ++i) {
        for (const auto* chain : {&inner, &outer}) {
            const VertexId a = (*chain)[i];
            const VertexId b = (*chain)[i + 1];
            s.setSpline(a, b, space,
                        devsurf::test::straightControlPoints(space, s.position(a), s.position(b)));
        }
    }
    return s;
}

} // namespace

class TstDevelopmentView : public QObject {
    Q_OBJECT
private slots:
    void liftingOneVertexKeepsTheDevelopmentTwoDimensional() {
        // Lifting one vertex of a flat design by 1 mm used to fold the development onto a line.
        for (const char* name : {"annulus", "sheet"}) {
            DevelopmentViews views(devsurf::model::makeExample(name));
            QVERIFY(views.show());
            const auto [width, height] = drawnExtent(views);
            QVERIFY(width > 250 && height > 250);
            // A vertex from the middle of the surface's list.
            const VertexId lifted =
                std::next(views.surface().vertices().begin(),
                          static_cast<long>(views.surface().vertices().size() / 2))
                    ->first;
            const Vec3 old = views.surface().position(lifted);
            views.document.mutableProject().surfaces[0].moveVertex(lifted, old + Vec3(0, 0, 1));
            views.document.notifyChanged(Change::Geometry);
            views.development->fitAll();
            const auto [newWidth, newHeight] = drawnExtent(views);
            QVERIFY2(std::abs(newWidth - width) < 0.02 * width &&
                         std::abs(newHeight - height) < 0.02 * height,
                     qPrintable(QString("%1: %2 × %3 mm, was %4 × %5 mm")
                                    .arg(name)
                                    .arg(newWidth)
                                    .arg(newHeight)
                                    .arg(width)
                                    .arg(height)));
            // And on screen: the drawing fills the view in both directions.
            const QImage image = views.development->grabImage();
            const auto [painted, paintedHeight] = paintedExtent(image);
            QVERIFY2(painted > image.width() / 3 && paintedHeight > image.height() / 3, name);
            QVERIFY(views.development->problem().isEmpty());
        }
    }

    void mountainsAndValleysInBothViewsWithALegend() {
        // The 3 × 3 sheet folded along its crease y = 100: the part beyond it rising towards
        // the normal side (+z) makes that crease a valley, sinking a mountain; flat: neither.
        for (const double degrees : {30.0, -30.0, 0.0}) {
            devsurf::model::Project project = devsurf::model::makeExample("sheet", 3);
            CompositeSurface& surface = project.surfaces.front();
            devsurf::test::foldBeyond(surface, 100.0, degrees * kPi / 180.0);
            DevelopmentViews views(std::move(project));
            QVERIFY(views.show());
            const std::pair<int, int> expected =
                degrees > 0 ? std::pair(0, 3) : (degrees < 0 ? std::pair(3, 0) : std::pair(0, 0));
            QCOMPARE(views.spatial->foldsDrawn(), expected);
            QCOMPARE(views.development->foldsDrawn(), expected);
            const std::pair<bool, bool> legend(expected.first > 0, expected.second > 0);
            QCOMPARE(views.spatial->foldLegend(), legend);
            QCOMPARE(views.development->foldLegend(), legend);
            // The valley blue is really on screen in the development (and not when flat).
            const QImage image = views.development->grabImage();
            int blue = 0;
            for (int y = 0; y < image.height(); ++y) {
                for (int x = 0; x < image.width(); ++x) {
                    const QColor c = image.pixelColor(x, y);
                    blue += c.blue() > 180 && c.red() < 90 && c.green() < 140 ? 1 : 0;
                }
            }
            QVERIFY2((blue > 50) == (expected.second > 0), qPrintable(QString::number(blue)));
            // Folds are dashed (mountain dash-dot, valley dashed), a few device pixels per
            // unit of the pattern whatever the zoom; a crease that is not folded is solid.
            for (SceneView* view : {static_cast<SceneView*>(views.spatial),
                                    static_cast<SceneView*>(views.development)}) {
                const auto [mountainDashes, valleyDashes] = view->foldDashesDrawn();
                QCOMPARE(mountainDashes > 3 * expected.first, expected.first > 0);
                QCOMPARE(valleyDashes > 3 * expected.second, expected.second > 0);
                // The sheet's creases at y = 200 stay flat.
                QVERIFY(view->legendContents().flatCreases);
                const double devicePixels = view->foldDashUnit() * view->scaleBarPixels() /
                                            view->scaleBarLength() *
                                            view->glWidget()->devicePixelRatioF();
                QVERIFY2(devicePixels > 0.8 * devsurf::views::kFoldDashUnitPixels &&
                             devicePixels < 1.25 * devsurf::views::kFoldDashUnitPixels,
                         qPrintable(QString::number(devicePixels)));
            }
        }
    }

    void foldDashesFollowTheZoom() {
        devsurf::model::Project project = devsurf::model::makeExample("sheet", 3);
        devsurf::test::foldBeyond(project.surfaces.front(), 100.0, 30.0 * kPi / 180.0);
        DevelopmentViews views(std::move(project));
        QVERIFY(views.show());
        DevelopmentView* view = views.development;
        const double unit = view->foldDashUnit();
        const int dashes = view->foldDashesDrawn().second;
        // Six wheel clicks towards the design: its lines grow on screen, their dashes do not.
        for (int click = 0; click < 6; ++click) {
            QWheelEvent wheel(QPointF(view->glWidget()->rect().center()),
                              view->glWidget()->mapToGlobal(view->glWidget()->rect().center()),
                              QPoint(), QPoint(0, 120), Qt::NoButton, Qt::NoModifier,
                              Qt::NoScrollPhase, false);
            QApplication::sendEvent(view->glWidget(), &wheel);
        }
        view->grabImage();
        QVERIFY2(view->foldDashUnit() < 0.6 * unit,
                 qPrintable(QString("%1 → %2 mm").arg(unit).arg(view->foldDashUnit())));
        QVERIFY2(view->foldDashesDrawn().second > dashes,
                 qPrintable(QString("%1 → %2").arg(dashes).arg(view->foldDashesDrawn().second)));
        // The same design a thousand times larger replaces it: its folds are not cut into the
        // dashes of the last zoom (millions) before it is fitted and drawn.
        devsurf::model::Project large = devsurf::model::makeExample("sheet", 3);
        devsurf::test::foldBeyond(large.surfaces.front(), 100.0, 30.0 * kPi / 180.0);
        devsurf::test::transformSurface(large.surfaces.front(),
                                        [](const Vec3& p) { return p * 1000.0; });
        views.document.resetProject(std::move(large));
        QVERIFY2(view->foldDashesDrawn().second < 20 * dashes,
                 qPrintable(QString::number(view->foldDashesDrawn().second)));
        view->grabImage();
        QVERIFY2(view->foldDashesDrawn().second < 2 * dashes,
                 qPrintable(QString("%1 → %2").arg(dashes).arg(view->foldDashesDrawn().second)));
    }

    void cylinderIsUprightAndItsSeamDrawnOnBothSides() {
        DevelopmentViews views(devsurf::model::makeExample("cylinder", 6));
        QVERIFY(views.show());
        const CompositeSurface& surface = views.surface();
        // Height in space is height in the development, and up on screen in both views.
        for (const auto& [a, pa] : surface.vertices()) {
            for (const auto& [b, pb] : surface.vertices()) {
                if (pb.z - pa.z < 1.0) {
                    continue;
                }
                const Vec3 qa = *views.development->vertexScenePoint(0, a);
                const Vec3 qb = *views.development->vertexScenePoint(0, b);
                QVERIFY(std::abs((qb.y - qa.y) - (pb.z - pa.z)) < 1e-6);
                QVERIFY(views.development->projectToWidget(qb).y() <
                        views.development->projectToWidget(qa).y());
            }
        }
        // The cut runs along a ruling: its vertices are drawn on both sides, one
        // circumference apart.
        double circumference = 0;
        for (const auto& [edge, record] : surface.edges()) {
            if (record.isSpline() && record.controlPoints.front().z == 0.0) {
                const auto curve =
                    devsurf::model::BSplineCurve::uniform(record.space, record.controlPoints);
                for (int i = 0; i < 1000; ++i) {
                    circumference +=
                        distance(curve.evaluate(i / 1000.0), curve.evaluate((i + 1) / 1000.0));
                }
            }
        }
        const auto [width, height] = drawnExtent(views);
        QVERIFY(std::abs(height - 180.0) < 1e-6);
        QVERIFY(width < circumference - 1.0); // the map holds one copy of every vertex
        const QImage image = views.development->grabImage();
        int seamVertices = 0;
        for (const auto& [id, p] : surface.vertices()) {
            const Vec3 q = *views.development->vertexScenePoint(0, id);
            for (const double side : {-1.0, 1.0}) {
                const QPoint other =
                    views.development->projectToWidget(q + Vec3(side * circumference, 0, 0));
                if (image.rect().contains(other) && darkPixelsNear(image, other) > 10) {
                    ++seamVertices;
                }
            }
        }
        QCOMPARE(seamVertices, 4); // the 4 vertices of the cut ruling (3 rows)
    }

    void heldSheetIsDrawnBehindItsDevelopment() {
        // fig8 held on a disk of radius 250 mm around its 300 mm square.
        devsurf::model::Project project = devsurf::model::makeExample("fig8");
        CompositeSurface& held = project.surfaces[0];
        QVERIFY(!devsurf::model::keepDevelopment(held));
        devsurf::model::SheetDomain disk;
        disk.shape = devsurf::model::SheetShape::Disk;
        disk.radius = 250.0;
        const auto mesh =
            devsurf::model::sampleSurface(held, devsurf::model::kDevelopmentSamplesPerInterval);
        held.setSheetDomain(devsurf::model::placeDomain(disk, mesh, held.development()));
        DevelopmentViews views(project);
        QVERIFY(views.show());
        QCOMPARE(views.development->sheetLoopsDrawn(), 1);
        QCOMPARE(views.spatial->sheetLoopsDrawn(), 0);
        QVERIFY(
            views.development->legendEntries().contains(devsurf::views::ViewOverlay::tr("Sheet")));
        QVERIFY(!views.spatial->legendEntries().contains(devsurf::views::ViewOverlay::tr("Sheet")));
        // The disk is wider than the square: the fitted view shows it whole, in its colour.
        const auto countSheetPixels = [&views] {
            const QImage image = views.development->grabImage();
            int count = 0;
            for (int y = 0; y < image.height(); ++y) {
                for (int x = 0; x < image.width(); ++x) {
                    const QColor c = image.pixelColor(x, y);
                    count += std::abs(c.red() - 219) < 25 && std::abs(c.green() - 158) < 25 &&
                                     std::abs(c.blue() - 77) < 25
                                 ? 1
                                 : 0;
                }
            }
            return count;
        };
        const int drawn = countSheetPixels();
        QVERIFY2(drawn > 500, qPrintable(QString::number(drawn)));
        // View ▸ Sheet Outline off hides it and its legend entry; on shows it again.
        views.development->setShowSheet(false);
        QVERIFY(countSheetPixels() < drawn / 20);
        QTRY_VERIFY(
            !views.development->legendEntries().contains(devsurf::views::ViewOverlay::tr("Sheet")));
        views.development->setShowSheet(true);
        QCOMPARE(countSheetPixels(), drawn);
        // Letting the sheet stretch again takes the sheet away.
        views.document.mutableProject().surfaces[0].setKeepsDevelopment(false);
        views.document.notifyChanged(Change::Geometry);
        QCOMPARE(views.development->sheetLoopsDrawn(), 0);
        QTRY_VERIFY(
            !views.development->legendEntries().contains(devsurf::views::ViewOverlay::tr("Sheet")));
        QVERIFY(countSheetPixels() < drawn / 20); // a few pixels of the patches' blending
    }

    void creaseCurvesAreDrawnInTheSheet() {
        // The annulus held on an annulus sheet with circles drawn at 130 and 205 mm for its
        // rings at 125 and 200 mm: the development view draws the two curves beside the sheet's
        // two loops, in the sheet's line; without the curves only the loops.
        devsurf::model::Project project = devsurf::model::makeExample("annulus");
        CompositeSurface& held = project.surfaces[0];
        QVERIFY(!devsurf::model::keepDevelopment(held));
        devsurf::model::SheetDomain ring;
        ring.shape = devsurf::model::SheetShape::Annulus;
        ring.innerRadius = 100.0;
        ring.radius = 250.0;
        const auto mesh =
            devsurf::model::sampleSurface(held, devsurf::model::kDevelopmentSamplesPerInterval);
        ring = devsurf::model::placeDomain(ring, mesh, held.development());
        for (double r : {130.0, 205.0}) {
            devsurf::model::SheetDomain::Curve circle;
            circle.closed = true;
            for (int i = 0; i < 360; ++i) {
                circle.points.emplace_back(r * std::cos(i * kPi / 180.0),
                                           r * std::sin(i * kPi / 180.0));
            }
            ring.creaseCurves.push_back(circle);
        }
        ring.creaseCurveOf =
            devsurf::model::assignCreasesToCurves(ring, held, mesh, held.development());
        QCOMPARE(static_cast<int>(ring.creaseCurveOf.size()), 16);
        held.setSheetDomain(ring);
        DevelopmentViews views(project);
        QVERIFY(views.show());
        QCOMPARE(views.development->sheetLoopsDrawn(), 4);
        ring.creaseCurves.clear();
        ring.creaseCurveOf.clear();
        views.document.mutableProject().surfaces[0].setSheetDomain(ring);
        views.document.notifyChanged(Change::Geometry);
        QCOMPARE(views.development->sheetLoopsDrawn(), 2);
    }

    void overlappingPiecesAreOutlinedInRed() {
        devsurf::model::Project band;
        band.surfaces.push_back(helicalBand());
        DevelopmentViews views(std::move(band));
        QVERIFY(views.show());
        QVERIFY(redPixels(views.development->grabImage()) > 100);
        views.document.resetProject(devsurf::model::makeExample("annulus"));
        QCOMPARE(redPixels(views.development->grabImage()), 0);
    }
};

DEVSURF_REGISTER_TEST(TstDevelopmentView);

#include "tst_development_view.moc"
