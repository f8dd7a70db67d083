// Tools ▸ Mark Region of Reference Shape and Add Strip Over Marked Region (issue 42): a lasso
// drawn with real mouse events marks exactly the points it should (checked against the view's
// own projection of every point and against the known geometry: a lasso around the left half
// of a plane marks its left half), only those facing the camera; Shift adds; the strip lies
// in the PCA plane of the marked points (checked with the covariance computed here) and covers
// them; undo and redo take it back and restore it byte for byte; a mark on a line is refused
// in one sentence; the mark is view state, cleared with the shapes or the project.
#include "main_window.h"
#include "mark_region_tool.h"
#include "model/document/commands/add_surfaces_command.h"
#include "model/document/commands/command_or_error.h"
#include "model/document/commands/reference_shapes_command.h"
#include "model/document/document.h"
#include "model/examples.h"
#include "model/reference/lasso_marking.h"
#include "test_registry.h"
#include "views/surface_view.h"
#include "views/vtk_opengl_widget.h"
#include "window_test_support.h"
#include "workspace.h"

#include <QAction>
#include <QSettings>
#include <QStatusBar>
#include <QTest>
#include <QTreeView>
#include <QUndoStack>

#include <algorithm>
#include <cmath>
#include <set>

using namespace devsurf;
using model::Vec2;
using model::Vec3;

namespace {

// A flat mesh in z = 0, `columns` × `rows` vertices over x ∈ (−50, 50), y ∈ (−30, 30), no
// vertex on x = 0; its triangles face +z.
model::ReferenceShape planeMesh(int columns = 30, int rows = 18) {
    model::ReferenceShape shape{"plane", "", {}, {}, {}};
    for (int j = 0; j < rows; ++j) {
        for (int i = 0; i < columns; ++i) {
            shape.points.push_back(
                {-50.0 + 100.0 * (i + 0.5) / columns, -30.0 + 60.0 * (j + 0.5) / rows, 0.0});
        }
    }
    for (int j = 0; j + 1 < rows; ++j) {
        for (int i = 0; i + 1 < columns; ++i) {
            const int a = j * columns + i;
            shape.triangles.push_back({a, a + 1, a + columns + 1});
            shape.triangles.push_back({a, a + columns + 1, a + columns});
        }
    }
    return shape;
}

// The same grid bent into a bowl z = (x² + y²) / 150: the marked points are not planar.
model::ReferenceShape bowlMesh() {
    model::ReferenceShape shape = planeMesh();
    shape.name = "bowl";
    for (Vec3& p : shape.points) {
        p.z = (p.x * p.x + p.y * p.y) / 150.0;
    }
    return shape;
}

void openShapeOnly(app::MainWindow& window, const model::ReferenceShape& shape) {
    model::Project project;
    project.referenceShapes.push_back(shape);
    window.workspace()->document()->resetProject(project);
}

app::MarkRegionTool* toolOf(app::MainWindow& window) {
    return window.action(QStringLiteral("actionMarkRegion"))->findChild<app::MarkRegionTool*>();
}

// Looks from the top (along −z) and renders, so that projections are current.
void lookFromTop(app::MainWindow& window) {
    window.action(QStringLiteral("actionViewTop"))->trigger();
    window.surfaceView()->grabImage();
}

// Draws a lasso through the corners of `rect` (widget coordinates), with intermediate moves
// along its sides, as a user drags it.
void drawLasso(views::SurfaceView* view, const QRect& rect,
               Qt::KeyboardModifiers modifiers = Qt::NoModifier, bool heldToTheEnd = true) {
    QWidget* gl = view->glWidget();
    const QPoint corners[] = {rect.topLeft(), rect.topRight(), rect.bottomRight(),
                              rect.bottomLeft(), rect.topLeft()};
    QTest::mousePress(gl, Qt::LeftButton, modifiers, corners[0]);
    for (int side = 0; side < 4; ++side) {
        for (int k = 1; k <= 8; ++k) {
            const QPointF at = corners[side] + (corners[side + 1] - corners[side]) * (k / 8.0);
            QTest::mouseMove(gl, at.toPoint());
        }
    }
    QTest::mouseRelease(gl, Qt::LeftButton, heldToTheEnd ? modifiers : Qt::NoModifier, corners[4]);
}

// The points of `shape` the view draws inside `rect` (its own projection, point by point).
std::vector<std::size_t> projectedInside(const views::SurfaceView* view,
                                         const model::ReferenceShape& shape, const QRect& rect) {
    std::vector<std::size_t> inside;
    for (std::size_t i = 0; i < shape.points.size(); ++i) {
        if (rect.contains(view->projectToWidget(shape.points[i]))) {
            inside.push_back(i);
        }
    }
    return inside;
}

// The screen rectangle from the left of the shape to the screen position of x = `rightX`,
// reaching beyond its top and bottom.
QRect leftOf(const views::SurfaceView* view, const model::ReferenceShape& shape, double rightX,
             double lowY = -1e9, double highY = 1e9) {
    int left = 1 << 20, top = 1 << 20, bottom = -(1 << 20);
    for (const Vec3& p : shape.points) {
        const QPoint at = view->projectToWidget(p);
        left = std::min(left, at.x());
        if (p.y >= lowY && p.y <= highY) {
            top = std::min(top, at.y());
            bottom = std::max(bottom, at.y());
        }
    }
    const int right = view->projectToWidget({rightX, 0.0, 0.0}).x();
    return QRect(QPoint(left - 15, top - 4), QPoint(right, bottom + 4));
}

} // namespace

class TstRegionMarking : public QObject {
    Q_OBJECT

private slots:
    void init() { QSettings().clear(); }

    void pointInPolygonAndFacing() {
        using model::reference::insidePolygon;
        // A concave L: its notch is outside.
        const std::vector<Vec2> ell{{0, 0}, {10, 0}, {10, 4}, {4, 4}, {4, 10}, {0, 10}};
        QVERIFY(insidePolygon(ell, {2, 2}));
        QVERIFY(insidePolygon(ell, {8, 2}));
        QVERIFY(insidePolygon(ell, {2, 8}));
        QVERIFY(!insidePolygon(ell, {8, 8}));
        QVERIFY(!insidePolygon(ell, {-1, 2}));
        QVERIFY(!insidePolygon({{0, 0}, {10, 0}}, {5, 0}));

        // A camera looking down −z, screen x = scene x, screen y = −scene y.
        model::reference::LassoCamera camera;
        camera.toScreen = {1, 0, 0, 0, 0, -1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
        camera.parallel = true;
        camera.direction = {0, 0, -1};
        const std::vector<Vec2> square{{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
        // A cloud with normals: the one facing away is not marked, nor the one outside.
        model::ReferenceShape cloud{"cloud", "", {{0, 0, 0}, {0.5, 0.5, 1}, {3, 0, 0}}, {}, {}};
        cloud.normals = {{0, 0, 1}, {0, 0, -1}, {0, 0, 1}};
        QCOMPARE(model::reference::pointsInLasso(cloud, square, camera),
                 std::vector<std::size_t>{0});
        // Without normals its sides cannot be told apart: both inside are marked.
        cloud.normals.clear();
        QCOMPARE(model::reference::pointsInLasso(cloud, square, camera),
                 (std::vector<std::size_t>{0, 1}));
        // A mesh: a triangle facing up, one facing down, and a vertex no triangle uses.
        model::ReferenceShape mesh{"mesh",
                                   "",
                                   {{0, 0, 0},
                                    {0.5, 0, 0},
                                    {0, 0.5, 0}, // up
                                    {0, 0, -1},
                                    {0, -0.5, -1},
                                    {0.5, 0, -1},   // down
                                    {0.2, 0.2, 3}}, // unused
                                   {},
                                   {{0, 1, 2}, {3, 5, 4}}};
        QCOMPARE(model::reference::pointsInLasso(mesh, square, camera),
                 (std::vector<std::size_t>{0, 1, 2}));
        // Seen from below, the other triangle.
        camera.toScreen = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
        camera.direction = {0, 0, 1};
        QCOMPARE(model::reference::pointsInLasso(mesh, square, camera),
                 (std::vector<std::size_t>{3, 4, 5}));
    }

    void actionNeedsAReferenceShape() {
        app::MainWindow window;
        QVERIFY(test::showActiveWithExample(window, QStringLiteral("sheet")));
        document::Document* doc = window.workspace()->document();
        QAction* mark = window.action(QStringLiteral("actionMarkRegion"));
        QAction* strip = window.action(QStringLiteral("actionAddStripOverMark"));
        QVERIFY(mark != nullptr && strip != nullptr);
        QVERIFY(!mark->isEnabled());
        QVERIFY(!strip->isEnabled());
        const QString noShape = mark->toolTip();
        QVERIFY(!noShape.isEmpty());
        // Its shortcut is its own.
        QCOMPARE(mark->shortcut(), QKeySequence(QStringLiteral("L")));
        int same = 0;
        for (const QAction* other : window.findChildren<QAction*>()) {
            same += other->shortcuts().contains(mark->shortcut()) ? 1 : 0;
        }
        QCOMPARE(same, 1);
        document::CommandOrError add =
            document::ReferenceShapesCommand::createImport(*doc, planeMesh());
        QVERIFY(document::push(*doc, add));
        QVERIFY(mark->isEnabled());
        QVERIFY(mark->toolTip() != noShape);
        QVERIFY(!strip->isEnabled()); // nothing marked yet
        mark->setChecked(true);
        doc->undoStack()->undo();
        QVERIFY(!mark->isEnabled());
        QVERIFY(!mark->isChecked());
        QCOMPARE(mark->toolTip(), noShape);
    }

    void cameraMatchesTheViewsProjection() {
        app::MainWindow window;
        QVERIFY(test::showActiveWithExample(window, QStringLiteral("sheet")));
        openShapeOnly(window, bowlMesh());
        views::SurfaceView* view = window.surfaceView();
        view->grabImage();
        const model::reference::LassoCamera camera = view->lassoCamera();
        for (const Vec3& p : window.workspace()->document()->project().referenceShapes[0].points) {
            Vec2 screen;
            QVERIFY(camera.project(p, screen));
            const QPoint drawn = view->projectToWidget(p);
            QVERIFY2(std::abs(screen.x - drawn.x()) <= 0.51 &&
                         std::abs(screen.y - drawn.y()) <= 0.51,
                     qPrintable(QStringLiteral("%1 %2 vs %3 %4")
                                    .arg(screen.x)
                                    .arg(screen.y)
                                    .arg(drawn.x())
                                    .arg(drawn.y())));
        }
    }

    void lassoMarksTheLeftHalf() {
        app::MainWindow window;
        QVERIFY(test::showActiveWithExample(window, QStringLiteral("sheet")));
        const model::ReferenceShape plane = planeMesh();
        openShapeOnly(window, plane);
        const QByteArray before = QByteArray::fromStdString(test::bytesOf(window));
        views::SurfaceView* view = window.surfaceView();
        lookFromTop(window);
        window.action(QStringLiteral("actionMarkRegion"))->setChecked(true);
        app::MarkRegionTool* tool = toolOf(window);
        QVERIFY(tool != nullptr);

        const QRect left = leftOf(view, plane, 0.0);
        drawLasso(view, left);
        std::vector<std::size_t> expected;
        for (std::size_t i = 0; i < plane.points.size(); ++i) {
            if (plane.points[i].x < 0.0) {
                expected.push_back(i);
            }
        }
        QCOMPARE(expected.size(), plane.points.size() / 2);
        QCOMPARE(tool->marked().size(), std::size_t(1));
        QCOMPARE(tool->marked()[0], expected);
        QCOMPARE(projectedInside(view, plane, left), expected);
        QCOMPARE(view->markedPointsDrawn(), static_cast<int>(expected.size()));
        QVERIFY(view->lasso().empty()); // drawn only while dragging
        const QString message = window.statusBar()->currentMessage();
        QVERIFY2(message.contains(QLocale().toString(static_cast<int>(expected.size()))) &&
                     message.contains(QStringLiteral("plane")),
                 qPrintable(message));
        QVERIFY(window.action(QStringLiteral("actionAddStripOverMark"))->isEnabled());
        // View state only: the project is as it was, unmodified.
        QCOMPARE(QByteArray::fromStdString(test::bytesOf(window)), before);
        QVERIFY(!window.workspace()->document()->isModified());

        // Shift adds the upper rows (y > 10) of the right half; a plain lasso replaces.
        const QRect upper = leftOf(view, plane, 60.0, 10.0, 1e9);
        drawLasso(view, upper, Qt::ShiftModifier);
        std::set<std::size_t> both(expected.begin(), expected.end());
        for (std::size_t i : projectedInside(view, plane, upper)) {
            QVERIFY(plane.points[i].y > 10.0);
            both.insert(i);
        }
        QCOMPARE(tool->marked()[0], std::vector<std::size_t>(both.begin(), both.end()));
        drawLasso(view, upper);
        QCOMPARE(tool->marked()[0], projectedInside(view, plane, upper));
        // Shift held at the press only adds too.
        drawLasso(view, left, Qt::ShiftModifier, false);
        QCOMPARE(tool->marked()[0], std::vector<std::size_t>(both.begin(), both.end()));

        // Seen from below the plane faces away: a lasso around all of it marks nothing.
        window.action(QStringLiteral("actionViewBottom"))->trigger();
        view->grabImage();
        drawLasso(view, leftOf(view, plane, 60.0).united(leftOf(view, plane, -60.0)));
        QCOMPARE(tool->markedCount(), std::size_t(0));
        QCOMPARE(view->markedPointsDrawn(), 0);
        QVERIFY(!window.action(QStringLiteral("actionAddStripOverMark"))->isEnabled());
    }

    void stripOverTheMarkedRegion() {
        app::MainWindow window;
        QVERIFY(test::showActiveWithExample(window, QStringLiteral("sheet")));
        document::Document* doc = window.workspace()->document();
        const model::ReferenceShape bowl = bowlMesh();
        document::CommandOrError add = document::ReferenceShapesCommand::createImport(*doc, bowl);
        QVERIFY(document::push(*doc, add));
        views::SurfaceView* view = window.surfaceView();
        lookFromTop(window);
        window.action(QStringLiteral("actionMarkRegion"))->setChecked(true);
        app::MarkRegionTool* tool = toolOf(window);
        drawLasso(view, leftOf(view, bowl, -10.0, -20.0, 25.0));
        const std::vector<Vec3> points = tool->markedPositions();
        QVERIFY(points.size() > 50);
        const std::string markedBytes = test::bytesOf(window);
        const int surfaces = doc->surfaceCount();
        const int steps = doc->undoStack()->count();

        // Enter adds it (the view has the focus since the lasso's press).
        QTest::keyClick(view->glWidget(), Qt::Key_Return);
        QCOMPARE(doc->surfaceCount(), surfaces + 1);
        QCOMPARE(doc->undoStack()->count(), steps + 1);
        const model::CompositeSurface& strip = doc->surface(surfaces);
        QCOMPARE(QString::fromStdString(strip.name()),
                 QStringLiteral("strip %1").arg(surfaces + 1));
        QVERIFY(strip.validate().empty());
        QCOMPARE(strip.faces().size(), std::size_t(1));
        QCOMPARE(tool->markedCount(), std::size_t(0)); // the mark is used up
        QCOMPARE(view->markedPointsDrawn(), 0);
        QVERIFY(!window.action(QStringLiteral("actionAddStripOverMark"))->isEnabled());

        // The PCA plane of the marked points, computed here: the centroid and the covariance.
        Vec3 centroid;
        for (const Vec3& p : points) {
            centroid += p;
        }
        centroid = centroid / static_cast<double>(points.size());
        double c[3][3] = {};
        for (const Vec3& p : points) {
            const Vec3 d = p - centroid;
            for (int r = 0; r < 3; ++r) {
                for (int k = 0; k < 3; ++k) {
                    c[r][k] += d[r] * d[k];
                }
            }
        }
        const auto quadratic = [&c](const Vec3& u) {
            double sum = 0.0;
            for (int r = 0; r < 3; ++r) {
                for (int k = 0; k < 3; ++k) {
                    sum += u[r] * c[r][k] * u[k];
                }
            }
            return sum;
        };
        // The strip's corners: a trapezoid in one plane, its two curves parallel (each spans
        // the points of its half).
        std::vector<std::pair<Vec3, Vec3>> curves;
        for (const auto& [id, record] : strip.edges()) {
            if (record.isSpline()) {
                curves.emplace_back(strip.position(record.from), strip.position(record.to));
            }
        }
        QCOMPARE(curves.size(), std::size_t(2));
        const Vec3 a = curves[0].first;
        const Vec3 e1 = curves[0].second - a;
        const Vec3 e2 = curves[1].first - a;
        QVERIFY(cross(e1, curves[1].second - curves[1].first).norm() <
                1e-9 * e1.norm() * (curves[1].second - curves[1].first).norm());
        Vec3 normal = cross(e1, e2);
        normal = normal / normal.norm();
        QVERIFY(std::abs(dot(curves[1].second - a, normal)) < 1e-9 * e1.norm());
        // Through the centroid, and its normal the least-variance direction: an eigenvector
        // of the covariance whose value no other direction goes below.
        QVERIFY(std::abs(dot(centroid - a, normal)) < 1e-9 * e1.norm());
        const double least = quadratic(normal);
        Vec3 cn;
        for (int r = 0; r < 3; ++r) {
            cn[r] = c[r][0] * normal.x + c[r][1] * normal.y + c[r][2] * normal.z;
        }
        QVERIFY((cn - normal * least).norm() < 1e-9 * (quadratic(e1 / e1.norm()) + least));
        for (int k = 0; k < 2000; ++k) {
            const double theta = std::acos(1.0 - 2.0 * ((k * 0.618034) - std::floor(k * 0.618034)));
            const double phi = 2.399963 * k;
            const Vec3 u(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi),
                         std::cos(theta));
            QVERIFY(quadratic(u) >= least * (1.0 - 1e-12));
        }
        QVERIFY(least > 0.0); // the bowl is curved: the points are not planar
        // Every marked point, projected onto the plane, lies inside the trapezoid a0 a1 b1 b0:
        // on the inner side of each of its edges.
        const Vec3 quad[4] = {curves[0].first, curves[0].second, curves[1].second, curves[1].first};
        for (const Vec3& p : points) {
            double sides[4];
            for (int k = 0; k < 4; ++k) {
                sides[k] = dot(cross(quad[(k + 1) % 4] - quad[k], p - quad[k]), normal);
            }
            const bool inside = (sides[0] > 0 && sides[1] > 0 && sides[2] > 0 && sides[3] > 0) ||
                                (sides[0] < 0 && sides[1] < 0 && sides[2] < 0 && sides[3] < 0);
            QVERIFY2(inside, qPrintable(QStringLiteral("%1 %2 %3 %4")
                                            .arg(sides[0])
                                            .arg(sides[1])
                                            .arg(sides[2])
                                            .arg(sides[3])));
        }

        // One undo step: undo takes it back, redo restores it byte for byte.
        const std::string added = test::bytesOf(window);
        doc->undoStack()->undo();
        QCOMPARE(doc->surfaceCount(), surfaces);
        QVERIFY(test::bytesOf(window) == markedBytes);
        doc->undoStack()->redo();
        QVERIFY(test::bytesOf(window) == added);
    }

    void markOnALineIsRefused() {
        app::MainWindow window;
        QVERIFY(test::showActiveWithExample(window, QStringLiteral("sheet")));
        document::Document* doc = window.workspace()->document();
        // A cloud: a row of points on the x axis, and a wide patch far off at y = 100.
        model::ReferenceShape cloud{"line", "", {}, {}, {}};
        for (int i = 0; i < 20; ++i) {
            cloud.points.push_back({-50.0 + 5.0 * i, 0.0, 0.0});
        }
        for (int i = 0; i < 5; ++i) {
            for (int j = 0; j < 5; ++j) {
                cloud.points.push_back({-50.0 + 25.0 * i, 100.0 + 10.0 * j, 0.0});
            }
        }
        document::CommandOrError add = document::ReferenceShapesCommand::createImport(*doc, cloud);
        QVERIFY(document::push(*doc, add));
        views::SurfaceView* view = window.surfaceView();
        lookFromTop(window);
        window.action(QStringLiteral("actionMarkRegion"))->setChecked(true);
        app::MarkRegionTool* tool = toolOf(window);
        drawLasso(view, leftOf(view, cloud, 60.0, -1.0, 1.0).adjusted(0, -6, 0, 6));
        QCOMPARE(tool->markedCount(), std::size_t(20));
        const int surfaces = doc->surfaceCount();
        const int steps = doc->undoStack()->count();
        window.action(QStringLiteral("actionAddStripOverMark"))->trigger();
        QCOMPARE(window.statusBar()->currentMessage(),
                 app::MarkRegionTool::tr("The marked points lie on a line, so no plane fits them: "
                                         "mark a region that is wide in two directions."));
        QCOMPARE(doc->surfaceCount(), surfaces);
        QCOMPARE(doc->undoStack()->count(), steps);
        QCOMPARE(tool->markedCount(), std::size_t(20)); // kept, to add to

        // Two points are too few.
        const QPoint first = view->projectToWidget(cloud.points[0]);
        const int between = (view->projectToWidget(cloud.points[1]).x() +
                             view->projectToWidget(cloud.points[2]).x()) /
                            2;
        drawLasso(view,
                  QRect(QPoint(first.x() - 20, first.y() - 6), QPoint(between, first.y() + 6)));
        QCOMPARE(tool->markedCount(), std::size_t(2));
        window.action(QStringLiteral("actionAddStripOverMark"))->trigger();
        QCOMPARE(window.statusBar()->currentMessage(),
                 app::MarkRegionTool::tr("Too few points are marked for a strip: mark at least "
                                         "three points that do not lie on a line."));
        QCOMPARE(doc->surfaceCount(), surfaces);
    }

    void markIsClearedWithTheShapesOrTheProject() {
        app::MainWindow window;
        QVERIFY(test::showActiveWithExample(window, QStringLiteral("sheet")));
        document::Document* doc = window.workspace()->document();
        const model::ReferenceShape plane = planeMesh();
        document::CommandOrError add = document::ReferenceShapesCommand::createImport(*doc, plane);
        QVERIFY(document::push(*doc, add));
        views::SurfaceView* view = window.surfaceView();
        lookFromTop(window);
        QAction* markAction = window.action(QStringLiteral("actionMarkRegion"));
        markAction->setChecked(true);
        app::MarkRegionTool* tool = toolOf(window);
        const QRect left = leftOf(view, plane, 0.0);
        drawLasso(view, left);
        const std::size_t marked = tool->markedCount();
        QVERIFY(marked > 0);

        // Esc during a drag drops the lasso, the mark stays; Esc then leaves the tool.
        QWidget* gl = view->glWidget();
        QTest::mousePress(gl, Qt::LeftButton, {}, left.center());
        QTest::mouseMove(gl, left.center() + QPoint(40, 0));
        QTest::mouseMove(gl, left.center() + QPoint(40, 40));
        QVERIFY(view->lasso().size() >= 2);
        QTest::keyClick(gl, Qt::Key_Escape);
        QVERIFY(view->lasso().empty());
        QTest::mouseRelease(gl, Qt::LeftButton, {}, left.center() + QPoint(40, 40));
        QCOMPARE(tool->markedCount(), marked);
        QVERIFY(markAction->isChecked());
        QTest::keyClick(gl, Qt::Key_Escape);
        QVERIFY(!markAction->isChecked());
        QCOMPARE(tool->markedCount(), marked);
        QCOMPARE(view->markedPointsDrawn(), static_cast<int>(marked));

        // Turned on from the menu with the keyboard focus in a panel, Esc still leaves it.
        markAction->setChecked(true);
        auto* panel = window.findChild<QTreeView*>();
        QVERIFY(panel != nullptr);
        panel->setFocus();
        QTest::keyClick(panel, Qt::Key_Escape);
        QVERIFY(!markAction->isChecked());

        // A click without dragging clears it.
        markAction->setChecked(true);
        QTest::mouseClick(gl, Qt::LeftButton, {}, left.center());
        QCOMPARE(tool->markedCount(), std::size_t(0));

        // Another reference shape (and taking it back) clears it.
        drawLasso(view, left);
        QVERIFY(tool->markedCount() > 0);
        document::CommandOrError more =
            document::ReferenceShapesCommand::createImport(*doc, bowlMesh());
        QVERIFY(document::push(*doc, more));
        QCOMPARE(tool->markedCount(), std::size_t(0));
        QCOMPARE(view->markedPointsDrawn(), 0);
        drawLasso(view, left);
        QVERIFY(tool->markedCount() > 0);
        doc->undoStack()->undo();
        QCOMPARE(tool->markedCount(), std::size_t(0));
        // An edit of the design keeps it; another project clears it.
        drawLasso(view, left);
        const std::size_t again = tool->markedCount();
        QVERIFY(again > 0);
        document::CommandOrError edit = document::AddSurfacesCommand::create(
            *doc, {model::makeExample("sheet").surfaces.front()}, QStringLiteral("edit"));
        QVERIFY(document::push(*doc, edit));
        QCOMPARE(tool->markedCount(), again);
        window.workspace()->newFromExample(QStringLiteral("sheet"), 0);
        QCOMPARE(tool->markedCount(), std::size_t(0));
        QCOMPARE(view->markedPointsDrawn(), 0);
    }
};

DEVSURF_REGISTER_TEST(TstRegionMarking);
#include "tst_region_marking.moc"
