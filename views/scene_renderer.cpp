#include "scene_renderer.h"

#include "poly_data_builders.h"
#include "quality_colours.h"
#include "scene_renderer_shapes.h"
#include "view_overlay.h"

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkCellPicker.h>
#include <vtkDoubleArray.h>
#include <vtkIdList.h>
#include <vtkIdTypeArray.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>
#include <vtkStaticCellLocator.h>
#include <vtkUnsignedCharArray.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace devsurf::views {

using document::Pick;
using model::Vec3;

namespace {

// Orange: the selection, in both views.
constexpr double kSelectionRgb[3] = {1.0, 0.45, 0.0};

} // namespace

struct SceneRenderer::Layer {
    vtkSmartPointer<vtkPolyData> data = vtkSmartPointer<vtkPolyData>::New();
    vtkSmartPointer<vtkPolyDataMapper> mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
    vtkSmartPointer<vtkActor> actor = vtkSmartPointer<vtkActor>::New();

    // Takes fresh's content; with geometryOnly and an unchanged structure only the points
    // (and normals) move, so cells, colours and the GPU index buffers stay.
    void assign(vtkPolyData* fresh, bool geometryOnly) {
        const bool sameStructure = data->GetNumberOfPoints() == fresh->GetNumberOfPoints() &&
                                   data->GetNumberOfCells() == fresh->GetNumberOfCells() &&
                                   data->GetNumberOfPoints() > 0;
        if (geometryOnly && sameStructure) {
            data->GetPoints()->DeepCopy(fresh->GetPoints());
            data->GetPoints()->Modified();
            if (vtkDataArray* normals = fresh->GetPointData()->GetNormals()) {
                data->GetPointData()->SetNormals(normals);
            }
            data->Modified();
        } else {
            data->ShallowCopy(fresh);
        }
    }
};

SceneRenderer::SceneRenderer(Mode mode, vtkRenderer* renderer)
    : m_mode(mode), m_renderer(renderer), m_picker(vtkSmartPointer<vtkCellPicker>::New()) {
    // Curves lie on the surface: draw lines and points in front of coincident polygons.
    vtkMapper::SetResolveCoincidentTopologyToPolygonOffset();

    const bool spatial = mode == Mode::Spatial;
    m_faces = &addLayer();
    m_faces->mapper->SetScalarModeToUseCellData();
    m_faces->mapper->SetColorModeToDirectScalars();
    m_faces->mapper->SetRelativeCoincidentTopologyPolygonOffsetParameters(1.0, 1.0);
    if (spatial) {
        // The light sits at the camera: some ambient keeps surfaces seen at a grazing angle
        // readable.
        m_faces->actor->GetProperty()->SetAmbient(0.3);
        m_faces->actor->GetProperty()->SetDiffuse(0.75);
        m_faces->actor->GetProperty()->SetSpecular(0.15);
        m_faces->actor->GetProperty()->SetSpecularPower(30.0);
    } else {
        // Paper: flat colours, no lighting.
        m_faces->actor->GetProperty()->SetLighting(false);
        m_faces->actor->GetProperty()->SetOpacity(1.0);
    }

    auto lineStyle = [](Layer& layer, double r, double g, double b, double width, bool tubes) {
        vtkProperty* p = layer.actor->GetProperty();
        p->SetColor(r, g, b);
        p->SetLineWidth(static_cast<float>(width));
        p->SetRenderLinesAsTubes(tubes);
        p->SetLighting(false);
        layer.mapper->ScalarVisibilityOff();
    };
    auto pointStyle = [](Layer& layer, double r, double g, double b, double size) {
        vtkProperty* p = layer.actor->GetProperty();
        p->SetColor(r, g, b);
        p->SetPointSize(static_cast<float>(size));
        p->SetRenderPointsAsSpheres(true);
        layer.mapper->ScalarVisibilityOff();
    };

    // The sheet a held development is confined to: wide and warm, first, so that the
    // development's own outline is drawn over it where its boundary lies on the sheet's.
    m_sheet = &addLayer();
    const QColor sheet = ViewOverlay::sheetColour();
    lineStyle(*m_sheet, sheet.redF(), sheet.greenF(), sheet.blueF(), 5.0, false);
    m_rulings = &addLayer();
    lineStyle(*m_rulings, 0.62, 0.62, 0.62, 1.0, false);
    m_outline = &addLayer();
    lineStyle(*m_outline, 0.05, 0.05, 0.05, 2.0, false);
    m_overlapOutline = &addLayer();
    lineStyle(*m_overlapOutline, 0.9, 0.05, 0.05, 4.0, false);
    m_rulingEdges = &addLayer();
    lineStyle(*m_rulingEdges, 0.35, 0.35, 0.35, 1.5, false);
    // Rulings the surface stays smooth across: light and wider, unlike the dark sharp ones.
    m_smoothRulings = &addLayer();
    const QColor smooth = ViewOverlay::smoothRulingColour();
    lineStyle(*m_smoothRulings, smooth.redF(), smooth.greenF(), smooth.blueF(), 3.0, false);
    m_splineEdges = &addLayer();
    lineStyle(*m_splineEdges, 0.15, 0.15, 0.15, 2.5, false);
    // Creases: the folds the design is about, thicker and darker than everything else; folded
    // ones in the origami colours and dashes (mountain red dash-dot, valley blue dashed).
    auto foldStyle = [&](model::FoldAssignment fold) {
        Layer& layer = addLayer();
        const QColor colour = ViewOverlay::foldColour(fold);
        lineStyle(layer, colour.redF(), colour.greenF(), colour.blueF(), 4.0, spatial);
        return &layer;
    };
    m_creases = foldStyle(model::FoldAssignment::Flat);
    m_mountains = foldStyle(model::FoldAssignment::Mountain);
    m_valleys = foldStyle(model::FoldAssignment::Valley);
    m_controlPolygons = &addLayer();
    lineStyle(*m_controlPolygons, 0.1, 0.3, 0.95, 1.5, false);
    m_controlPoints = &addLayer();
    pointStyle(*m_controlPoints, 0.1, 0.3, 0.95, 6.0);
    m_vertices = &addLayer();
    pointStyle(*m_vertices, 0.1, 0.1, 0.1, 9.0);
    // Pinned vertices: red, as the paper draws fixed vertices.
    m_pinned = &addLayer();
    pointStyle(*m_pinned, 0.85, 0.05, 0.05, 13.0);
    m_target = &addLayer();
    pointStyle(*m_target, 0.1, 0.7, 0.2, 4.0);
    // Marked points of a reference shape: magenta (neither the selection's orange nor a colour
    // of the distance map) and larger than the shape's own points.
    m_marked = &addLayer();
    pointStyle(*m_marked, 0.85, 0.0, 0.85, 7.0);
    m_selectedEdges = &addLayer();
    lineStyle(*m_selectedEdges, kSelectionRgb[0], kSelectionRgb[1], kSelectionRgb[2], 6.0, true);
    m_selectedVertices = &addLayer();
    pointStyle(*m_selectedVertices, kSelectionRgb[0], kSelectionRgb[1], kSelectionRgb[2], 15.0);

    // The preview of an edit: bright green, thick, drawn in front of the surface.
    m_preview = &addLayer();
    lineStyle(*m_preview, 0.0, 0.75, 0.25, 5.0, spatial);
    m_preview->mapper->SetRelativeCoincidentTopologyLineOffsetParameters(-2.0, -2.0);

    // Reference curves: thin and dark, drawn in front of the surface they may lie on. Not in
    // the pick list: picking never returns them.
    m_referenceCurves = &addLayer();
    lineStyle(*m_referenceCurves, 0.12, 0.12, 0.16, 1.5, false);
    m_referenceCurves->mapper->SetRelativeCoincidentTopologyLineOffsetParameters(-1.0, -1.0);

    m_controlPolygons->actor->SetVisibility(false);
    m_controlPoints->actor->SetVisibility(false);
    if (spatial) {
        m_quality = std::make_unique<QualityColouring>();
    }

    m_picker->SetTolerance(0.0005);
    m_picker->PickFromListOn();
    m_picker->AddPickList(m_faces->actor);
    m_locator = vtkSmartPointer<vtkStaticCellLocator>::New();
    m_locator->SetDataSet(m_faces->data);
    m_picker->AddLocator(m_locator);

    if (spatial) {
        m_renderer->GradientBackgroundOn();
        m_renderer->SetBackground(0.80, 0.83, 0.88);
        m_renderer->SetBackground2(0.97, 0.97, 0.99);
        // From the front right, above, z up: no example is seen edge-on (the cylinder's wall
        // would be from along its axis, the sheet's from the side).
        vtkCamera* camera = m_renderer->GetActiveCamera();
        const Vec3 direction = defaultDirection();
        camera->SetFocalPoint(0.0, 0.0, 0.0);
        camera->SetPosition(-direction.x, -direction.y, -direction.z);
        camera->SetViewUp(0.0, 0.0, 1.0);
    } else {
        m_renderer->SetBackground(0.96, 0.96, 0.93);
        vtkCamera* camera = m_renderer->GetActiveCamera();
        camera->ParallelProjectionOn();
        camera->SetPosition(0.0, 0.0, 1.0);
        camera->SetFocalPoint(0.0, 0.0, 0.0);
        camera->SetViewUp(0.0, 1.0, 0.0);
    }
}

// The actors stay in the renderer: removing one releases its GL resources, which needs the
// view's context current. They are released with everything else when the GL widget finalizes
// its render window (with its context current).
SceneRenderer::~SceneRenderer() = default;

SceneRenderer::Layer& SceneRenderer::addLayer() {
    m_layers.push_back(std::make_unique<Layer>());
    Layer& layer = *m_layers.back();
    layer.mapper->SetInputData(layer.data);
    layer.actor->SetMapper(layer.mapper);
    layer.actor->PickableOff();
    m_renderer->AddActor(layer.actor);
    return layer;
}

void SceneRenderer::setScenes(std::shared_ptr<const SceneSet> scenes, bool geometryOnly) {
    m_set = scenes != nullptr ? std::move(scenes) : std::make_shared<const SceneSet>();

    // Faces: one polydata for every surface, colour per patch as cell data.
    std::vector<Vec3> points;
    std::vector<Vec3> normals;
    auto polys = vtkSmartPointer<vtkCellArray>::New();
    m_cellFace.clear();
    for (const SurfaceScene& scene : m_set->scenes) {
        const vtkIdType base = static_cast<vtkIdType>(points.size());
        points.insert(points.end(), scene.points.begin(), scene.points.end());
        normals.insert(normals.end(), scene.normals.begin(), scene.normals.end());
        for (std::size_t i = 0; i < scene.polygons.size(); ++i) {
            polys->InsertNextCell(static_cast<vtkIdType>(scene.polygons[i].size()));
            for (int p : scene.polygons[i]) {
                polys->InsertCellPoint(base + p);
            }
            m_cellFace.emplace_back(scene.surface, scene.polygonFace[i]);
        }
    }
    auto faces = vtkSmartPointer<vtkPolyData>::New();
    faces->SetPoints(makePoints(points));
    faces->SetPolys(polys);
    if (!normals.empty() && normals.size() == points.size()) {
        auto array = vtkSmartPointer<vtkDoubleArray>::New();
        array->SetNumberOfComponents(3);
        array->SetNumberOfTuples(static_cast<vtkIdType>(normals.size()));
        for (std::size_t i = 0; i < normals.size(); ++i) {
            array->SetTuple3(static_cast<vtkIdType>(i), normals[i].x, normals[i].y, normals[i].z);
        }
        faces->GetPointData()->SetNormals(array);
    }
    m_faces->assign(faces, geometryOnly);
    m_locatorStale = true;
    m_faces->actor->SetPickable(true);

    std::vector<std::vector<Vec3>> rulingEdges;
    std::vector<std::vector<Vec3>> smoothRulings;
    std::vector<std::vector<Vec3>> splineEdges;
    std::vector<std::vector<Vec3>> creases;
    std::vector<std::vector<Vec3>> mountains;
    std::vector<std::vector<Vec3>> valleys;
    std::vector<std::pair<Vec3, Vec3>> rulings;
    std::vector<std::pair<Vec3, Vec3>> outline;
    std::vector<std::pair<Vec3, Vec3>> overlapOutline;
    std::vector<std::vector<Vec3>> sheet;
    std::vector<std::vector<Vec3>> controlPolygons;
    std::vector<Vec3> controlPoints;
    std::vector<Vec3> vertices;
    std::vector<Vec3> pinned;
    m_pinnedDrawn.clear();
    int sharpRulings = 0;
    for (const SurfaceScene& scene : m_set->scenes) {
        for (model::VertexId id : scene.pinned) {
            auto it = scene.vertices.find(id);
            if (it != scene.vertices.end()) {
                pinned.push_back(it->second);
                m_pinnedDrawn.insert(Pick{Pick::Kind::Vertex, scene.surface, id});
            }
        }
        for (const EdgeCurve& edge : scene.edges) {
            if (edge.crease && edge.fold == model::FoldAssignment::Mountain) {
                mountains.push_back(edge.points);
            } else if (edge.crease && edge.fold == model::FoldAssignment::Valley) {
                valleys.push_back(edge.points);
            } else if (edge.smooth) {
                smoothRulings.push_back(edge.points);
            } else {
                (edge.crease ? creases : (edge.spline ? splineEdges : rulingEdges))
                    .push_back(edge.points);
                sharpRulings += !edge.spline && !edge.boundary ? 1 : 0;
            }
        }
        rulings.insert(rulings.end(), scene.rulings.begin(), scene.rulings.end());
        outline.insert(outline.end(), scene.outline.begin(), scene.outline.end());
        sheet.insert(sheet.end(), scene.sheet.begin(), scene.sheet.end());
        overlapOutline.insert(overlapOutline.end(), scene.overlapOutline.begin(),
                              scene.overlapOutline.end());
        vertices.insert(vertices.end(), scene.seamVertices.begin(), scene.seamVertices.end());
        controlPolygons.insert(controlPolygons.end(), scene.controlPolygons.begin(),
                               scene.controlPolygons.end());
        controlPoints.insert(controlPoints.end(), scene.controlPoints.begin(),
                             scene.controlPoints.end());
        for (const auto& entry : scene.vertices) {
            vertices.push_back(entry.second);
        }
    }
    m_rulingEdges->assign(polylineData(rulingEdges), geometryOnly);
    m_smoothRulings->assign(polylineData(smoothRulings), geometryOnly);
    m_rulingCounts = {static_cast<int>(smoothRulings.size()), sharpRulings};
    m_conditionMarks = views::conditionMarks(m_set->scenes);
    m_splineEdges->assign(polylineData(splineEdges), geometryOnly);
    m_creases->assign(polylineData(creases), geometryOnly);
    m_flatCreases = static_cast<int>(creases.size());
    m_mountainLines = std::move(mountains);
    m_valleyLines = std::move(valleys);
    m_rulings->assign(segmentData(rulings), geometryOnly);
    m_outline->assign(segmentData(outline), geometryOnly);
    m_sheetLoops = static_cast<int>(sheet.size());
    m_sheet->assign(polylineData(sheet), geometryOnly);
    m_overlapOutline->assign(segmentData(overlapOutline), geometryOnly);
    m_controlPolygons->assign(polylineData(controlPolygons), geometryOnly);
    m_controlPoints->assign(pointData(controlPoints), geometryOnly);
    m_vertices->assign(pointData(vertices), geometryOnly);
    m_pinned->assign(pointData(pinned), false);

    double diagonal = 0.0;
    if (!points.empty()) {
        double lo[3] = {std::numeric_limits<double>::infinity(),
                        std::numeric_limits<double>::infinity(),
                        std::numeric_limits<double>::infinity()};
        double hi[3] = {-lo[0], -lo[1], -lo[2]};
        for (const Vec3& p : points) {
            for (int k = 0; k < 3; ++k) {
                lo[k] = std::min(lo[k], p[k]);
                hi[k] = std::max(hi[k], p[k]);
            }
        }
        diagonal = std::hypot(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]);
    }
    m_sceneSize = diagonal > 0.0 ? diagonal : 1.0;
    // The folds are dashed as last drawn (the zoom is unchanged, so are the dashes' lengths);
    // updateFoldDashes() follows the zoom. A new design, larger by far, is not cut into the
    // dashes of the last one's zoom before its first render.
    m_dashUnit = m_dashUnit > 0.0 ? std::max(m_dashUnit, m_sceneSize / 2000.0) : currentDashUnit();
    drawFolds();

    if (m_quality) {
        m_quality->update(m_set->scenes);
    }
    rebuildHighlight();
}

double SceneRenderer::currentDashUnit() const {
    const double perUnit = pixelsPerUnit();
    const double unit = perUnit > 0.0 && std::isfinite(perUnit) ? kFoldDashUnitPixels / perUnit
                                                                : m_sceneSize / 300.0;
    return std::max(unit, m_sceneSize / 2000.0);
}

void SceneRenderer::drawFolds() {
    auto dashes = [this](model::FoldAssignment fold) {
        std::vector<double> pattern = foldDashes(fold);
        for (double& length : pattern) {
            length *= m_dashUnit;
        }
        return pattern;
    };
    m_mountains->assign(
        polylineData(dashedPolylines(m_mountainLines, dashes(model::FoldAssignment::Mountain))),
        false);
    m_valleys->assign(
        polylineData(dashedPolylines(m_valleyLines, dashes(model::FoldAssignment::Valley))), false);
}

bool SceneRenderer::updateFoldDashes() {
    const double unit = currentDashUnit();
    if (unit > 0.8 * m_dashUnit && unit < 1.25 * m_dashUnit) {
        return false;
    }
    m_dashUnit = unit;
    drawFolds();
    return true;
}

std::pair<int, int> SceneRenderer::foldDashCounts() const {
    return {static_cast<int>(m_mountains->data->GetNumberOfCells()),
            static_cast<int>(m_valleys->data->GetNumberOfCells())};
}

void SceneRenderer::setSelection(const std::set<Pick>& picks) {
    m_selection = picks;
    rebuildHighlight();
}

void SceneRenderer::setColourBy(ColourBy by) {
    if (m_quality) {
        m_quality->setMode(by);
        m_quality->update(m_set->scenes);
        rebuildHighlight();
    }
}

void SceneRenderer::rebuildHighlight() {
    m_highlighted.clear();
    const ColourBy by = m_quality ? m_quality->mode() : ColourBy::Patch;
    const bool perCellQuality =
        by != ColourBy::Patch && !isPerPoint(by) && m_quality->values().size() == m_cellFace.size();

    // Selected faces: their patch colour pulled towards the selection colour.
    auto colours = vtkSmartPointer<vtkUnsignedCharArray>::New();
    colours->SetNumberOfComponents(3);
    colours->SetName("colours");
    colours->SetNumberOfTuples(static_cast<vtkIdType>(m_cellFace.size()));
    for (std::size_t c = 0; c < m_cellFace.size(); ++c) {
        const auto& [surface, face] = m_cellFace[c];
        std::array<double, 3> rgb =
            perCellQuality ? m_quality->colour(m_quality->values()[c]) : patchRgb(face);
        const Pick pick{Pick::Kind::Face, surface, face};
        if (m_selection.count(pick) != 0) {
            m_highlighted.insert(pick);
            for (int k = 0; k < 3; ++k) {
                rgb[static_cast<std::size_t>(k)] =
                    0.3 * rgb[static_cast<std::size_t>(k)] + 0.7 * kSelectionRgb[k];
            }
        }
        unsigned char value[3];
        for (int k = 0; k < 3; ++k) {
            value[k] = static_cast<unsigned char>(
                std::lround(255.0 * std::clamp(rgb[static_cast<std::size_t>(k)], 0.0, 1.0)));
        }
        colours->SetTypedTuple(static_cast<vtkIdType>(c), value);
    }
    if (m_faces->data->GetNumberOfCells() == static_cast<vtkIdType>(m_cellFace.size())) {
        m_faces->data->GetCellData()->SetScalars(colours);
        const bool perPoint = by != ColourBy::Patch && isPerPoint(by) &&
                              static_cast<vtkIdType>(m_quality->values().size()) ==
                                  m_faces->data->GetNumberOfPoints();
        m_faces->data->GetPointData()->SetScalars(perPoint ? m_quality->pointColours() : nullptr);
        if (perPoint) {
            m_faces->mapper->SetScalarModeToUsePointData();
        } else {
            m_faces->mapper->SetScalarModeToUseCellData();
        }
        m_faces->data->Modified();
    }

    std::vector<std::vector<Vec3>> edges;
    std::vector<Vec3> vertices;
    for (const SurfaceScene& scene : m_set->scenes) {
        for (const EdgeCurve& edge : scene.edges) {
            const Pick pick{Pick::Kind::Edge, scene.surface, edge.id};
            if (m_selection.count(pick) != 0) {
                m_highlighted.insert(pick);
                edges.push_back(edge.points);
            }
        }
        for (const auto& [id, position] : scene.vertices) {
            const Pick pick{Pick::Kind::Vertex, scene.surface, id};
            if (m_selection.count(pick) != 0) {
                m_highlighted.insert(pick);
                vertices.push_back(position);
            }
        }
    }
    m_selectedEdges->assign(polylineData(edges), false);
    m_selectedVertices->assign(pointData(vertices), false);
}

void SceneRenderer::setShowControlPolygons(bool show) {
    m_controlPolygons->actor->SetVisibility(show);
    m_controlPoints->actor->SetVisibility(show);
    m_controlPointsShown = show;
}

void SceneRenderer::setShowVertices(bool show) {
    m_vertices->actor->SetVisibility(show);
}

void SceneRenderer::setShowSheet(bool show) {
    m_showSheet = show;
    m_sheet->actor->SetVisibility(show);
}

void SceneRenderer::setTargetPoints(const std::vector<Vec3>& points) {
    m_target->assign(pointData(points), false);
}

void SceneRenderer::setMarkedPoints(const std::vector<Vec3>& points) {
    m_marked->assign(pointData(points), false);
}

void SceneRenderer::showMarkedPoints(bool show) {
    m_marked->actor->SetVisibility(show);
}

int SceneRenderer::markedPointCount() const {
    return m_showReferenceShapes ? static_cast<int>(m_marked->data->GetNumberOfPoints()) : 0;
}

void SceneRenderer::setPreviewLines(const std::vector<std::vector<Vec3>>& lines) {
    m_preview->assign(polylineData(lines), false);
}

void SceneRenderer::setReferenceCurves(const std::vector<std::vector<Vec3>>& curves) {
    m_referenceCurves->assign(polylineData(curves), false);
    m_referenceCurveCount = static_cast<int>(m_referenceCurves->data->GetNumberOfCells());
    // Their bounding box's corners, for the fit (fitPoints).
    m_referenceCorners.clear();
    Vec3 low(std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
             std::numeric_limits<double>::infinity());
    Vec3 high = -low;
    for (const auto& curve : curves) {
        for (const Vec3& p : curve) {
            low = Vec3(std::min(low.x, p.x), std::min(low.y, p.y), std::min(low.z, p.z));
            high = Vec3(std::max(high.x, p.x), std::max(high.y, p.y), std::max(high.z, p.z));
        }
    }
    if (low.x <= high.x) {
        for (int corner = 0; corner < 8; ++corner) {
            m_referenceCorners.push_back({(corner & 1) != 0 ? high.x : low.x,
                                          (corner & 2) != 0 ? high.y : low.y,
                                          (corner & 4) != 0 ? high.z : low.z});
        }
    }
}
} // namespace devsurf::views
