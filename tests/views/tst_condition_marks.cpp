#include "model/document/document.h"
#include "model/document/selection.h"
#include "model/examples.h"
#include "side_by_side_views.h"
#include "test_registry.h"
#include "views/crease_marks.h"
#include "views/development_view.h"
#include "views/surface_view.h"

#include <QHBoxLayout>
#include <QTest>

#include <algorithm>
#include <map>

using devsurf::document::Change;
using devsurf::document::Document;
using devsurf::document::Selection;
using devsurf::model::CompositeSurface;
using devsurf::model::CreaseCondition;
using devsurf::model::EdgeId;
using devsurf::model::Vec3;
using devsurf::views::DevelopmentView;
using devsurf::views::SceneView;
using devsurf::views::SurfaceView;
using devsurf::views::ViewOverlay;

namespace {

struct MarkedViews : devsurf::test::SideBySideViews {
    explicit MarkedViews(devsurf::model::Project project)
        : SideBySideViews(std::move(project), 1000, 500) {}

    // Edits the surface in place as a label change (what the commands announce) and renders.
    template <class Edit> void edit(Edit&& change) {
        change(document.mutableProject().surfaces[0]);
        document.notifyChanged(Change::Labels);
        spatial->grabImage();
        development->grabImage();
    }
};

// Pixels of an image within a few units of a colour.
int pixelsOf(const QImage& image, const QColor& colour, int tolerance) {
    int count = 0;
    for (int y = 0; y < image.height(); ++y) {
        for (int x = 0; x < image.width(); ++x) {
            const QColor c = image.pixelColor(x, y);
            count += std::abs(c.red() - colour.red()) <= tolerance &&
                             std::abs(c.green() - colour.green()) <= tolerance &&
                             std::abs(c.blue() - colour.blue()) <= tolerance && c.alpha() > 200
                         ? 1
                         : 0;
        }
    }
    return count;
}

// The 3 × 3 sheet (vertex j·4 + i at (100 i, 100 j)): curves run along x, rulings along y.
struct SheetEdges {
    EdgeId curvedFold, geodesic, straight, smooth;
};

SheetEdges sheetEdges(const CompositeSurface& sheet) {
    return {sheet.edgeBetween(4, 5), sheet.edgeBetween(5, 6), sheet.edgeBetween(9, 10),
            sheet.edgeBetween(5, 9)};
}

} // namespace

class TstConditionMarks : public QObject {
    Q_OBJECT
private slots:
    void conditionBadgesSmoothRulingsAndLegendInBothViews() {
        devsurf::model::Project project = devsurf::model::makeExample("sheet", 3);
        CompositeSurface& sheet = project.surfaces.front();
        const SheetEdges edges = sheetEdges(sheet);
        sheet.setCreaseCondition(edges.curvedFold, CreaseCondition::CurvedFold);
        sheet.setCreaseCondition(edges.geodesic, CreaseCondition::Geodesic);
        sheet.setCreaseCondition(edges.straight, CreaseCondition::Straight);
        sheet.setSmooth(edges.smooth, true);
        MarkedViews views(std::move(project));
        QVERIFY(views.show());

        const std::map<EdgeId, CreaseCondition> expected{
            {edges.curvedFold, CreaseCondition::CurvedFold},
            {edges.geodesic, CreaseCondition::Geodesic},
            {edges.straight, CreaseCondition::Straight}};
        // The sheet is flat: its creases are not folded.
        const std::vector<CreaseCondition> conditions{
            CreaseCondition::CurvedFold, CreaseCondition::Geodesic, CreaseCondition::Straight};
        for (SceneView* view :
             {static_cast<SceneView*>(views.spatial), static_cast<SceneView*>(views.development)}) {
            const auto badges = view->conditionBadges();
            QCOMPARE(badges.size(), expected.size());
            for (const ViewOverlay::Badge& badge : badges) {
                QCOMPARE(badge.surface, 0);
                QVERIFY(expected.count(badge.edge) == 1);
                QCOMPARE(badge.condition, expected.at(badge.edge));
                // At the middle of the straight crease, where the view draws it.
                const auto& record = views.document.project().surfaces[0].edge(badge.edge);
                const std::optional<Vec3> from = view->vertexScenePoint(0, record.from);
                const std::optional<Vec3> to = view->vertexScenePoint(0, record.to);
                QVERIFY(from && to);
                const QPoint middle = view->projectToWidget((*from + *to) * 0.5);
                QVERIFY2((badge.position - QPointF(middle)).manhattanLength() < 3.0,
                         qPrintable(QString("%1,%2 vs %3,%4")
                                        .arg(badge.position.x())
                                        .arg(badge.position.y())
                                        .arg(middle.x())
                                        .arg(middle.y())));
            }
            // One of the six rulings between two patches is smooth.
            QCOMPARE(view->rulingsDrawn(), std::make_pair(1, 5));
            // The legend: creases not folded, the three conditions by their badges, smooth and
            // sharp rulings.
            const ViewOverlay::LegendContents legend = view->legendContents();
            QVERIFY(legend.flatCreases && !legend.mountainFolds && !legend.valleyFolds);
            QCOMPARE(legend.conditions, conditions);
            QVERIFY(legend.smoothRulings && legend.sharpRulings);
            const QStringList entries = view->legendEntries();
            QCOMPARE(entries.size(), qsizetype(6));
            for (std::size_t i = 0; i < conditions.size(); ++i) {
                QVERIFY2(entries[qsizetype(i) + 1].startsWith(
                             ViewOverlay::badgeText(conditions[i]) + QLatin1Char(' ')),
                         qPrintable(entries.join(',')));
            }
            // The badges are painted in their colours.
            const QImage overlay = view->grabOverlay();
            for (const CreaseCondition condition :
                 {CreaseCondition::CurvedFold, CreaseCondition::Geodesic,
                  CreaseCondition::Straight}) {
                const int painted = pixelsOf(overlay, ViewOverlay::badgeColour(condition), 8);
                QVERIFY2(painted > 40, qPrintable(QString::number(painted)));
            }
        }
        const int whiteBefore = pixelsOf(views.spatial->grabImage(), Qt::white, 0);

        // Cleared conditions and a sharp ruling: no badges, no legend entries but the creases.
        views.edit([&](CompositeSurface& surface) {
            for (EdgeId edge : {edges.curvedFold, edges.geodesic, edges.straight}) {
                surface.setCreaseCondition(edge, CreaseCondition::None);
            }
            surface.setSmooth(edges.smooth, false);
        });
        for (SceneView* view :
             {static_cast<SceneView*>(views.spatial), static_cast<SceneView*>(views.development)}) {
            QVERIFY(view->conditionBadges().empty());
            QCOMPARE(view->rulingsDrawn(), std::make_pair(0, 6));
            const ViewOverlay::LegendContents legend = view->legendContents();
            QVERIFY(legend.flatCreases && legend.conditions.empty());
            QVERIFY(!legend.smoothRulings && !legend.sharpRulings);
            QCOMPARE(view->legendEntries().size(), qsizetype(1));
            for (const CreaseCondition condition :
                 {CreaseCondition::CurvedFold, CreaseCondition::Geodesic,
                  CreaseCondition::Straight}) {
                QCOMPARE(pixelsOf(view->grabOverlay(), ViewOverlay::badgeColour(condition), 8), 0);
            }
        }
        // The smooth ruling was drawn as a light line across the sheet in 3D.
        const int whiteAfter = pixelsOf(views.spatial->grabImage(), Qt::white, 0);
        QVERIFY2(whiteBefore > whiteAfter + 50,
                 qPrintable(QString("%1 → %2").arg(whiteBefore).arg(whiteAfter)));
    }

    void dashedPolylinesFollowThePatternAlongTheLine() {
        using devsurf::views::dashedPolylines;
        // A straight line of 100 mm in three pieces (corners at 31 and 62), dashed 4 on, 2
        // off: 17 dashes of 4 mm (the last one ends with the line); the two over a corner
        // (30–34 and 60–64) keep it.
        const std::vector<std::vector<Vec3>> line{
            {Vec3(0, 0, 0), Vec3(31, 0, 0), Vec3(62, 0, 0), Vec3(100, 0, 0)}};
        const auto dashes = dashedPolylines(line, {4.0, 2.0});
        QCOMPARE(dashes.size(), std::size_t{17});
        auto near = [](const Vec3& a, const Vec3& b) {
            return devsurf::model::distance(a, b) < 1e-12;
        };
        int overCorners = 0;
        for (std::size_t i = 0; i < dashes.size(); ++i) {
            const std::vector<Vec3>& dash = dashes[i];
            QVERIFY(dash.size() >= 2);
            QVERIFY(near(dash.front(), Vec3(6.0 * static_cast<double>(i), 0, 0)));
            double length = 0.0;
            for (std::size_t k = 0; k + 1 < dash.size(); ++k) {
                QVERIFY(dash[k + 1].x >= dash[k].x);
                length += devsurf::model::distance(dash[k], dash[k + 1]);
            }
            QVERIFY2(std::abs(length - 4.0) < 1e-9, qPrintable(QString::number(length)));
            bool overCorner = false;
            for (const double corner : {31.0, 62.0}) {
                overCorner = overCorner || (dash.front().x < corner && dash.back().x > corner);
            }
            overCorners += overCorner ? 1 : 0;
            QCOMPARE(dash.size(), overCorner ? std::size_t{3} : std::size_t{2});
        }
        QCOMPARE(overCorners, 2);
        // Around a right angle, dash-dot 6, 2, 1, 2: dashes from 0 to 6, 8 to 9, 11 to 17 and
        // 19 to 20 along the bend.
        const std::vector<std::vector<Vec3>> bend{{Vec3(0, 0, 0), Vec3(10, 0, 0), Vec3(10, 12, 0)}};
        const auto dashDot = dashedPolylines(
            bend, devsurf::views::foldDashes(devsurf::model::FoldAssignment::Mountain));
        QCOMPARE(dashDot.size(), std::size_t{4});
        QVERIFY(near(dashDot[0].back(), Vec3(6, 0, 0)));
        QVERIFY(near(dashDot[1].front(), Vec3(8, 0, 0)) && near(dashDot[1].back(), Vec3(9, 0, 0)));
        QVERIFY(near(dashDot[2].front(), Vec3(10, 1, 0)) &&
                near(dashDot[2].back(), Vec3(10, 7, 0)));
        QVERIFY(near(dashDot[3].front(), Vec3(10, 9, 0)) &&
                near(dashDot[3].back(), Vec3(10, 10, 0)));
        // A crease that is not folded is solid; a bad pattern leaves the lines as they are.
        QVERIFY(devsurf::views::foldDashes(devsurf::model::FoldAssignment::Flat).empty());
        for (const std::vector<double>& bad :
             std::vector<std::vector<double>>{{}, {4.0}, {4.0, 0.0}, {4.0, -1.0}}) {
            QCOMPARE(dashedPolylines(line, bad).size(), std::size_t{1});
        }
    }

    void aBadgeHiddenBehindTheSurfaceIsNotDrawnIn3D() {
        // The cylinder seen from the front: a crease on its far side is hidden by the near
        // wall, one on the near side is seen; the development shows both.
        devsurf::model::Project project = devsurf::model::makeExample("cylinder", 6);
        CompositeSurface& cylinder = project.surfaces.front();
        std::vector<EdgeId> creases;
        for (const auto& [id, record] : cylinder.edges()) {
            if (record.isSpline() && cylinder.facesOfEdge(id).size() == 2) {
                creases.push_back(id);
            }
        }
        QVERIFY(!creases.empty());
        for (EdgeId id : creases) {
            cylinder.setCreaseCondition(id, CreaseCondition::Geodesic);
        }
        MarkedViews views(std::move(project));
        QVERIFY(views.show());
        views.spatial->setStandardView(SceneView::StandardView::Front);
        views.spatial->grabImage();
        const auto seen = views.spatial->conditionBadges().size();
        QVERIFY2(seen > 0 && seen < creases.size(),
                 qPrintable(QString("%1 of %2").arg(seen).arg(creases.size())));
        QVERIFY(views.development->conditionBadges().size() >= creases.size());
    }
};

DEVSURF_REGISTER_TEST(TstConditionMarks);
#include "tst_condition_marks.moc"
