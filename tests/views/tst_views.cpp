#include "model/document/document.h"
#include "model/document/selection.h"
#include "model/examples.h"
#include "side_by_side_views.h"
#include "test_registry.h"
#include "views/development_view.h"
#include "views/surface_view.h"
#include "views/vtk_opengl_widget.h"

#include <QApplication>
#include <QMouseEvent>
#include <QSignalSpy>
#include <QTest>
#include <QVBoxLayout>

#include <cmath>
#include <memory>
#include <optional>
#include <set>

using devsurf::document::Change;
using devsurf::document::Document;
using devsurf::document::Pick;
using devsurf::document::Selection;
using devsurf::model::CompositeSurface;
using devsurf::model::Vec3;
using devsurf::model::VertexId;
using devsurf::views::DevelopmentView;
using devsurf::views::SceneView;
using devsurf::views::SurfaceView;

namespace {

const char* const kExamples[] = {"sheet", "annulus", "cylinder", "mixed"};

// Both views side by side in one top-level window.
struct Views : devsurf::test::SideBySideViews {
    explicit Views(const QString& example)
        : SideBySideViews(devsurf::model::makeExample(example.toStdString()), 900, 450) {}
};

bool isDarkColour(const QColor& c) {
    return c.red() < 110 && c.green() < 110 && c.blue() < 110;
}

QColor pixelAt(const QImage& image, const QPoint& widgetPos) {
    const double dpr = image.devicePixelRatio();
    return image.pixelColor(QPoint(static_cast<int>(std::lround(widgetPos.x() * dpr)),
                                   static_cast<int>(std::lround(widgetPos.y() * dpr))));
}

// Distinct colours in the middle half of the image.
int centralColours(const QImage& image) {
    const QRect central(image.width() / 4, image.height() / 4, image.width() / 2,
                        image.height() / 2);
    std::set<QRgb> colours;
    for (int y = central.top(); y <= central.bottom(); y += 2) {
        for (int x = central.left(); x <= central.right(); x += 2) {
            colours.insert(image.pixel(x, y) & 0xffffffu);
        }
    }
    return static_cast<int>(colours.size());
}

int darkPixelsAround(const QImage& image, const QPoint& widgetPos) {
    int count = 0;
    for (int dy = -4; dy <= 4; ++dy) {
        for (int dx = -4; dx <= 4; ++dx) {
            count += isDarkColour(pixelAt(image, widgetPos + QPoint(dx, dy))) ? 1 : 0;
        }
    }
    return count;
}

bool isOrange(const QColor& c) {
    return c.red() > 170 && c.blue() < 110 && c.red() > c.green() + 40;
}

// A vertex drawn well inside the view where a click can only mean that vertex: every other
// vertex drawn near it on screen lies far behind it along the viewing direction (on the
// closed examples, hidden by the surface in between). In the 3D view only the vertices nearest
// to the eye are tried.
std::optional<VertexId> isolatedVertex(const SceneView& view, const CompositeSurface& surface,
                                       bool frontOnly) {
    const Vec3 direction = view.viewDirection();
    double nearest = std::numeric_limits<double>::infinity();
    double extent = 0.0;
    for (const auto& [id, p] : surface.vertices()) {
        nearest = std::min(nearest, dot(p, direction));
        extent = std::max(extent, p.norm());
    }
    const QRect inside = view.glWidget()->rect().adjusted(15, 15, -15, -15);
    for (const auto& [id, p] : surface.vertices()) {
        if (frontOnly && dot(p, direction) > nearest + 0.02 * extent) {
            continue;
        }
        const QPoint pos = view.projectVertexToWidget(0, id);
        if (!inside.contains(pos)) {
            continue;
        }
        bool alone = true;
        for (const auto& [other, q] : surface.vertices()) {
            const bool near = (view.projectVertexToWidget(0, other) - pos).manhattanLength() < 12;
            const bool farBehind = dot(q, direction) > dot(p, direction) + 0.1 * extent;
            if (other != id && near && !farBehind) {
                alone = false;
            }
        }
        if (alone) {
            return id;
        }
    }
    return std::nullopt;
}

} // namespace

class TstViews : public QObject {
    Q_OBJECT

private:
    static void examples_data() {
        QTest::addColumn<QString>("example");
        for (const char* name : kExamples) {
            QTest::newRow(name) << QString::fromLatin1(name);
        }
    }

private slots:

    void rendersGeometry_data() { examples_data(); }
    void rendersGeometry() {
        QFETCH(QString, example);
        Views views(example);
        QVERIFY(views.show());
        for (SceneView* view :
             {static_cast<SceneView*>(views.spatial), static_cast<SceneView*>(views.development)}) {
            const QImage image = view->grabImage();
            QVERIFY(!image.isNull());
            QVERIFY2(centralColours(image) > 1, qPrintable(example));
            QVERIFY(view->problem().isEmpty());
        }
    }

    void clickSelectsVertex_data() { examples_data(); }
    void clickSelectsVertex() {
        QFETCH(QString, example);
        Views views(example);
        QVERIFY(views.show());
        for (SceneView* view :
             {static_cast<SceneView*>(views.spatial), static_cast<SceneView*>(views.development)}) {
            const bool spatial = view == views.spatial;
            const std::optional<VertexId> vertex = isolatedVertex(*view, views.surface(), spatial);
            QVERIFY2(vertex.has_value(), qPrintable(example));
            const QPoint pos = view->projectVertexToWidget(0, *vertex);
            // The projection agrees with the rendering: a dark vertex dot is drawn there.
            QVERIFY(isDarkColour(pixelAt(view->grabImage(), pos)));

            const Pick expected{Pick::Kind::Vertex, 0, *vertex};
            QSignalSpy changed(&views.selection, &Selection::selectionChanged);
            QTest::mouseClick(view->glWidget(), Qt::LeftButton, {}, pos);
            QCOMPARE(changed.count(), 1);
            QCOMPARE(views.selection.picks(), std::set<Pick>{expected});
            QVERIFY(isOrange(pixelAt(view->grabImage(), pos)));

            // Shift-click toggles it off again; a plain click on empty space clears.
            QTest::mouseClick(view->glWidget(), Qt::LeftButton, Qt::ShiftModifier, pos);
            QVERIFY(views.selection.isEmpty());
            QTest::mouseClick(view->glWidget(), Qt::LeftButton, {}, pos);
            QCOMPARE(views.selection.picks().size(), std::size_t{1});
            QTest::mouseClick(view->glWidget(), Qt::LeftButton, {}, QPoint(2, 2));
            QVERIFY(views.selection.isEmpty());
        }
    }

    void selectionIsMirrored_data() { examples_data(); }
    void selectionIsMirrored() {
        QFETCH(QString, example);
        Views views(example);
        QVERIFY(views.show());
        const std::optional<VertexId> vertex =
            isolatedVertex(*views.development, views.surface(), false);
        QVERIFY(vertex.has_value());
        const QPoint pos2d = views.development->projectVertexToWidget(0, *vertex);

        // Picked in 3D, shown in 2D.
        const QImage before = views.development->grabImage();
        QVERIFY(!isOrange(pixelAt(before, pos2d)));
        const Pick pick{Pick::Kind::Vertex, 0, *vertex};
        views.selection.set({pick});
        QCOMPARE(views.development->highlightedPicks(), std::set<Pick>{pick});
        QCOMPARE(views.spatial->highlightedPicks(), std::set<Pick>{pick});
        QVERIFY(isOrange(pixelAt(views.development->grabImage(), pos2d)));

        // A face selected anywhere recolours both views.
        const devsurf::model::FaceId face = views.surface().faces().begin()->first;
        const Pick facePick{Pick::Kind::Face, 0, face};
        const QImage spatialBefore = views.spatial->grabImage();
        const QImage developmentBefore = views.development->grabImage();
        views.selection.set({facePick});
        QCOMPARE(views.spatial->highlightedPicks(), std::set<Pick>{facePick});
        QCOMPARE(views.development->highlightedPicks(), std::set<Pick>{facePick});
        QVERIFY(views.spatial->grabImage() != spatialBefore);
        QVERIFY(views.development->grabImage() != developmentBefore);

        // Clicked in 2D, highlighted in 3D.
        views.selection.clear();
        QTest::mouseClick(views.development->glWidget(), Qt::LeftButton, {}, pos2d);
        QCOMPARE(views.selection.picks(), std::set<Pick>{pick});
        QCOMPARE(views.spatial->highlightedPicks(), std::set<Pick>{pick});
    }

    void pickAtFindsEntities() {
        Views views(QStringLiteral("sheet"));
        QVERIFY(views.show());
        const CompositeSurface& sheet = views.surface();
        // The sheet lies in z = 0 and the 3D view looks straight down on it: the midpoint of
        // any edge is drawn on that edge, the centroid of a face inside that face.
        for (SceneView* view :
             {static_cast<SceneView*>(views.spatial), static_cast<SceneView*>(views.development)}) {
            const auto& [edgeId, edge] = *sheet.edges().begin();
            const QPoint pa = view->projectVertexToWidget(0, edge.from);
            const QPoint pb = view->projectVertexToWidget(0, edge.to);
            const QPoint mid = (pa + pb) / 2;
            QVERIFY((pa - pb).manhattanLength() > 40);
            const std::optional<Pick> onEdge = view->pickAt(mid);
            QVERIFY(onEdge.has_value());
            QCOMPARE(onEdge->kind, Pick::Kind::Edge);
            QCOMPARE(onEdge->id, edgeId);

            const auto& [faceId, loop] = *sheet.faces().begin();
            QPoint sum;
            for (VertexId v : loop) {
                sum += view->projectVertexToWidget(0, v);
            }
            const QPoint centroid = sum / static_cast<int>(loop.size());
            const std::optional<Pick> onFace = view->pickAt(centroid);
            QVERIFY(onFace.has_value());
            QCOMPARE(onFace->kind, Pick::Kind::Face);
            QCOMPARE(onFace->id, faceId);

            QVERIFY(!view->pickAt(QPoint(2, 2)).has_value());
            QVERIFY(!view->pickAt(QPoint(-10, 5)).has_value());
        }
    }

    void hoverDescribesEntity() {
        Views views(QStringLiteral("sheet"));
        QVERIFY(views.show());
        const std::optional<VertexId> vertex =
            isolatedVertex(*views.spatial, views.surface(), true);
        QVERIFY(vertex.has_value());
        QSignalSpy hover(views.spatial, &SceneView::hoverChanged);
        // Sent directly: QTest::mouseMove may move the real pointer and arrive later.
        QWidget* gl = views.spatial->glWidget();
        const QPoint pos = views.spatial->projectVertexToWidget(0, *vertex);
        QMouseEvent move(QEvent::MouseMove, pos, gl->mapToGlobal(pos), Qt::NoButton, Qt::NoButton,
                         Qt::NoModifier);
        QApplication::sendEvent(gl, &move);
        QCOMPARE(hover.count(), 1);
        // The vertex under the mouse, named by its number.
        const std::optional<devsurf::document::Pick> under = views.spatial->pickAt(pos);
        QVERIFY(under ==
                (devsurf::document::Pick{devsurf::document::Pick::Kind::Vertex, 0, *vertex}));
        const QString said = hover.last().at(0).toString();
        QVERIFY2(said.contains(QString::number(*vertex)), qPrintable(said));
    }

    void rubberBandSelectsVertices() {
        Views views(QStringLiteral("annulus"));
        QVERIFY(views.show());
        QWidget* gl = views.development->glWidget();
        const QPoint from(1, 1);
        const QPoint to(gl->width() - 2, gl->height() - 2);
        QTest::mousePress(gl, Qt::LeftButton, Qt::ControlModifier, from);
        QTest::mouseMove(gl, (from + to) / 2);
        QTest::mouseMove(gl, to);
        QTest::mouseRelease(gl, Qt::LeftButton, Qt::ControlModifier, to);
        std::set<Pick> all;
        for (const auto& entry : views.surface().vertices()) {
            all.insert(Pick{Pick::Kind::Vertex, 0, entry.first});
        }
        QCOMPARE(views.selection.picks(), all);
    }

    void toggles() {
        Views views(QStringLiteral("mixed"));
        QVERIFY(views.show());
        const std::optional<VertexId> vertex =
            isolatedVertex(*views.spatial, views.surface(), true);
        QVERIFY(vertex.has_value());
        const QPoint pos = views.spatial->projectVertexToWidget(0, *vertex);
        // Vertices lie on the (dark) curves: hiding the dots leaves fewer dark pixels around.
        const int withDots = darkPixelsAround(views.spatial->grabImage(), pos);
        views.spatial->setShowVertices(false);
        QVERIFY(!views.spatial->showVertices());
        QVERIFY(darkPixelsAround(views.spatial->grabImage(), pos) < withDots);
        views.spatial->setShowVertices(true);

        const QImage without = views.spatial->grabImage();
        views.spatial->setShowControlPolygons(true);
        QVERIFY(views.spatial->grabImage() != without);

        // The target point cloud is drawn when given.
        views.spatial->setShowControlPolygons(false);
        const QImage base = views.spatial->grabImage();
        std::vector<Vec3> cloud;
        for (const auto& entry : views.surface().vertices()) {
            cloud.push_back(entry.second + Vec3(3.0, 3.0, 3.0));
        }
        views.spatial->setTargetPointCloud(cloud);
        QCOMPARE(views.spatial->targetPointCloud().size(), cloud.size());
        QVERIFY(views.spatial->grabImage() != base);

        // The palette distinguishes every pair among the first ids, which neighbouring patches
        // of the examples carry.
        for (devsurf::model::FaceId a = 0; a < 6; ++a) {
            for (devsurf::model::FaceId b = a + 1; b < 6; ++b) {
                QVERIFY2(SurfaceView::patchColor(a) != SurfaceView::patchColor(b),
                         qPrintable(QStringLiteral("patches %1 and %2").arg(a).arg(b)));
            }
        }
    }

    void geometryChangeUpdatesImage() {
        Views views(QStringLiteral("sheet"));
        QVERIFY(views.show());
        // Move a corner of the sheet diagonally inwards and out of the plane.
        const VertexId corner = views.surface().vertices().begin()->first;
        const Vec3 old = views.surface().position(corner);
        const QPoint spatialBefore = views.spatial->projectVertexToWidget(0, corner);
        const QImage spatialImage = views.spatial->grabImage();
        const QImage developmentImage = views.development->grabImage();
        const std::optional<Vec3> flatBefore = views.development->vertexScenePoint(0, corner);
        QVERIFY(flatBefore.has_value());

        views.document.mutableProject().surfaces[0].moveVertex(corner,
                                                               old + Vec3(40.0, 40.0, 30.0));
        views.document.notifyChanged(Change::Geometry);

        QVERIFY(views.spatial->projectVertexToWidget(0, corner) != spatialBefore);
        QVERIFY(views.spatial->grabImage() != spatialImage);
        QVERIFY(views.development->grabImage() != developmentImage);
        // The development's corner moved relative to its neighbours: the unfolded rulings at the
        // corner take their new 3D lengths (up to the unfolding's tolerance for a surface that
        // is no longer exactly developable).
        const CompositeSurface& sheet = views.surface();
        for (const auto& [id, edge] : sheet.edges()) {
            if (edge.isSpline() || (edge.from != corner && edge.to != corner)) {
                continue;
            }
            const double length3d = distance(sheet.position(edge.from), sheet.position(edge.to));
            const Vec3 p = *views.development->vertexScenePoint(0, edge.from);
            const Vec3 q = *views.development->vertexScenePoint(0, edge.to);
            QVERIFY(std::abs(distance(p, q) - length3d) < 0.05 * length3d);
            QVERIFY(std::abs(distance(p, q) - 100.0) > 10.0); // it was 100 before the move
        }

        // A new project replaces everything.
        views.document.resetProject(devsurf::model::makeExample("cylinder"));
        QVERIFY(views.spatial->grabImage() != spatialImage);
        QVERIFY(centralColours(views.spatial->grabImage()) > 1);
    }

    void resizeReparentAndDestroy() {
        auto views = std::make_unique<Views>(QStringLiteral("mixed"));
        QVERIFY(views->show());
        const QSize before = views->spatial->grabImage().size();
        views->window.resize(700, 600);
        QTRY_COMPARE(views->spatial->glWidget()->height() > 500, true);
        const QImage resized = views->spatial->grabImage();
        QVERIFY(resized.size() != before);
        QVERIFY(centralColours(resized) > 1);
        // Picking still agrees with the rendering after the resize.
        const std::optional<VertexId> vertex =
            isolatedVertex(*views->spatial, views->surface(), true);
        QVERIFY(vertex.has_value());
        QCOMPARE(views->spatial->pickAt(views->spatial->projectVertexToWidget(0, *vertex)),
                 std::optional<Pick>(Pick{Pick::Kind::Vertex, 0, *vertex}));

        // Into another top-level window (a new GL context) and back.
        for (SceneView* view : {static_cast<SceneView*>(views->spatial),
                                static_cast<SceneView*>(views->development)}) {
            QWidget other;
            auto* layout = new QVBoxLayout(&other);
            layout->addWidget(view);
            other.resize(500, 400);
            other.show();
            QVERIFY(QTest::qWaitForWindowExposed(&other));
            QVERIFY(centralColours(view->grabImage()) > 1);
            views->window.layout()->addWidget(view);
            QTRY_VERIFY(view->isVisible());
            QVERIFY(centralColours(view->grabImage()) > 1);
        }
        QVERIFY(centralColours(views->development->grabImage()) > 1);

        // Destroyed while shown, with a selection.
        views->selection.set({Pick{Pick::Kind::Face, 0, views->surface().faces().begin()->first}});
        delete views->spatial;
        QVERIFY(centralColours(views->development->grabImage()) > 1);
        views.reset();
    }

    void viewWithoutDocument() {
        SurfaceView view(nullptr, nullptr);
        view.resize(200, 200);
        view.show();
        QVERIFY(QTest::qWaitForWindowExposed(&view));
        QVERIFY(!view.grabImage().isNull());
        QVERIFY(!view.pickAt(QPoint(100, 100)).has_value());
        QCOMPARE(view.projectVertexToWidget(0, 0), QPoint(-1, -1));
    }
};

DEVSURF_REGISTER_TEST(TstViews);
#include "tst_views.moc"
