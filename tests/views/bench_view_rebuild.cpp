// Not a test: times what one geometry change of a large design costs the two views on the GUI
// thread (the rebuild of both, taking in what was built in the background, then one render of
// each), and the stages of that rebuild on their own.
// Usage: bench_view_rebuild [ANNULUS_SIZE] [MOVES]  (run under a display, e.g. xvfb-run).

#include "model/document/commands/move_vertices_command.h"
#include "model/examples.h"
#include "side_by_side_views.h"
#include "solver/quality/quality_measures.h"
#include "views/scene_cache.h"
#include "views/scene_geometry.h"
#include "views/vtk_opengl_widget.h"

#include <QApplication>
#include <QElapsedTimer>
#include <QSurfaceFormat>
#include <QUndoStack>

#include <algorithm>
#include <cstdio>
#include <functional>
#include <vector>

using namespace devsurf;

namespace {

double median(std::vector<double> values) {
    std::sort(values.begin(), values.end());
    return values.empty() ? 0.0 : values[values.size() / 2];
}

double timeMs(const std::function<void()>& run) {
    QElapsedTimer clock;
    clock.start();
    run();
    return static_cast<double>(clock.nsecsElapsed()) / 1e6;
}

} // namespace

int main(int argc, char** argv) {
    QSurfaceFormat::setDefaultFormat(views::VtkOpenGLWidget::defaultFormat());
    QApplication app(argc, argv);
    const int size = argc > 1 ? std::atoi(argv[1]) : 13;
    const int moves = argc > 2 ? std::atoi(argv[2]) : 10;

    // The annulus with every crease a curved fold, so that the views draw a badge at each.
    model::Project project = model::makeExample("annulus", size);
    model::CompositeSurface& surface = project.surfaces.front();
    for (const auto& [id, record] : surface.edges()) {
        if (record.isSpline() && surface.facesOfEdge(id).size() == 2) {
            surface.setCreaseCondition(id, model::CreaseCondition::CurvedFold);
        }
    }

    std::vector<double> spatial, development;
    for (int m = 0; m < moves; ++m) {
        spatial.push_back(timeMs([&] { views::buildSpatialScene(surface, 0); }));
        development.push_back(timeMs([&] { views::buildDevelopmentScenes(project); }));
    }
    std::vector<double> validate, develop, layout, quality;
    for (int m = 0; m < moves; ++m) {
        quality.push_back(
            timeMs([&] { solver::developabilityOfPatches(surface, views::kSamplesPerInterval); }));
        validate.push_back(timeMs([&] { surface.validate(); }));
        views::SurfaceDevelopment developed;
        develop.push_back(timeMs([&] { developed = views::developSurfaceForView(surface, 0); }));
        layout.push_back(timeMs([&] { views::layOutDevelopments(project, {&developed}); }));
    }
    std::printf("stage buildSpatialScene      %8.2f ms\n", median(spatial));
    std::printf("  of which patch developability %5.2f ms\n", median(quality));
    std::printf("stage buildDevelopmentScenes %8.2f ms\n", median(development));
    std::printf("  of which validate()        %8.2f ms\n", median(validate));
    std::printf("  develop one surface        %8.2f ms (validate included)\n", median(develop));
    std::printf("  lay out, scenes            %8.2f ms\n", median(layout));

    test::SideBySideViews views(project, 1600, 800);
    if (!views.show()) {
        std::fprintf(stderr, "no display\n");
        return 1;
    }
    const model::VertexId vertex = views.surface().vertices().begin()->first;
    views::SceneCache* cache = views::SceneCache::of(&views.document);
    const auto pending = [cache] { return cache->developmentPending() || cache->spatialPending(); };
    std::vector<double> rebuild, results, work, render3d, render2d, total;
    for (int m = 0; m < moves; ++m) {
        const double step = (m % 2 == 0 ? 1.0 : -1.0) * 0.5;
        auto edit = document::MoveVerticesCommand::createTranslation(views.document, 0, {vertex},
                                                                     {0.0, 0.0, step});
        QUndoCommand* command = edit.takeCommand().release();
        // An undoable geometry change as an undo or redo makes it: the push and the views'
        // rebuilds on the GUI thread.
        const double r = timeMs([&] { views.document.undoStack()->push(command); });
        // The background jobs run (not GUI time); then their results are taken in, as the
        // event loop would, without the paint events (timed below).
        double e = 0.0;
        while (pending()) {
            cache->waitForBackgroundJobs(60000);
            e += timeMs([] { QCoreApplication::sendPostedEvents(nullptr, QEvent::MetaCall); });
        }
        const double a = timeMs([&] { views.spatial->glWidget()->repaint(); });
        const double b = timeMs([&] { views.development->glWidget()->repaint(); });
        QCoreApplication::processEvents();
        rebuild.push_back(r);
        results.push_back(e);
        work.push_back(r + e);
        render3d.push_back(a);
        render2d.push_back(b);
        total.push_back(r + e + a + b);
    }
    std::vector<double> still3d, still2d;
    for (int m = 0; m < moves; ++m) {
        // A render of an unchanged scene (and the read-back of the frame).
        views.spatial->glWidget()->requestRender();
        still3d.push_back(timeMs([&] { views.spatial->grabImage(); }));
        views.development->glWidget()->requestRender();
        still2d.push_back(timeMs([&] { views.development->grabImage(); }));
    }
    std::printf("render 3D alone (grab)       %8.2f ms\n", median(still3d));
    std::printf("render 2D alone (grab)       %8.2f ms\n", median(still2d));
    std::printf("push + rebuild (both views)  %8.2f ms\n", median(rebuild));
    std::printf("background results taken in %8.2f ms\n", median(results));
    std::printf("GUI thread, without renders  %8.2f ms\n", median(work));
    std::printf("render + overlay 3D          %8.2f ms\n", median(render3d));
    std::printf("render + overlay development %8.2f ms\n", median(render2d));
    std::printf("total per geometry change    %8.2f ms\n", median(total));
    return 0;
}
