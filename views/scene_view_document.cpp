// How a view follows its document: which changes rebuild its scene, on the GUI thread or in
// the background (SceneCache), and the reference curves and shapes drawn with it.

#include "scene_view.h"

#include "scene_cache.h"
#include "scene_view_private.h"

#include <QUndoStack>

#include <array>
#include <set>

namespace devsurf::views {

using document::Pick;

namespace {

// Faces of a surface from which its 3D scene and its development after a change are always
// built in the background (an annulus of size 30 has 1,200).
constexpr std::size_t kBackgroundDevelopmentFaces = 500;

} // namespace

void SceneView::onDocumentChanged(unsigned changes) {
    // resetProject() announces itself twice (projectReset, then changed): build once.
    if (d->document == nullptr || d->document->revision() == d->builtRevision) {
        return;
    }
    if (!isVisible() && window()->isVisible()) {
        d->staleWhileHidden = true;
        return;
    }
    const unsigned references = static_cast<unsigned>(document::Change::ReferenceCurves) |
                                static_cast<unsigned>(document::Change::ReferenceShapes);
    if (changes != 0 && (changes & ~references) == 0 && !d->scene->scenes().empty()) {
        // Only reference curves or shapes changed: the surfaces' actors stay as they are.
        d->builtRevision = d->document->revision();
        if ((changes & static_cast<unsigned>(document::Change::ReferenceCurves)) != 0) {
            showReferenceCurves();
        }
        if ((changes & static_cast<unsigned>(document::Change::ReferenceShapes)) != 0) {
            showReferenceShapes();
        }
        rerender();
        return;
    }
    // References changed with something else (a new document): built with everything.
    const unsigned structural = static_cast<unsigned>(document::Change::Labels) |
                                static_cast<unsigned>(document::Change::Topology) | references;
    const bool firstBuild = d->scene->scenes().empty();
    // A run of geometry changes of one surface that merge into one undo step (a drag: a solver
    // result per mouse move) is developed in the background, so that the GUI thread only
    // resamples it for the 3D view; the development view follows as developments arrive.
    const QUndoStack* stack = d->document->undoStack();
    const std::array<int, 3> state = {stack->count(), stack->index(),
                                      d->document->changedSurface()};
    const bool geometryOfOne =
        changes == static_cast<unsigned>(document::Change::Geometry) && state[2] >= 0;
    const bool continued = geometryOfOne && state == d->lastChange;
    // Any such change of a large surface (an edit, an undo, a redo) is sampled and developed
    // in the background: building either scene on the GUI thread would stop the window
    // answering.
    const bool large = geometryOfOne &&
                       d->document->surface(state[2]).faces().size() >= kBackgroundDevelopmentFaces;
    d->lastChange = state;
    const bool development = d->kind == Kind::Development;
    if ((large || (development && continued)) && !firstBuild && d->problem.isEmpty()) {
        d->builtRevision = d->document->revision();
        d->followBackground = true;
        SceneCache* cache = SceneCache::of(d->document);
        if (development) {
            cache->developInBackground(state[2]);
        } else {
            cache->sampleInBackground(state[2]);
        }
        return;
    }
    d->followBackground = false;
    rebuild((changes & structural) == 0);
    if (firstBuild) {
        fitAll();
    }
}

void SceneView::showEvent(QShowEvent* event) {
    QWidget::showEvent(event);
    if (d->staleWhileHidden) {
        d->staleWhileHidden = false;
        if (d->document != nullptr && d->document->revision() != d->builtRevision) {
            // Shapes may have been freed and others stored where they were meanwhile.
            d->scene->forgetReferenceShapes();
            rebuild(false);
        }
    }
}

void SceneView::onProjectReset() {
    d->scene->forgetReferenceShapes();
    rebuild(false);
    fitAll();
}

void SceneView::onSelectionChanged() {
    d->scene->setSelection(d->selection ? d->selection->picks() : std::set<Pick>{});
    rerender();
}

void SceneView::rebuild(bool geometryOnly) {
    d->problem.clear();
    std::shared_ptr<const SceneSet> scenes;
    if (SceneCache* cache = SceneCache::of(d->document)) {
        d->builtRevision = d->document->revision();
        // Shared with the other views of the document: built once per surface revision.
        if (d->kind == Kind::Spatial) {
            scenes = d->followBackground ? cache->latestSpatialScenes() : cache->spatialScenes();
        } else {
            scenes =
                d->followBackground ? cache->latestDevelopmentScenes() : cache->developmentScenes();
        }
        for (int i : scenes->invalidSurfaces) {
            // An invalid surface (e.g. mid-way through an edit) is skipped, not fatal.
            d->problem = tr("Surface %1 is not valid and is not shown.").arg(i + 1);
            geometryOnly = false;
        }
    }
    d->anchors.clear();
    d->anchorsValid = false;
    d->scene->setScenes(std::move(scenes), geometryOnly);
    d->scene->setSelection(d->selection ? d->selection->picks() : std::set<Pick>{});
    if (!geometryOnly) {
        showReferenceCurves(); // not again for every move of a drag: the curves did not change
        showReferenceShapes(); // rebuilt only for shapes not drawn before (SceneRenderer)
    }
    rerender();
}

void SceneView::showReferenceCurves() {
    std::vector<std::vector<model::Vec3>> curves;
    if (d->kind == Kind::Spatial && d->document != nullptr) {
        for (const model::ReferenceCurve& curve : d->document->project().referenceCurves) {
            curves.push_back(curve.points);
        }
    }
    d->scene->setReferenceCurves(curves);
}

int SceneView::referenceCurvesDrawn() const {
    return d->scene->referenceCurveCount();
}

void SceneView::showReferenceShapes() {
    static const std::vector<model::ReferenceShape> none;
    d->scene->setReferenceShapes(d->kind == Kind::Spatial && d->document != nullptr
                                     ? d->document->project().referenceShapes
                                     : none,
                                 d->gl->effectiveDevicePixelRatio());
    showReferenceDistances(); // shapes built anew take their colours again
}

int SceneView::referenceShapesDrawn() const {
    return d->scene->referenceShapeCount();
}

bool SceneView::showsReferenceShapes() const {
    return d->scene->showsReferenceShapes();
}

void SceneView::setShowReferenceShapes(bool show) {
    d->scene->setShowReferenceShapes(show);
    rerender();
    if (d->byDistance) {
        setColourReferenceByDistance(true); // measures only while the shapes are shown
    }
}

int SceneView::sheetLoopsDrawn() const {
    return d->scene->sheetLoopCount();
}

} // namespace devsurf::views
