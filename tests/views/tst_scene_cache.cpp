#include "model/document/commands/move_vertices_command.h"
#include "model/document/commands/pin_vertices_command.h"
#include "model/examples.h"
#include "side_by_side_views.h"
#include "test_registry.h"
#include "views/scene_cache.h"
#include "views/scene_geometry.h"

#include <QSignalSpy>
#include <QTest>
#include <QUndoStack>

#include <memory>
#include <optional>

using devsurf::document::Document;
using devsurf::views::SceneCache;
using devsurf::views::SurfaceScene;

namespace {

// Two surfaces: an annulus and a sheet.
devsurf::model::Project twoSurfaces() {
    devsurf::model::Project project = devsurf::model::makeExample("annulus", 3);
    project.addSurface(devsurf::model::makeExample("sheet", 2).surfaces.front());
    return project;
}

bool sameEdges(const SurfaceScene& a, const SurfaceScene& b) {
    if (a.edges.size() != b.edges.size()) {
        return false;
    }
    for (std::size_t i = 0; i < a.edges.size(); ++i) {
        const auto& x = a.edges[i];
        const auto& y = b.edges[i];
        if (x.id != y.id || x.spline != y.spline || x.crease != y.crease || x.fold != y.fold ||
            x.condition != y.condition || x.smooth != y.smooth || x.boundary != y.boundary ||
            x.points != y.points) {
            return false;
        }
    }
    return true;
}

bool sameScene(const SurfaceScene& a, const SurfaceScene& b) {
    return a.surface == b.surface && a.points == b.points && a.normals == b.normals &&
           a.pointOrigin == b.pointOrigin && a.polygons == b.polygons &&
           a.polygonFace == b.polygonFace && sameEdges(a, b) && a.rulings == b.rulings &&
           a.outline == b.outline && a.controlPolygons == b.controlPolygons &&
           a.controlPoints == b.controlPoints && a.vertices == b.vertices && a.pinned == b.pinned &&
           a.seamVertices == b.seamVertices && a.overlapOutline == b.overlapOutline;
}

bool sameScenes(const std::vector<SurfaceScene>& a, const std::vector<SurfaceScene>& b) {
    if (a.size() != b.size()) {
        return false;
    }
    for (std::size_t i = 0; i < a.size(); ++i) {
        if (!sameScene(a[i], b[i])) {
            return false;
        }
    }
    return true;
}

} // namespace

// The scenes of the 3D and the development view are built once per surface revision, shared
// by the views, and only for the surface that changed.
class TstSceneCache : public QObject {
    Q_OBJECT

    void push(Document& document, devsurf::document::CommandOrError edit) {
        QVERIFY(!edit.isRefused());
        document.undoStack()->push(edit.takeCommand().release());
    }

    // Equal to what the views built without the cache.
    void compareWithUncached(Document& document) {
        SceneCache* cache = SceneCache::of(&document);
        std::vector<SurfaceScene> spatial;
        for (int i = 0; i < document.surfaceCount(); ++i) {
            spatial.push_back(devsurf::views::buildSpatialScene(document.surface(i), i));
        }
        QVERIFY(sameScenes(cache->spatialScenes()->scenes, spatial));
        const auto development = devsurf::views::buildDevelopmentScenes(document.project());
        QVERIFY(sameScenes(cache->developmentScenes()->scenes, development.scenes));
        QCOMPARE(cache->developmentScenes()->invalidSurfaces, development.invalidSurfaces);
    }

private slots:
    void theDocumentSaysWhichSurfaceChanged() {
        Document document;
        document.resetProject(twoSurfaces());
        const quint64 reset = document.revision();
        QCOMPARE(document.surfaceRevision(0), reset);
        QCOMPARE(document.surfaceRevision(1), reset);
        QCOMPARE(document.changedSurface(), -1);
        int seen = -2;
        connect(&document, &Document::changed, this, [&] { seen = document.changedSurface(); });
        push(document,
             devsurf::document::MoveVerticesCommand::createTranslation(
                 document, 1, {document.surface(1).vertices().begin()->first}, {0.0, 0.0, 1.0}));
        QCOMPARE(seen, 1);
        QCOMPARE(document.surfaceRevision(0), reset);
        QCOMPARE(document.surfaceRevision(1), document.revision());
        document.undoStack()->undo();
        QCOMPARE(seen, 1);
        QCOMPARE(document.surfaceRevision(0), reset);
        QCOMPARE(document.surfaceRevision(1), document.revision());
        document.resetProject(twoSurfaces());
        QCOMPARE(document.surfaceRevision(0), document.revision());
        QCOMPARE(document.surfaceRevision(1), document.revision());
    }

    void bothViewsShareOneBuildPerSurfaceRevision() {
        devsurf::test::SideBySideViews views(twoSurfaces(), 800, 400);
        QVERIFY(views.show());
        SceneCache* cache = SceneCache::of(&views.document);
        // Both views of the document use the same cache, and each surface was built once.
        QCOMPARE(cache->spatialBuilds(), 2);
        QCOMPARE(cache->developmentBuilds(), 2);
        // A second 3D view of the same document builds nothing.
        devsurf::views::SurfaceView another(&views.document, &views.selection);
        QCOMPARE(cache->spatialBuilds(), 2);
        QCOMPARE(cache->spatialScenes(), cache->spatialScenes());
        compareWithUncached(views.document);
    }

    void anEditRebuildsOnlyTheSurfaceItChanged() {
        devsurf::test::SideBySideViews views(twoSurfaces(), 800, 400);
        QVERIFY(views.show());
        devsurf::views::SurfaceView another(&views.document, &views.selection);
        SceneCache* cache = SceneCache::of(&views.document);
        QCOMPARE(cache->spatialBuilds(), 2);
        QCOMPARE(cache->developmentBuilds(), 2);
        const int layouts = cache->layouts();

        // Geometry of the first surface: the first surface once, for the three views.
        const auto vertex = views.document.surface(0).vertices().begin()->first;
        push(views.document, devsurf::document::MoveVerticesCommand::createTranslation(
                                 views.document, 0, {vertex}, {0.0, 0.0, 2.0}));
        QCOMPARE(cache->spatialBuilds(), 3);
        QCOMPARE(cache->developmentBuilds(), 3);
        QCOMPARE(cache->layouts(), layouts + 1);
        QCOMPARE(*views.spatial->vertexScenePoint(0, vertex),
                 views.document.surface(0).position(vertex));
        QCOMPARE(*another.vertexScenePoint(0, vertex), views.document.surface(0).position(vertex));
        compareWithUncached(views.document);

        // Pins of the second surface: the second surface only.
        push(views.document,
             devsurf::document::PinVerticesCommand::create(
                 views.document, 1, {views.document.surface(1).vertices().begin()->first}, true));
        QCOMPARE(cache->spatialBuilds(), 4);
        QCOMPARE(cache->developmentBuilds(), 4);
        QCOMPARE(views.development->pinnedPicks().size(), std::size_t(1));
        compareWithUncached(views.document);

        // Undo: the changed surface again, and nothing else.
        views.document.undoStack()->undo();
        QCOMPARE(cache->spatialBuilds(), 5);
        QCOMPARE(cache->developmentBuilds(), 5);
        QVERIFY(views.development->pinnedPicks().empty());
        compareWithUncached(views.document);

        // A new project: every surface.
        views.document.resetProject(twoSurfaces());
        QCOMPARE(cache->spatialBuilds(), 7);
        QCOMPARE(cache->developmentBuilds(), 7);
        compareWithUncached(views.document);
    }

    void aHiddenDevelopmentViewCatchesUpWhenShown() {
        devsurf::test::SideBySideViews views(twoSurfaces(), 800, 400);
        QVERIFY(views.show());
        SceneCache* cache = SceneCache::of(&views.document);
        views.development->hide();
        const auto vertex = views.document.surface(1).vertices().begin()->first;
        push(views.document,
             devsurf::document::PinVerticesCommand::create(views.document, 1, {vertex}, true));
        QCOMPARE(cache->spatialBuilds(), 3);
        QCOMPARE(cache->developmentBuilds(), 2); // not developed while nobody draws it
        views.development->show();
        QCOMPARE(cache->developmentBuilds(), 3);
        const std::set<devsurf::document::Pick> pinned{
            {devsurf::document::Pick::Kind::Vertex, 1, vertex}};
        QCOMPARE(views.development->pinnedPicks(), pinned);
    }

    void aDragIsDevelopedInTheBackground() {
        devsurf::test::SideBySideViews views(twoSurfaces(), 800, 400);
        QVERIFY(views.show());
        SceneCache* cache = SceneCache::of(&views.document);
        QSignalSpy ready(cache, &SceneCache::developmentReady);
        const auto vertex = views.document.surface(0).vertices().begin()->first;
        const int commands = views.document.undoStack()->count();
        // Moves of one vertex merge into one undo step, as the solver results of a drag do.
        for (int i = 1; i <= 6; ++i) {
            push(views.document, devsurf::document::MoveVerticesCommand::createTranslation(
                                     views.document, 0, {vertex}, {0.0, 0.0, 0.5 * i}));
        }
        QCOMPARE(views.document.undoStack()->count(), commands + 1);
        QCOMPARE(cache->spatialBuilds(), 2 + 6); // the 3D view is always current
        while (cache->developmentPending()) {
            QVERIFY(ready.wait(10000));
        }
        // Not more developments than changes, none of the other surface, and in the end the
        // development view shows the latest revision exactly.
        QVERIFY(cache->developmentBuilds() <= 2 + 6);
        QVERIFY(!ready.isEmpty());
        compareWithUncached(views.document);
        const auto uncached = devsurf::views::buildDevelopmentScenes(views.document.project());
        QCOMPARE(views.development->vertexScenePoint(0, vertex),
                 std::optional<devsurf::model::Vec3>(uncached.scenes.front().vertices.at(vertex)));
        QCOMPARE(views.development->problem(), QString());
    }

    // Issue 46, 5: edits, undo and redo of a large surface are sampled and developed in the
    // background, so that undo bursts keep the window answering; both views end at the state
    // undone to.
    void largeSurfacesAreDevelopedInTheBackground() {
        devsurf::test::SideBySideViews views(devsurf::model::makeExample("annulus", 30), 800, 400);
        QVERIFY(views.show());
        SceneCache* cache = SceneCache::of(&views.document);
        QSignalSpy ready(cache, &SceneCache::developmentReady);
        QSignalSpy sampled(cache, &SceneCache::spatialReady);
        const auto vertex = views.document.surface(0).vertices().begin()->first;
        push(views.document, devsurf::document::MoveVerticesCommand::createTranslation(
                                 views.document, 0, {vertex}, {0.0, 0.0, 2.0}));
        for (const int step : {0, 1, 2}) { // the push, its undo, its redo
            if (step == 1) {
                views.document.undoStack()->undo();
            } else if (step == 2) {
                views.document.undoStack()->redo();
            }
            const int builds = cache->spatialBuilds();
            QVERIFY(cache->developmentPending()); // not developed on the GUI thread
            QVERIFY(cache->spatialPending());     // nor sampled there
            QCOMPARE(cache->spatialBuilds(), builds);
            while (cache->developmentPending()) {
                QVERIFY(ready.wait(30000));
            }
            while (cache->spatialPending()) {
                QVERIFY(sampled.wait(30000));
            }
            const auto surface = views.document.surface(0);
            const devsurf::views::SurfaceScene scene =
                devsurf::views::buildSpatialScene(surface, 0);
            QCOMPARE(views.spatial->vertexScenePoint(0, vertex),
                     std::optional<devsurf::model::Vec3>(scene.vertices.at(vertex)));
            QCOMPARE(cache->spatialScenes()->scenes.front().points, scene.points);
            const auto uncached = devsurf::views::buildDevelopmentScenes(views.document.project());
            QCOMPARE(
                views.development->vertexScenePoint(0, vertex),
                std::optional<devsurf::model::Vec3>(uncached.scenes.front().vertices.at(vertex)));
        }
    }
};

DEVSURF_REGISTER_TEST(TstSceneCache);
#include "tst_scene_cache.moc"
