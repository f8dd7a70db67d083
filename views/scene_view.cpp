#include "scene_view.h"

#include "model/document/document.h"
#include "model/model_error.h"
#include "scene_renderer.h"
#include "vtk_interactor_styles.h"
#include "vtk_opengl_widget.h"

#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkRenderWindowInteractor.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>

#include <QMouseEvent>
#include <QPointer>
#include <QRubberBand>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>
#include <exception>
#include <limits>

namespace devsurf::views {

using document::Pick;

namespace {

// Pointer travel (logical pixels) below which a press and release count as a click.
constexpr int kClickSlop = 3;
// Vertices are picked within this many logical pixels of the cursor.
constexpr double kPickRadius = 9.0;

} // namespace

struct SceneView::Private {
    Kind kind = Kind::Spatial;
    QPointer<document::Document> document;
    QPointer<document::Selection> selection;
    VtkOpenGLWidget* gl = nullptr;
    vtkSmartPointer<vtkRenderer> renderer;
    std::unique_ptr<SceneRenderer> scene;
    quint64 builtRevision = std::numeric_limits<quint64>::max();
    QString problem;
    QString hover;

    QPoint pressPos;
    bool pressed = false;
    QRubberBand* band = nullptr;
    bool banding = false;

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

SceneView::SceneView(Kind kind, document::Document* document, document::Selection* selection,
                     QWidget* parent)
    : QWidget(parent), d(std::make_unique<Private>()) {
    d->kind = kind;
    d->document = document;
    d->selection = selection;

    d->gl = new VtkOpenGLWidget(this);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(d->gl);

    d->renderer = vtkSmartPointer<vtkRenderer>::New();
    d->gl->renderWindow()->AddRenderer(d->renderer);
    if (kind == Kind::Spatial) {
        d->gl->interactor()->SetInteractorStyle(vtkSmartPointer<OrbitStyle>::New());
    } else {
        d->gl->interactor()->SetInteractorStyle(vtkSmartPointer<PlanarStyle>::New());
    }
    d->scene = std::make_unique<SceneRenderer>(
        kind == Kind::Spatial ? SceneRenderer::Mode::Spatial : SceneRenderer::Mode::Development,
        d->renderer);

    d->band = new QRubberBand(QRubberBand::Rectangle, d->gl);
    d->gl->installEventFilter(this);

    if (document != nullptr) {
        connect(document, &document::Document::changed, this,
                [this](document::Changes changes) { onDocumentChanged(changes.toInt()); });
        connect(document, &document::Document::projectReset, this, &SceneView::onProjectReset);
    }
    if (selection != nullptr) {
        connect(selection, &document::Selection::selectionChanged, this,
                &SceneView::onSelectionChanged);
    }
    onProjectReset();
}

SceneView::~SceneView() {
    d->gl->removeEventFilter(this);
    // The GL widget, a child, is destroyed after this: it finalizes the render window (and so
    // every actor's GL resources) with its context current.
    d->scene.reset();
}

document::Document* SceneView::document() const {
    return d->document;
}

document::Selection* SceneView::selection() const {
    return d->selection;
}

VtkOpenGLWidget* SceneView::glWidget() const {
    return d->gl;
}

std::optional<Pick> SceneView::pickAt(const QPoint& widgetPos) const {
    if (!d->gl->rect().contains(widgetPos)) {
        return std::nullopt;
    }
    const double dpr = d->gl->effectiveDevicePixelRatio();
    return d->scene->pick(d->displayX(widgetPos.x()), d->displayY(widgetPos.y()),
                          kPickRadius * dpr);
}

QPoint SceneView::projectToWidget(const model::Vec3& scenePoint) const {
    const model::Vec3 display = d->scene->toDisplay(scenePoint);
    const double dpr = d->gl->effectiveDevicePixelRatio();
    return QPoint(static_cast<int>(std::lround(display.x / dpr)),
                  static_cast<int>(std::lround((d->deviceHeight() - 1.0 - display.y) / dpr)));
}

QPoint SceneView::projectVertexToWidget(int surface, model::VertexId vertex) const {
    const std::optional<model::Vec3> point = vertexScenePoint(surface, vertex);
    return point ? projectToWidget(*point) : QPoint(-1, -1);
}

std::optional<model::Vec3> SceneView::vertexScenePoint(int surface, model::VertexId vertex) const {
    const model::Vec3* p = d->scene->vertexPosition(surface, vertex);
    return p ? std::optional<model::Vec3>(*p) : std::nullopt;
}

model::Vec3 SceneView::viewDirection() const {
    return d->scene->viewDirection();
}

QImage SceneView::grabImage() {
    return d->gl->grabFramebuffer();
}

std::set<Pick> SceneView::highlightedPicks() const {
    return d->scene->highlighted();
}

QString SceneView::problem() const {
    return d->problem;
}

void SceneView::fitAll() {
    d->scene->resetCamera();
    rerender();
}

void SceneView::rerender() {
    d->gl->requestRender();
}

void SceneView::setShowControlPolygonsImpl(bool show) {
    d->scene->setShowControlPolygons(show);
    rerender();
}

void SceneView::setShowVerticesImpl(bool show) {
    d->scene->setShowVertices(show);
    rerender();
}

void SceneView::setTargetPointsImpl(const std::vector<model::Vec3>& points) {
    d->scene->setTargetPoints(points);
    rerender();
}

void SceneView::onDocumentChanged(unsigned changes) {
    // resetProject() announces itself twice (projectReset, then changed): build once.
    if (d->document == nullptr || d->document->revision() == d->builtRevision) {
        return;
    }
    const unsigned structural = static_cast<unsigned>(document::Change::Labels) |
                                static_cast<unsigned>(document::Change::Topology);
    const bool firstBuild = d->scene->scenes().empty();
    rebuild((changes & structural) == 0);
    if (firstBuild) {
        fitAll();
    }
}

void SceneView::onProjectReset() {
    rebuild(false);
    fitAll();
}

void SceneView::onSelectionChanged() {
    d->scene->setSelection(d->selection ? d->selection->picks() : std::set<Pick>{});
    rerender();
}

void SceneView::rebuild(bool geometryOnly) {
    d->problem.clear();
    std::vector<SurfaceScene> scenes;
    if (d->document != nullptr) {
        d->builtRevision = d->document->revision();
        const auto& surfaces = d->document->project().surfaces;
        double x0 = 0.0;
        for (std::size_t i = 0; i < surfaces.size(); ++i) {
            try {
                if (d->kind == Kind::Spatial) {
                    scenes.push_back(buildSpatialScene(surfaces[i], static_cast<int>(i)));
                } else {
                    scenes.push_back(buildDevelopmentScene(surfaces[i], static_cast<int>(i), x0));
                    // Developments of several surfaces lie side by side with a gap.
                    const auto [lo, hi] = sceneBounds(scenes.back());
                    if (std::isfinite(hi.x)) {
                        x0 = hi.x + 0.1 * std::max(hi.x - lo.x, hi.y - lo.y);
                    }
                }
            } catch (const std::exception&) {
                // An invalid surface (e.g. mid-way through an edit) is skipped, not fatal.
                d->problem = tr("Surface %1 is not valid and is not shown.").arg(i + 1);
                geometryOnly = false;
            }
        }
    }
    d->scene->setScenes(std::move(scenes), geometryOnly);
    d->scene->setSelection(d->selection ? d->selection->picks() : std::set<Pick>{});
    rerender();
}

QString SceneView::describe(const Pick& pick) const {
    if (d->document == nullptr) {
        return {};
    }
    const auto& surfaces = d->document->project().surfaces;
    if (pick.surface < 0 || pick.surface >= static_cast<int>(surfaces.size())) {
        return {};
    }
    const model::CompositeSurface& surface = surfaces[static_cast<std::size_t>(pick.surface)];
    QString text;
    switch (pick.kind) {
    case Pick::Kind::Vertex:
        text = tr("vertex %1").arg(pick.id);
        break;
    case Pick::Kind::Edge: {
        if (!surface.hasEdge(pick.id)) {
            return {};
        }
        const bool spline = surface.edge(pick.id).isSpline();
        const std::size_t faces = surface.facesOfEdge(pick.id).size();
        if (!spline) {
            text = tr("edge %1 (R)").arg(pick.id);
        } else if (faces == 2) {
            text = tr("edge %1 (S, crease)").arg(pick.id);
        } else {
            text = tr("edge %1 (S, boundary)").arg(pick.id);
        }
        break;
    }
    case Pick::Kind::Face: {
        if (!surface.hasFace(pick.id)) {
            return {};
        }
        QString type;
        switch (surface.faceType(pick.id)) {
        case model::FaceType::StripSRSR:
            type = tr("SRSR strip");
            break;
        case model::FaceType::StripSRS:
            type = tr("SRS strip");
            break;
        case model::FaceType::ConeSRR:
            type = tr("SRR cone");
            break;
        case model::FaceType::Planar:
            type = tr("planar polygon");
            break;
        case model::FaceType::Invalid:
            type = tr("invalid face");
            break;
        }
        text = tr("face %1 (%2)").arg(pick.id).arg(type);
        break;
    }
    }
    if (surfaces.size() > 1) {
        text = tr("surface %1: %2").arg(pick.surface + 1).arg(text);
    }
    return text;
}

void SceneView::selectInRectangle(const QRect& rect, bool add) {
    if (d->selection == nullptr) {
        return;
    }
    std::set<Pick> picks = add ? d->selection->picks() : std::set<Pick>{};
    for (const SurfaceScene& scene : d->scene->scenes()) {
        for (const auto& [id, position] : scene.vertices) {
            if (rect.contains(projectToWidget(position))) {
                picks.insert(Pick{Pick::Kind::Vertex, scene.surface, id});
            }
        }
    }
    d->selection->set(std::move(picks));
}

bool SceneView::eventFilter(QObject* watched, QEvent* event) {
    if (watched != d->gl) {
        return QWidget::eventFilter(watched, event);
    }
    switch (event->type()) {
    case QEvent::MouseButtonPress: {
        auto* me = static_cast<QMouseEvent*>(event);
        if (me->button() != Qt::LeftButton) {
            break;
        }
        d->pressPos = me->position().toPoint();
        d->pressed = true;
        if (me->modifiers() & Qt::ControlModifier) {
            // Rectangle selection instead of the camera's spin.
            d->banding = true;
            d->band->setGeometry(QRect(d->pressPos, QSize()));
            d->band->show();
            return true;
        }
        break;
    }
    case QEvent::MouseMove: {
        auto* me = static_cast<QMouseEvent*>(event);
        if (d->banding) {
            d->band->setGeometry(QRect(d->pressPos, me->position().toPoint()).normalized());
            return true;
        }
        if (me->buttons() == Qt::NoButton) {
            const std::optional<Pick> pick = pickAt(me->position().toPoint());
            const QString text = pick ? describe(*pick) : QString();
            if (text != d->hover) {
                d->hover = text;
                emit hoverChanged(text);
            }
        }
        break;
    }
    case QEvent::MouseButtonRelease: {
        auto* me = static_cast<QMouseEvent*>(event);
        if (me->button() != Qt::LeftButton || !d->pressed) {
            break;
        }
        d->pressed = false;
        const QPoint pos = me->position().toPoint();
        const bool click = (pos - d->pressPos).manhattanLength() <= kClickSlop;
        const bool shift = me->modifiers() & Qt::ShiftModifier;
        const bool wasBanding = d->banding;
        if (d->banding) {
            d->banding = false;
            d->band->hide();
            if (!click) {
                selectInRectangle(QRect(d->pressPos, pos).normalized(), shift);
                return true;
            }
        }
        if (click && d->selection != nullptr) {
            const std::optional<Pick> pick = pickAt(pos);
            if (shift) {
                if (pick) {
                    d->selection->toggle(*pick);
                }
            } else if (pick) {
                d->selection->set({*pick});
            } else {
                d->selection->clear();
            }
        }
        if (wasBanding) {
            return true; // the press never reached VTK either
        }
        break;
    }
    case QEvent::Leave:
        if (!d->hover.isEmpty()) {
            d->hover.clear();
            emit hoverChanged(QString());
        }
        break;
    default:
        break;
    }
    return QWidget::eventFilter(watched, event);
}

} // namespace devsurf::views
