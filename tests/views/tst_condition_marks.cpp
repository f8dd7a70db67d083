#include "model/document/document.h"
#include "model/document/selection.h"
#include "model/examples.h"
#include "side_by_side_views.h"
#include "test_registry.h"
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

struct Views : devsurf::test::SideBySideViews {
    explicit Views(devsurf::model::Project project)
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
        Views views(std::move(project));
        QVERIFY(views.show());

        const std::map<EdgeId, CreaseCondition> expected{
            {edges.curvedFold, CreaseCondition::CurvedFold},
            {edges.geodesic, CreaseCondition::Geodesic},
            {edges.straight, CreaseCondition::Straight}};
        const QStringList legend{"CF Curved fold", "G Geodesic", "SU Straight when unfolded",
                                 "Smooth ruling", "Sharp ruling"};
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
            QCOMPARE(view->legendEntries(), legend);
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

        // Cleared conditions and a sharp ruling: no badges, no legend entries.
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
            QVERIFY2(view->legendEntries().isEmpty(), qPrintable(view->legendEntries().join(',')));
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
        Views views(std::move(project));
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
