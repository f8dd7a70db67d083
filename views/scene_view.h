#pragma once

#include "colour_by.h"
#include "distance_legend.h"
#include "model/document/selection.h"
#include "model/ids.h"
#include "model/reference/lasso_marking.h"
#include "model/vec3.h"
#include "view_overlay.h"

#include <QColor>
#include <QImage>
#include <QPoint>
#include <QPointF>
#include <QRect>
#include <QString>
#include <QStringList>
#include <QWidget>

#include <memory>
#include <optional>
#include <set>

namespace devsurf::document {
class Document;
} // namespace devsurf::document

namespace devsurf::views {

class VtkOpenGLWidget;

// What the 3D view and the development view share: a VtkOpenGLWidget showing the document's
// surfaces, updated from Document::changed / projectReset and Selection::selectionChanged, and
// picking that edits the Selection (never the model). Plain click selects (empty space
// clears), Shift-click toggles, Ctrl-drag selects the vertices inside a rectangle
// (Ctrl+Shift-drag adds them).
//
// Widget coordinates below are those of glWidget() (logical pixels, origin top left).
class SceneView : public QWidget {
    Q_OBJECT
public:
    ~SceneView() override;

    document::Document* document() const;
    document::Selection* selection() const;
    VtkOpenGLWidget* glWidget() const;

    // The entity under a widget position: a vertex (within a few pixels), else an edge, else a
    // face; nothing over empty space.
    std::optional<document::Pick> pickAt(const QPoint& widgetPos) const;
    // Where a point of the scene is drawn: world coordinates in the 3D view, the laid-out
    // development plane (z = 0) in the development view.
    QPoint projectToWidget(const model::Vec3& scenePoint) const;
    // Where a coarse vertex of a surface is drawn; (-1, -1) if the view shows no such vertex.
    QPoint projectVertexToWidget(int surface, model::VertexId vertex) const;
    // The scene point a coarse vertex is drawn at, if it is shown.
    std::optional<model::Vec3> vertexScenePoint(int surface, model::VertexId vertex) const;

    // The unit vector along which the camera looks (scene coordinates). The 3D view starts
    // looking from the front right and above (z up); the development view looks down -z.
    model::Vec3 viewDirection() const;

    // The rendered image (grabFramebuffer of the GL widget).
    QImage grabImage();
    // The selected entities this view currently draws highlighted.
    std::set<document::Pick> highlightedPicks() const;
    // The pinned vertices this view currently draws (red).
    std::set<document::Pick> pinnedPicks() const;
    // Where the line of sight through a widget position meets the plane through planePoint
    // with the given normal (scene coordinates); nullopt if it runs parallel to the plane.
    std::optional<model::Vec3> widgetToPlane(const QPoint& widgetPos, const model::Vec3& planePoint,
                                             const model::Vec3& planeNormal) const;
    // A one-sentence problem with the current project that this view could not draw (e.g. an
    // invalid surface), or empty.
    QString problem() const;

    // Standard directions of the 3D view (z up; front looks along +y). The development view
    // always looks straight down at its plane and only fits.
    enum class StandardView { Isometric, Front, Top, Right, Rear, Bottom, Left };
    void setStandardView(StandardView view);

    // The scale bar drawn in the lower right corner: its length in mm, on screen (logical
    // pixels) and its text ("50 mm"); 0 and empty before the first render. In the 3D view it
    // holds at the point the camera turns about.
    double scaleBarLength() const;
    double scaleBarPixels() const;
    QString scaleBarText() const;
    // The point of a surface under a widget position and its patch (3D view: the surface
    // hit; the development view: none).
    std::optional<std::pair<model::Vec3, document::Pick>>
    surfacePointAt(const QPoint& widgetPos) const;
    // A measurement drawn over the view: a line through the scene points, with its text at the
    // last one (none when empty).
    void setMeasurement(const std::vector<model::Vec3>& points, const QString& text);
    std::vector<model::Vec3> measurementPoints() const;
    // The camera as a lasso drawn in widget coordinates needs it (model::reference::
    // pointsInLasso): scene point → widget position, and where the camera looks from.
    model::reference::LassoCamera lassoCamera() const;
    // A lasso being drawn over the view (widget coordinates; empty: none).
    void setLasso(const std::vector<QPointF>& points);
    std::vector<QPointF> lasso() const;
    // Points of the reference shapes marked with the lasso, drawn magenta and larger (3D view;
    // hidden with the reference shapes), and how many are drawn.
    void setMarkedPoints(const std::vector<model::Vec3>& points);
    int markedPointsDrawn() const;
    // The verdict of the design's last solve written in the upper right corner (empty: none),
    // and where it is drawn (widget coordinates of glWidget()).
    QString verdictText() const;
    QRect verdictRect() const;
    // Mountain and valley creases drawn, and whether the fold legend shows each.
    std::pair<int, int> foldsDrawn() const;
    std::pair<bool, bool> foldLegend() const;
    // The dashes drawn for the mountain and the valley folds, and the length of one unit of
    // their patterns in scene units (mm) as drawn.
    std::pair<int, int> foldDashesDrawn() const;
    double foldDashUnit() const;
    // The badges drawn at the creases that carry a condition ("CF", "G", "SU"), those in view
    // (in 3D not where the surface hides them), at widget positions.
    std::vector<ViewOverlay::Badge> conditionBadges() const;
    // Rulings between two patches drawn smooth (light) and sharp (dark).
    std::pair<int, int> rulingsDrawn() const;
    // The legend's entries, top to bottom: "Mountain fold", "CF Curved fold", "Smooth ruling"…
    QStringList legendEntries() const;
    // What the legend shows (legendEntries() is its wording).
    ViewOverlay::LegendContents legendContents() const;
    // What the overlay paints over the rendering (legend, badges, labels, scale bar).
    QImage grabOverlay() const;
    // The 3D view draws an orientation triad (x red, y green, z blue) in its lower left.
    bool hasOrientationTriad() const;
    bool showPatchLabels() const;
    // The patch numbers drawn (the visible ones), in the order of the patches.
    QStringList patchLabelTexts() const;
    // The 3D view colours its surfaces by patch (the default) or by a quality measure on a
    // logarithmic scale with a legend; the development view always shows patches.
    ColourBy colourBy() const;
    // Where the quality legend is drawn (widget coordinates); empty when colouring by patch.
    // View ▸ Fit keeps the design left of it.
    QRect legendRect() const;
    // The tolerance the legend marks (below it: green, "developable"); 0 by patch. Its
    // words at the mark, and the colour a value is drawn in (invalid by patch).
    double legendTolerance() const;
    QString legendToleranceLabel() const;
    QColor legendColour(double value) const;
    // The legend's title (empty when colouring by patch) and its range.
    QString legendTitle() const;
    std::pair<double, double> legendRange() const;
    // The value the colouring gives a patch (a face pick): the largest over its polygons (the
    // Solver panel's value of the patch for developability), NaN when colouring by patch.
    double legendValue(const document::Pick& face) const;
    // The number of preview lines shown.
    int previewLineCount() const;
    // The reference curves drawn (3D view: the project's; the development view: none).
    int referenceCurvesDrawn() const;
    // The reference shapes drawn (3D view: the project's while shown; the development view:
    // none).
    int referenceShapesDrawn() const;
    bool showsReferenceShapes() const;
    // Boundary loops of held sheets drawn behind the development (development view; 0 in 3D).
    int sheetLoopsDrawn() const;

    // The colour map of the reference shapes by their distance to the design (3D view, View ▸
    // Colour Reference by Distance), measured in the background (ReferenceDistances):
    // Hidden when off or with nothing to measure; Measuring before the first result (no
    // colours); Stale while the design changed since the colours shown were measured (they
    // are drawn faded and the legend says it updates); Current.
    enum class DistanceMap { Hidden, Measuring, Stale, Current };
    DistanceMap distanceMap() const;
    bool coloursReferenceByDistance() const;
    // The legend's scale in mm (0 to its top) and the coverage tolerance it marks; zeros
    // without colours.
    std::pair<double, double> distanceLegendRange() const;
    double distanceLegendTolerance() const;
    // Where the legend is drawn (widget coordinates of glWidget()); empty without one.
    QRect distanceLegendRect() const;
    // The colour a point of a reference shape is drawn in by distance (invalid when not), and
    // the colour the scale gives a distance in mm (invalid without colours).
    QColor referencePointColour(int shape, int point) const;
    QColor distanceColour(double millimetres) const;

public slots:
    void fitAll();
    // The starting camera (3D: from the front right and above), fitted to the design.
    void resetView();
    void setShowPatchLabels(bool show);
    // Writes a solve's verdict in the upper right corner in `colour` (empty text: none).
    void setVerdict(const QString& text, const QColor& colour);
    void setColourBy(devsurf::views::ColourBy by);
    // Shows the lines an edit would add before it is made (3D scene coordinates; the
    // development view ignores them). An empty list removes the preview.
    void setPreviewLines(const std::vector<std::vector<model::Vec3>>& lines);
    // Shows or hides the reference shapes (View ▸ Reference Shapes; shown by default).
    void setShowReferenceShapes(bool show);
    // Colours the reference shapes by their distance to the design, with a legend (3D view).
    void setColourReferenceByDistance(bool on);

signals:
    // What the mouse is over, e.g. "vertex 12", "edge 7 (S, crease)", "patch 3 (strip (SRSR))";
    // empty over nothing.
    void hoverChanged(const QString& text);
    // A right click (press and release without moving) at a widget position of glWidget(),
    // after the entity under it was selected (unless it already was).
    void contextMenuRequested(const QPoint& widgetPos);

protected:
    enum class Kind { Spatial, Development };
    SceneView(Kind kind, document::Document* document, document::Selection* selection,
              QWidget* parent);

    bool eventFilter(QObject* watched, QEvent* event) override;
    // A view hidden in a shown window (e.g. the development view switched off) skips rebuilds
    // and catches up when it is shown again.
    void showEvent(QShowEvent* event) override;

    void setShowControlPolygonsImpl(bool show);
    void setShowVerticesImpl(bool show);
    void setShowSheetImpl(bool show);
    void setTargetPointsImpl(const std::vector<model::Vec3>& points);
    void rerender();

private:
    void onDocumentChanged(unsigned changes);
    void onProjectReset();
    void onSelectionChanged();
    void rebuild(bool geometryOnly);
    void showReferenceCurves();
    void showReferenceShapes();
    // Applies the latest distances (ReferenceDistances) to the shapes drawn and the legend.
    void showReferenceDistances();
    // The colour map's legend as it should be drawn now (none when hidden).
    std::optional<DistanceLegend> distanceLegend() const;
    QString describe(const document::Pick& pick) const;
    void selectInRectangle(const QRect& rect, bool add);
    // After each render: scale bar and patch labels for the camera just drawn.
    void updateOverlay();
    // The condition badges and the legend entries of conditions and rulings.
    void updateBadges();
    void syncTriadCamera();

    struct Private;
    std::unique_ptr<Private> d;
};

} // namespace devsurf::views
