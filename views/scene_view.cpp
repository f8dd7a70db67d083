#include "scene_view.h"

#include "model/model_error.h"
#include "reference_distances.h"
#include "scene_cache.h"
#include "scene_view_private.h"
#include "vtk_interactor_styles.h"

#include <vtkAxesActor.h>
#include <vtkCallbackCommand.h>
#include <vtkCamera.h>
#include <vtkCaptionActor2D.h>
#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkRenderWindowInteractor.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>
#include <vtkTextProperty.h>

#include <QLocale>
#include <QRectF>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>
#include <exception>
#include <limits>
#include <map>
#include <set>

namespace devsurf::views {

using document::Pick;

namespace {

// The scale bar is at most this long (logical pixels); the orientation triad this wide.
constexpr double kMaxScaleBar = 120.0;
constexpr double kTriadSize = 110.0;

// The longest of 1, 2 and 5 × 10^k mm that fits in maxPixels.
double niceLength(double pixelsPerMm, double maxPixels) {
    const double fits = maxPixels / pixelsPerMm;
    const double decade = std::pow(10.0, std::floor(std::log10(fits)));
    for (double step : {5.0, 2.0}) {
        if (step * decade <= fits) {
            return step * decade;
        }
    }
    return decade;
}

QString lengthText(double millimetres) {
    if (millimetres >= 1000.0) {
        return SceneView::tr("%1 m").arg(QLocale().toString(millimetres / 1000.0, 'g', 6));
    }
    return SceneView::tr("%1 mm").arg(QLocale().toString(millimetres, 'g', 6));
}

std::vector<LabelAnchor> labelAnchors(const std::vector<SurfaceScene>& scenes) {
    std::vector<LabelAnchor> anchors;
    for (const SurfaceScene& scene : scenes) {
        std::map<model::FaceId, std::vector<model::Vec3>> centres;
        for (std::size_t i = 0; i < scene.polygons.size(); ++i) {
            model::Vec3 c;
            for (int p : scene.polygons[i]) {
                c += scene.points[static_cast<std::size_t>(p)];
            }
            if (!scene.polygons[i].empty()) {
                centres[scene.polygonFace[i]].push_back(
                    c / static_cast<double>(scene.polygons[i].size()));
            }
        }
        for (const auto& [face, points] : centres) {
            model::Vec3 mean;
            for (const model::Vec3& p : points) {
                mean += p;
            }
            mean = mean / static_cast<double>(points.size());
            const auto nearest =
                std::min_element(points.begin(), points.end(), [&](const auto& a, const auto& b) {
                    return (a - mean).squaredNorm() < (b - mean).squaredNorm();
                });
            anchors.push_back({scene.surface, face, *nearest});
        }
    }
    return anchors;
}

} // namespace

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
    d->overlay = new ViewOverlay(d->gl);
    d->overlay->setGeometry(d->gl->rect());
    d->gl->installEventFilter(this);

    if (kind == Kind::Spatial) {
        // The orientation triad: the axes in a small renderer over the lower left corner that
        // turns with the main camera but never moves or zooms.
        auto axes = vtkSmartPointer<vtkAxesActor>::New();
        for (vtkCaptionActor2D* caption :
             {axes->GetXAxisCaptionActor2D(), axes->GetYAxisCaptionActor2D(),
              axes->GetZAxisCaptionActor2D()}) {
            vtkTextProperty* text = caption->GetCaptionTextProperty();
            text->SetColor(0.1, 0.1, 0.1);
            text->ShadowOff();
            text->ItalicOff();
        }
        d->triad = vtkSmartPointer<vtkRenderer>::New();
        d->triad->SetLayer(1);
        d->triad->InteractiveOff();
        d->triad->AddActor(axes);
        d->gl->renderWindow()->SetNumberOfLayers(2);
        d->gl->renderWindow()->AddRenderer(d->triad);
    }
    // Before every render: the triad follows the camera, the folds' dashes the zoom.
    d->startObserver = vtkSmartPointer<vtkCallbackCommand>::New();
    d->startObserver->SetClientData(this);
    d->startObserver->SetCallback([](vtkObject*, unsigned long, void* view, void*) {
        auto* self = static_cast<SceneView*>(view);
        if (self->d->triad != nullptr) {
            self->syncTriadCamera();
        }
        self->d->scene->updateFoldDashes();
    });
    d->startTag = d->renderer->AddObserver(vtkCommand::StartEvent, d->startObserver);
    d->endObserver = vtkSmartPointer<vtkCallbackCommand>::New();
    d->endObserver->SetClientData(this);
    d->endObserver->SetCallback([](vtkObject*, unsigned long, void* view, void*) {
        static_cast<SceneView*>(view)->updateOverlay();
    });
    d->endTag = d->renderer->AddObserver(vtkCommand::EndEvent, d->endObserver);

    if (kind == Kind::Spatial && document != nullptr) {
        // Created before this view follows the document, so that it has taken in a change
        // (e.g. dropped the distances of shapes just replaced) when the view rebuilds.
        connect(ReferenceDistances::of(document), &ReferenceDistances::changed, this,
                &SceneView::showReferenceDistances);
    }
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
    if (SceneCache* cache = SceneCache::of(document)) {
        const bool development = kind == Kind::Development;
        auto follow = [this, development] {
            if (d->followBackground) {
                rebuild(true);
                const SceneCache* cache = SceneCache::of(d->document);
                d->followBackground =
                    development ? cache->developmentPending() : cache->spatialPending();
            }
        };
        if (development) {
            connect(cache, &SceneCache::developmentReady, this, follow);
        } else {
            connect(cache, &SceneCache::spatialReady, this, follow);
        }
    }
}

SceneView::~SceneView() {
    d->gl->removeEventFilter(this);
    d->renderer->RemoveObserver(d->endTag);
    if (d->startObserver != nullptr) {
        d->renderer->RemoveObserver(d->startTag);
    }
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

std::set<Pick> SceneView::pinnedPicks() const {
    return d->scene->pinnedDrawn();
}

std::optional<model::Vec3> SceneView::widgetToPlane(const QPoint& widgetPos,
                                                    const model::Vec3& planePoint,
                                                    const model::Vec3& planeNormal) const {
    return d->scene->displayToPlane(d->displayX(widgetPos.x()), d->displayY(widgetPos.y()),
                                    planePoint, planeNormal);
}

QString SceneView::problem() const {
    return d->problem;
}

void SceneView::fitAll() {
    d->scene->resetCamera();
    rerender();
}

void SceneView::resetView() {
    if (d->kind == Kind::Spatial) {
        d->scene->lookAlong(SceneRenderer::defaultDirection(), {0.0, 0.0, 1.0});
    } else {
        d->scene->resetCamera();
    }
    rerender();
}

void SceneView::setStandardView(StandardView view) {
    if (d->kind != Kind::Spatial) {
        fitAll();
        return;
    }
    using model::Vec3;
    const Vec3 up(0.0, 0.0, 1.0);
    switch (view) {
    case StandardView::Isometric:
        d->scene->lookAlong({-1.0, 1.0, -1.0}, up);
        break;
    case StandardView::Front:
        d->scene->lookAlong({0.0, 1.0, 0.0}, up);
        break;
    case StandardView::Top:
        d->scene->lookAlong({0.0, 0.0, -1.0}, {0.0, 1.0, 0.0});
        break;
    case StandardView::Right:
        d->scene->lookAlong({-1.0, 0.0, 0.0}, up);
        break;
    case StandardView::Rear:
        d->scene->lookAlong({0.0, -1.0, 0.0}, up);
        break;
    case StandardView::Bottom:
        d->scene->lookAlong({0.0, 0.0, 1.0}, {0.0, -1.0, 0.0});
        break;
    case StandardView::Left:
        d->scene->lookAlong({1.0, 0.0, 0.0}, up);
        break;
    }
    rerender();
}

double SceneView::scaleBarLength() const {
    return d->barLength;
}

double SceneView::scaleBarPixels() const {
    return d->overlay->scaleBarPixels();
}

std::pair<int, int> SceneView::foldsDrawn() const {
    return d->scene->foldCounts();
}

std::optional<std::pair<model::Vec3, document::Pick>>
SceneView::surfacePointAt(const QPoint& widgetPos) const {
    if (d->kind != Kind::Spatial) {
        return std::nullopt;
    }
    std::optional<Pick> face;
    const std::optional<model::Vec3> hit =
        d->scene->surfacePoint(d->displayX(widgetPos.x()), d->displayY(widgetPos.y()), &face);
    if (!hit || !face) {
        return std::nullopt;
    }
    return std::make_pair(*hit, *face);
}

void SceneView::setMeasurement(const std::vector<model::Vec3>& points, const QString& text) {
    d->measurement = points;
    d->measurementText = text;
    rerender();
}

std::vector<model::Vec3> SceneView::measurementPoints() const {
    return d->measurement;
}

QString SceneView::verdictText() const {
    return d->overlay->verdict();
}

QRect SceneView::verdictRect() const {
    return d->overlay->verdictRect().toAlignedRect();
}

void SceneView::setVerdict(const QString& text, const QColor& colour) {
    d->overlay->setVerdict(text, colour);
}

std::pair<bool, bool> SceneView::foldLegend() const {
    return {d->overlay->showsMountainLegend(), d->overlay->showsValleyLegend()};
}

std::pair<int, int> SceneView::foldDashesDrawn() const {
    return d->scene->foldDashCounts();
}

double SceneView::foldDashUnit() const {
    return d->scene->foldDashUnit();
}

std::vector<ViewOverlay::Badge> SceneView::conditionBadges() const {
    return d->overlay->badges();
}

std::pair<int, int> SceneView::rulingsDrawn() const {
    return d->scene->rulingCounts();
}

QStringList SceneView::legendEntries() const {
    return d->overlay->legendEntries();
}

ViewOverlay::LegendContents SceneView::legendContents() const {
    return d->overlay->legendContents();
}

QImage SceneView::grabOverlay() const {
    return d->overlay->grab().toImage();
}

QString SceneView::scaleBarText() const {
    return d->overlay->scaleBarText();
}

bool SceneView::hasOrientationTriad() const {
    return d->triad != nullptr && d->triad->GetActors()->GetNumberOfItems() > 0;
}

bool SceneView::showPatchLabels() const {
    return d->showLabels;
}

QStringList SceneView::patchLabelTexts() const {
    QStringList texts;
    for (const ViewOverlay::Label& label : d->overlay->labels()) {
        texts << label.text;
    }
    return texts;
}

void SceneView::setShowPatchLabels(bool show) {
    d->showLabels = show;
    if (!show) {
        d->overlay->setLabels({});
    }
    rerender();
}

void SceneView::setPreviewLines(const std::vector<std::vector<model::Vec3>>& lines) {
    if (d->kind != Kind::Spatial) {
        return;
    }
    d->previewLines = static_cast<int>(lines.size());
    d->scene->setPreviewLines(lines);
    rerender();
}

ColourBy SceneView::colourBy() const {
    return d->scene->quality() ? d->scene->quality()->mode() : ColourBy::Patch;
}

QString SceneView::legendTitle() const {
    return d->scene->quality() ? d->scene->quality()->title() : QString();
}

QRect SceneView::legendRect() const {
    return d->overlay->qualityLegendRect().toAlignedRect();
}

double SceneView::legendTolerance() const {
    const QualityColouring* quality = d->scene->quality();
    return quality && quality->mode() != ColourBy::Patch ? quality->tolerance() : 0.0;
}

QString SceneView::legendToleranceLabel() const {
    return legendTolerance() > 0.0 ? QualityColouring::toleranceLabel() : QString();
}

QColor SceneView::legendColour(double value) const {
    if (legendTolerance() <= 0.0) {
        return QColor();
    }
    const std::array<double, 3> rgb = d->scene->quality()->colour(value);
    return QColor::fromRgbF(static_cast<float>(rgb[0]), static_cast<float>(rgb[1]),
                            static_cast<float>(rgb[2]));
}

std::pair<double, double> SceneView::legendRange() const {
    const QualityColouring* quality = d->scene->quality();
    return quality ? std::make_pair(quality->low(), quality->high()) : std::make_pair(0.0, 0.0);
}

double SceneView::legendValue(const document::Pick& face) const {
    const QualityColouring* quality = d->scene->quality();
    if (quality == nullptr || face.kind != document::Pick::Kind::Face) {
        return std::numeric_limits<double>::quiet_NaN();
    }
    return quality->valueOfPatch(d->scene->scenes(), face.surface, face.id);
}

void SceneView::setColourBy(ColourBy by) {
    d->scene->setColourBy(by);
    rerender();
}

int SceneView::previewLineCount() const {
    return d->previewLines;
}

void SceneView::syncTriadCamera() {
    vtkCamera* main = d->renderer->GetActiveCamera();
    vtkCamera* camera = d->triad->GetActiveCamera();
    double direction[3];
    main->GetDirectionOfProjection(direction);
    camera->SetFocalPoint(0.0, 0.0, 0.0);
    camera->SetPosition(-direction[0], -direction[1], -direction[2]);
    camera->SetViewUp(main->GetViewUp());
    d->triad->ResetCamera();
    const int* size = d->gl->renderWindow()->GetSize();
    if (size[0] > 0 && size[1] > 0) {
        const double side = kTriadSize * d->gl->effectiveDevicePixelRatio();
        d->triad->SetViewport(0.0, 0.0, std::min(1.0, side / size[0]),
                              std::min(1.0, side / size[1]));
    }
}

void SceneView::updateOverlay() {
    const double dpr = d->gl->effectiveDevicePixelRatio();
    const double perMm = d->scene->pixelsPerUnit() / dpr;
    if (perMm > 0.0 && std::isfinite(perMm) && !d->scene->scenes().empty()) {
        d->barLength = niceLength(perMm, kMaxScaleBar);
        d->overlay->setScaleBar(d->barLength * perMm, lengthText(d->barLength));
    } else {
        d->barLength = 0.0;
        d->overlay->setScaleBar(0.0, QString());
    }
    std::vector<QPointF> measured;
    for (const model::Vec3& point : d->measurement) {
        const model::Vec3 display = d->scene->toDisplay(point);
        measured.emplace_back(display.x / dpr, (d->deviceHeight() - 1.0 - display.y) / dpr);
    }
    d->overlay->setMeasurement(std::move(measured), d->measurementText);
    const QualityColouring* quality = d->scene->quality();
    if (quality != nullptr && quality->mode() != ColourBy::Patch) {
        d->overlay->setQualityLegend(ViewOverlay::QualityLegend{
            quality->title(), quality->colours(), quality->low(), quality->high(),
            quality->tolerance(), QualityColouring::toleranceLabel()});
    } else {
        d->overlay->setQualityLegend(std::nullopt);
    }
    d->overlay->setDistanceLegend(distanceLegend());
    const auto [mountains, valleys] = d->scene->foldCounts();
    d->overlay->setFoldLegend(mountains > 0, valleys > 0, d->scene->flatCreaseCount() > 0);
    d->overlay->setSheetLegend(d->scene->sheetLoopCount() > 0 && d->scene->showsSheet());
    updateBadges();
    std::vector<ViewOverlay::Label> labels;
    if (d->showLabels) {
        if (!d->anchorsValid) {
            d->anchors = labelAnchors(d->scene->scenes());
            d->anchorsValid = true;
        }
        for (const LabelAnchor& anchor : d->anchors) {
            const model::Vec3 display = d->scene->toDisplay(anchor.point);
            if (d->kind == Kind::Spatial) {
                // In 3D a number is written only where its patch is seen, not through others.
                const std::optional<Pick> seen = d->scene->faceAt(display.x, display.y);
                if (!seen || seen->surface != anchor.surface || seen->id != anchor.face) {
                    continue;
                }
            }
            labels.push_back({QPointF(display.x / dpr, (d->deviceHeight() - 1.0 - display.y) / dpr),
                              QString::number(anchor.face)});
        }
    }
    d->overlay->setLabels(std::move(labels));
}

void SceneView::updateBadges() {
    const double dpr = d->gl->effectiveDevicePixelRatio();
    std::vector<ViewOverlay::Badge> badges;
    std::set<model::CreaseCondition> present;
    for (const ConditionMark& mark : d->scene->conditionMarks()) {
        present.insert(mark.condition);
        if (d->scene->isHidden(mark.point)) {
            continue;
        }
        const model::Vec3 display = d->scene->toDisplay(mark.point);
        badges.push_back({QPointF(display.x / dpr, (d->deviceHeight() - 1.0 - display.y) / dpr),
                          mark.condition, mark.surface, mark.edge});
    }
    const auto [smooth, sharp] = d->scene->rulingCounts();
    d->overlay->setMarkLegend({present.begin(), present.end()}, smooth > 0, sharp > 0);
    d->overlay->setBadges(std::move(badges));
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

void SceneView::setShowSheetImpl(bool show) {
    d->scene->setShowSheet(show);
    rerender();
}

void SceneView::setTargetPointsImpl(const std::vector<model::Vec3>& points) {
    d->scene->setTargetPoints(points);
    rerender();
}

} // namespace devsurf::views
