#pragma once

// Internal to views/: includes VTK.

#include "crease_marks.h"
#include "distance_colours.h"
#include "model/document/selection.h"
#include "model/reference_shape.h"
#include "quality_colours.h"
#include "scene_geometry.h"

#include <vtkSmartPointer.h>

#include <memory>
#include <optional>
#include <set>
#include <vector>

class vtkActor;
class vtkCellPicker;
class vtkStaticCellLocator;
class vtkPolyData;
class vtkRenderer;

namespace devsurf::views {

// The VTK side of a view: the actors that draw a list of SurfaceScenes in one renderer, the
// selection highlight, and picking in display coordinates (device pixels, origin bottom left).
class SceneRenderer {
public:
    enum class Mode { Spatial, Development };

    SceneRenderer(Mode mode, vtkRenderer* renderer);
    ~SceneRenderer();

    // Replaces what is drawn. With geometryOnly (the combinatorics are unchanged) the layers
    // whose structure still matches keep their cells and colours and only take new points.
    // The scenes are shared (SceneCache), never copied.
    void setScenes(std::shared_ptr<const SceneSet> scenes, bool geometryOnly);
    const std::vector<SurfaceScene>& scenes() const { return m_set->scenes; }

    void setSelection(const std::set<document::Pick>& picks);
    // The selected picks that are drawn highlighted (those that exist in the scenes).
    const std::set<document::Pick>& highlighted() const { return m_highlighted; }

    // The pinned vertices drawn (red).
    const std::set<document::Pick>& pinnedDrawn() const { return m_pinnedDrawn; }
    // Mountain and valley creases drawn (for the fold legend and tests).
    std::pair<int, int> foldCounts() const {
        return {static_cast<int>(m_mountainLines.size()), static_cast<int>(m_valleyLines.size())};
    }
    // Creases drawn that are not folded (solid, in the crease colour).
    int flatCreaseCount() const { return m_flatCreases; }
    // Redraws the dashes of the folds (foldDashes) if the zoom changed their length on screen
    // by more than a quarter since they were drawn; called before every render. True if it did.
    bool updateFoldDashes();
    // The length in scene units of one unit of the fold dash patterns, as last drawn; and the
    // number of dashes drawn for mountains and for valleys (tests).
    double foldDashUnit() const { return m_dashUnit; }
    std::pair<int, int> foldDashCounts() const;
    // The creases with a condition (drawn as badges by the view's overlay).
    const std::vector<ConditionMark>& conditionMarks() const { return m_conditionMarks; }
    // Rulings between two patches drawn smooth (light) and sharp (dark).
    std::pair<int, int> rulingCounts() const { return m_rulingCounts; }
    // Whether the surface hides a scene point from the camera (3D; never in the development).
    bool isHidden(const model::Vec3& point) const;

    // Patch colours, or a quality measure with its legend (3D view only).
    void setColourBy(ColourBy by);
    const QualityColouring* quality() const { return m_quality.get(); }

    void setShowControlPolygons(bool show);
    void setShowVertices(bool show);
    // The held sheet behind the development (development view); shown by default.
    void setShowSheet(bool show);
    bool showsSheet() const { return m_showSheet; }
    void setTargetPoints(const std::vector<model::Vec3>& points);
    // Points of the reference shapes marked by a lasso (3D only): large magenta points, shown
    // and hidden with the reference shapes.
    void setMarkedPoints(const std::vector<model::Vec3>& points);
    int markedPointCount() const;
    // Lines an edit in progress would add (drawn dashed-bright over everything else).
    void setPreviewLines(const std::vector<std::vector<model::Vec3>>& lines);
    // The project's reference curves (3D only): thin dark lines, never picked.
    void setReferenceCurves(const std::vector<std::vector<model::Vec3>>& curves);
    int referenceCurveCount() const { return m_referenceCurveCount; }
    // The project's reference shapes (3D only): a mesh translucent, a point cloud as small
    // points, never picked. A shape whose storage is the one drawn before (the same points and
    // triangles in memory: commands move shapes, never copy them) keeps its poly data, so an
    // unrelated change does not rebuild millions of points; forgetReferenceShapes() drops
    // that cache when the shapes may have changed unseen.
    // Point clouds are drawn 3 logical pixels wide (3 × devicePixelRatio device pixels).
    void setReferenceShapes(const std::vector<model::ReferenceShape>& shapes,
                            double devicePixelRatio = 1.0);
    void forgetReferenceShapes();
    void setShowReferenceShapes(bool show);
    bool showsReferenceShapes() const { return m_showReferenceShapes; }
    // The shapes drawn: 0 while hidden.
    int referenceShapeCount() const;
    // Colours the points (and mesh vertices) of each drawn shape by its distances (one per
    // point, in the shape's order; null or of another size: the shape's own colour), on the
    // colouring's scale, faded when stale. A null colouring gives every shape its own colour.
    // True if anything drawn changed (a frame is due).
    bool setReferenceColours(const std::vector<const std::vector<double>*>& distances,
                             const DistanceColouring* colouring, bool stale);
    // The colour a point of a drawn shape is drawn in by distance; invalid when the shape is
    // not coloured so.
    QColor referencePointColour(int shape, int point) const;
    // Whether a shown shape is coloured by distance (its legend is drawn).
    bool drawsDistanceColours() const;
    // Boundary loops of held sheets drawn (development view).
    int sheetLoopCount() const { return m_sheetLoops; }

    // Vertex within radius, else edge within radius * 0.6, else face under the point; in 3D
    // vertices and edges hidden behind the surface are not picked.
    std::optional<document::Pick> pick(double displayX, double displayY, double radius) const;
    // The patch drawn at a display position, if any (nothing hides it).
    std::optional<document::Pick> faceAt(double displayX, double displayY) const;
    // The surface point under display coordinates and its patch (3D only).
    std::optional<model::Vec3> surfacePoint(double displayX, double displayY,
                                            std::optional<document::Pick>* face) const {
        return surfaceHit(displayX, displayY, face);
    }
    // Where the ray through a display point meets a plane (scene coordinates); nullopt if the
    // ray runs parallel to it.
    std::optional<model::Vec3> displayToPlane(double displayX, double displayY,
                                              const model::Vec3& planePoint,
                                              const model::Vec3& planeNormal) const;
    // Scene point → display coordinates {x, y, depth}.
    model::Vec3 toDisplay(const model::Vec3& point) const;
    // Unit vector along which the camera looks.
    model::Vec3 viewDirection() const;
    const model::Vec3* vertexPosition(int surface, model::VertexId vertex) const;

    // Fits the camera to the scenes, keeping its direction (the development view always looks
    // straight down at the plane): everything drawn (fitPoints(), projected) lies inside the
    // viewport by kFitMargin device pixels (kFitAir of its size if more), so that the markers drawn
    // at the outermost vertices (pins, 13 px) show whole, and left of the quality legend when it is
    // shown.
    void resetCamera();
    static constexpr double kFitMargin = 16.0;
    static constexpr double kFitAir = 0.04; // of the viewport's smaller side
    // The 3D view: looks along direction with the given up vector, then fits. Ignored by the
    // development view.
    void lookAlong(const model::Vec3& direction, const model::Vec3& up);
    // The 3D view's starting direction: from the front right and above, z up.
    static model::Vec3 defaultDirection();
    // Device pixels per scene unit (mm) at the camera's focal point.
    double pixelsPerUnit() const;

private:
    // Zooms and pans the camera so that the projected corners of the visible props' bounds
    // fill the viewport less its margins (resetCamera).
    void fitBoundsToViewport();
    // What the fit keeps in view: the drawn surfaces' points (at most about kFitPoints of
    // them), the control points when shown, and the corners of the reference curves' bounds.
    std::vector<model::Vec3> fitPoints() const;
    static constexpr std::size_t kFitPoints = 20000;
    struct Layer;
    Layer& addLayer();
    void rebuildHighlight();
    std::optional<model::Vec3> surfaceHit(double displayX, double displayY,
                                          std::optional<document::Pick>* face) const;

    Mode m_mode;
    vtkSmartPointer<vtkRenderer> m_renderer;
    vtkSmartPointer<vtkCellPicker> m_picker;
    // The faces' cells binned for picking: a pick (one per badge and label in every overlay
    // update) costs a few cells instead of all of them. Built on the first pick after a change.
    vtkSmartPointer<vtkStaticCellLocator> m_locator;
    mutable bool m_locatorStale = true;
    std::vector<std::unique_ptr<Layer>> m_layers;
    Layer* m_faces = nullptr;
    Layer* m_rulingEdges = nullptr;
    Layer* m_smoothRulings = nullptr;
    std::pair<int, int> m_rulingCounts; // smooth and sharp rulings between two patches
    std::vector<ConditionMark> m_conditionMarks;
    Layer* m_splineEdges = nullptr;
    Layer* m_creases = nullptr;
    Layer* m_mountains = nullptr;
    Layer* m_valleys = nullptr;
    int m_flatCreases = 0;
    std::vector<std::vector<model::Vec3>> m_mountainLines; // the creases drawn, undashed
    std::vector<std::vector<model::Vec3>> m_valleyLines;
    double m_dashUnit = 0.0; // scene units per dash unit, 0 before the first drawing
    // The dash unit for the current camera (kFoldDashUnitPixels on screen, at least 1/2000 of
    // the scene's size so that a close zoom cannot multiply the dashes without bound).
    double currentDashUnit() const;
    void drawFolds();
    Layer* m_rulings = nullptr;
    Layer* m_outline = nullptr;
    Layer* m_sheet = nullptr;
    int m_sheetLoops = 0;
    bool m_showSheet = true;
    Layer* m_overlapOutline = nullptr; // development: pieces that overlap, in red
    Layer* m_controlPolygons = nullptr;
    Layer* m_controlPoints = nullptr;
    Layer* m_vertices = nullptr;
    Layer* m_pinned = nullptr;
    Layer* m_target = nullptr;
    Layer* m_marked = nullptr;
    void showMarkedPoints(bool show);
    Layer* m_selectedEdges = nullptr;
    Layer* m_selectedVertices = nullptr;
    Layer* m_preview = nullptr;
    Layer* m_referenceCurves = nullptr;
    int m_referenceCurveCount = 0;
    struct ShapeActor;
    // One actor per shape drawn; never removed from the renderer (that needs the GL context),
    // an unused one is hidden and emptied.
    std::vector<std::unique_ptr<ShapeActor>> m_shapeActors;
    int m_shapesDrawn = 0;
    std::vector<model::Vec3> m_shapeCorners; // of each drawn shape's bounding box (the fit)
    bool m_showReferenceShapes = true;

    std::unique_ptr<QualityColouring> m_quality; // 3D only
    std::shared_ptr<const SceneSet> m_set = std::make_shared<const SceneSet>();
    std::vector<std::pair<int, model::FaceId>> m_cellFace; // faces layer cell -> (surface, face)
    std::set<document::Pick> m_selection;
    std::set<document::Pick> m_highlighted;
    std::set<document::Pick> m_pinnedDrawn;
    double m_sceneSize = 1.0;
    bool m_controlPointsShown = false;
    std::vector<model::Vec3> m_referenceCorners; // of the reference curves' bounding box
};

} // namespace devsurf::views
