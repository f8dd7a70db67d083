#pragma once

// Internal to views/: the state of a SceneView, shared by scene_view.cpp and
// scene_view_input.cpp.

#include "model/document/document.h"
#include "scene_renderer.h"
#include "scene_view.h"
#include "view_overlay.h"
#include "vtk_opengl_widget.h"

#include <vtkCallbackCommand.h>
#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>

#include <QPointer>
#include <QRubberBand>

#include <array>
#include <cmath>
#include <limits>
#include <memory>

namespace devsurf::views {

// Pointer travel (logical pixels) below which a press and release count as a click.
inline constexpr int kClickSlop = 3;
// Vertices are picked within this many logical pixels of the cursor.
inline constexpr double kPickRadius = 9.0;

// Where a patch's number is written: the centre of the patch's drawn polygon nearest the
// mean of all its points, so that the number sits on the patch, not in a hole or off a curve.
struct LabelAnchor {
    int surface = 0;
    model::FaceId face = model::kInvalidId;
    model::Vec3 point;
};

struct SceneView::Private {
    Kind kind = Kind::Spatial;
    QPointer<document::Document> document;
    QPointer<document::Selection> selection;
    VtkOpenGLWidget* gl = nullptr;
    vtkSmartPointer<vtkRenderer> renderer;
    std::unique_ptr<SceneRenderer> scene;
    quint64 builtRevision = std::numeric_limits<quint64>::max();
    bool staleWhileHidden = false; // a change arrived while the view was hidden
    // The undo stack (count, index) and the surface changed at the last change: the same again
    // means the last change merged into the undo step before it (a drag goes on).
    std::array<int, 3> lastChange = {-1, -1, -1};
    // The view draws the latest background build (SceneCache) while one is pending: the
    // development during a drag, and either view after a change of a large surface.
    bool followBackground = false;
    QString problem;
    QString hover;

    QPoint pressPos;
    bool pressed = false;
    QRubberBand* band = nullptr;
    bool banding = false;
    QPoint rightPressPos;
    bool rightPressed = false;

    ViewOverlay* overlay = nullptr;
    std::vector<model::Vec3> measurement; // scene points of the measurement drawn
    QString measurementText;
    vtkSmartPointer<vtkRenderer> triad; // 3D view only
    vtkSmartPointer<vtkCallbackCommand> startObserver;
    vtkSmartPointer<vtkCallbackCommand> endObserver;
    unsigned long startTag = 0;
    unsigned long endTag = 0;
    bool showLabels = false;
    std::vector<LabelAnchor> anchors; // computed when labels are first drawn after a rebuild
    bool anchorsValid = false;
    double barLength = 0.0;
    int previewLines = 0;
    bool byDistance = false; // View ▸ Colour Reference by Distance
    DistanceMap distanceMap = DistanceMap::Hidden;
    DistanceColouring distanceColouring;

    double displayX(double widgetX) const { return widgetX * gl->effectiveDevicePixelRatio(); }
    double displayY(double widgetY) const {
        const double dpr = gl->effectiveDevicePixelRatio();
        return deviceHeight() - 1.0 - widgetY * dpr;
    }
    double deviceHeight() const {
        const int* size = gl->renderWindow()->GetSize();
        return size[1] > 0 ? size[1] : std::lround(gl->height() * gl->effectiveDevicePixelRatio());
    }
};

} // namespace devsurf::views
