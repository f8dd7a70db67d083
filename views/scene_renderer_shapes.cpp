// Reference shapes in the 3D view: a mesh translucent, a cloud as small points, each built
// once into poly data and kept while its shape is unchanged.
#include "scene_renderer_shapes.h"

#include <vtkCellArray.h>
#include <vtkDoubleArray.h>
#include <vtkIdTypeArray.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>
#include <vtkUnsignedCharArray.h>

#include <algorithm>
#include <memory>

namespace devsurf::views {

using model::Vec3;

namespace {

// A shape's poly data: its points as doubles, then either its triangles or one poly-vertex
// cell holding every point (one cell draws millions of points in one call). Built from
// flat arrays, without a cell inserted at a time: about 0.15 s per million points.
vtkSmartPointer<vtkPolyData> shapeData(const model::ReferenceShape& shape) {
    const auto n = static_cast<vtkIdType>(shape.points.size());
    auto coordinates = vtkSmartPointer<vtkDoubleArray>::New();
    coordinates->SetNumberOfComponents(3);
    coordinates->SetNumberOfTuples(n);
    double* out = coordinates->GetPointer(0);
    for (const Vec3& p : shape.points) {
        *out++ = p.x;
        *out++ = p.y;
        *out++ = p.z;
    }
    auto points = vtkSmartPointer<vtkPoints>::New();
    points->SetData(coordinates);
    auto data = vtkSmartPointer<vtkPolyData>::New();
    data->SetPoints(points);

    auto offsets = vtkSmartPointer<vtkIdTypeArray>::New();
    auto connectivity = vtkSmartPointer<vtkIdTypeArray>::New();
    auto cells = vtkSmartPointer<vtkCellArray>::New();
    if (shape.isPointCloud()) {
        offsets->SetNumberOfValues(2);
        offsets->SetValue(0, 0);
        offsets->SetValue(1, n);
        connectivity->SetNumberOfValues(n);
        vtkIdType* ids = connectivity->GetPointer(0);
        for (vtkIdType i = 0; i < n; ++i) {
            ids[i] = i;
        }
        cells->SetData(offsets, connectivity);
        data->SetVerts(cells);
    } else {
        const auto t = static_cast<vtkIdType>(shape.triangles.size());
        offsets->SetNumberOfValues(t + 1);
        connectivity->SetNumberOfValues(3 * t);
        vtkIdType* ids = connectivity->GetPointer(0);
        for (vtkIdType i = 0; i <= t; ++i) {
            offsets->SetValue(i, 3 * i);
        }
        for (const std::array<int, 3>& triangle : shape.triangles) {
            *ids++ = triangle[0];
            *ids++ = triangle[1];
            *ids++ = triangle[2];
        }
        cells->SetData(offsets, connectivity);
        data->SetPolys(cells);
    }
    return data;
}

} // namespace

void SceneRenderer::setReferenceShapes(const std::vector<model::ReferenceShape>& shapes,
                                       double devicePixelRatio) {
    // Poly data already built for these shapes, whichever actor drew them.
    std::vector<std::unique_ptr<ShapeActor>> previous = std::move(m_shapeActors);
    m_shapeActors.clear();
    for (const model::ReferenceShape& shape : shapes) {
        auto reused = std::find_if(previous.begin(), previous.end(), [&](const auto& actor) {
            return actor != nullptr && actor->builtFrom(shape);
        });
        if (reused != previous.end()) {
            m_shapeActors.push_back(std::move(*reused));
            m_shapeActors.back()->actor->GetProperty()->SetPointSize(
                static_cast<float>(3.0 * devicePixelRatio));
            continue;
        }
        // A free actor (emptied below), else a new one.
        auto free = std::find_if(previous.begin(), previous.end(), [](const auto& actor) {
            return actor != nullptr && actor->data == nullptr;
        });
        std::unique_ptr<ShapeActor> actor;
        if (free != previous.end()) {
            actor = std::move(*free);
        } else {
            actor = std::make_unique<ShapeActor>();
            actor->actor->SetMapper(actor->mapper);
            actor->actor->PickableOff();
            actor->mapper->ScalarVisibilityOff();
            m_renderer->AddActor(actor->actor);
        }
        actor->data = shapeData(shape);
        actor->mapper->SetInputData(actor->data);
        actor->points = shape.points.data();
        actor->pointCount = shape.points.size();
        actor->triangles = shape.triangles.data();
        actor->triangleCount = shape.triangles.size();
        actor->isCloud = shape.isPointCloud();
        actor->coloured = false;
        double bounds[6];
        actor->data->GetBounds(bounds);
        actor->low = Vec3(bounds[0], bounds[2], bounds[4]);
        actor->high = Vec3(bounds[1], bounds[3], bounds[5]);
        vtkProperty* p = actor->actor->GetProperty();
        if (shape.isPointCloud()) {
            // Small unlit points: a dense cloud reads as a surface without hiding the design.
            p->SetRepresentationToPoints();
            p->SetPointSize(static_cast<float>(3.0 * devicePixelRatio));
            p->SetRenderPointsAsSpheres(false);
            p->SetLighting(false);
            p->SetColor(0.30, 0.36, 0.46);
            p->SetOpacity(1.0);
        } else {
            // Translucent blue-grey, both sides lit: the design shows through it.
            p->SetRepresentationToSurface();
            p->SetLighting(true);
            p->SetColor(0.55, 0.62, 0.72);
            p->SetOpacity(0.35);
            p->BackfaceCullingOff();
            p->FrontfaceCullingOff();
        }
        m_shapeActors.push_back(std::move(actor));
    }
    // Actors no shape needs: hidden and emptied, kept for the next shapes.
    auto empty = vtkSmartPointer<vtkPolyData>::New();
    for (std::unique_ptr<ShapeActor>& actor : previous) {
        if (actor == nullptr) {
            continue;
        }
        actor->data = nullptr;
        actor->points = nullptr;
        actor->triangles = nullptr;
        actor->mapper->SetInputData(empty);
        actor->actor->SetVisibility(false);
        m_shapeActors.push_back(std::move(actor));
    }
    m_shapesDrawn = static_cast<int>(shapes.size());
    m_shapeCorners.clear();
    for (int i = 0; i < m_shapesDrawn; ++i) {
        const ShapeActor& shape = *m_shapeActors[static_cast<std::size_t>(i)];
        for (int corner = 0; corner < 8; ++corner) {
            m_shapeCorners.push_back({(corner & 1) != 0 ? shape.high.x : shape.low.x,
                                      (corner & 2) != 0 ? shape.high.y : shape.low.y,
                                      (corner & 4) != 0 ? shape.high.z : shape.low.z});
        }
    }
    setShowReferenceShapes(m_showReferenceShapes);
}

bool SceneRenderer::setReferenceColours(const std::vector<const std::vector<double>*>& distances,
                                        const DistanceColouring* colouring, bool stale) {
    bool changed = false;
    for (int i = 0; i < m_shapesDrawn; ++i) {
        ShapeActor& shape = *m_shapeActors[static_cast<std::size_t>(i)];
        const std::vector<double>* values =
            colouring != nullptr && i < static_cast<int>(distances.size())
                ? distances[static_cast<std::size_t>(i)]
                : nullptr;
        const bool colour = values != nullptr && values->size() == shape.pointCount;
        if (!colour && !shape.coloured) {
            continue; // drawn in its own colour, as it was
        }
        changed = true;
        if (colour) {
            shape.data->GetPointData()->SetScalars(colouring->pointColours(*values, stale));
            shape.mapper->SetColorModeToDirectScalars();
            shape.mapper->SetScalarModeToUsePointData();
            shape.mapper->ScalarVisibilityOn();
        } else if (shape.coloured) {
            shape.data->GetPointData()->SetScalars(nullptr);
            shape.mapper->ScalarVisibilityOff();
        }
        if (!shape.isCloud) {
            // Coloured, a mesh is less translucent: its colours must read over the design.
            shape.actor->GetProperty()->SetOpacity(colour ? 0.8 : 0.35);
        }
        shape.coloured = colour;
        shape.data->Modified();
    }
    return changed;
}

bool SceneRenderer::drawsDistanceColours() const {
    for (int i = 0; i < m_shapesDrawn && m_showReferenceShapes; ++i) {
        if (m_shapeActors[static_cast<std::size_t>(i)]->coloured) {
            return true;
        }
    }
    return false;
}

QColor SceneRenderer::referencePointColour(int shape, int point) const {
    if (shape < 0 || shape >= m_shapesDrawn) {
        return QColor();
    }
    const ShapeActor& actor = *m_shapeActors[static_cast<std::size_t>(shape)];
    vtkDataArray* scalars = actor.data->GetPointData()->GetScalars();
    if (!actor.coloured || scalars == nullptr || point < 0 ||
        point >= scalars->GetNumberOfTuples()) {
        return QColor();
    }
    double rgb[3];
    scalars->GetTuple(point, rgb);
    return QColor(static_cast<int>(rgb[0]), static_cast<int>(rgb[1]), static_cast<int>(rgb[2]));
}

void SceneRenderer::forgetReferenceShapes() {
    // Every actor becomes free: the next setReferenceShapes() builds each shape again.
    for (std::unique_ptr<ShapeActor>& actor : m_shapeActors) {
        actor->data = nullptr;
        actor->points = nullptr;
        actor->triangles = nullptr;
    }
}

void SceneRenderer::setShowReferenceShapes(bool show) {
    m_showReferenceShapes = show;
    for (int i = 0; i < static_cast<int>(m_shapeActors.size()); ++i) {
        m_shapeActors[static_cast<std::size_t>(i)]->actor->SetVisibility(show && i < m_shapesDrawn);
    }
    showMarkedPoints(show);
}

int SceneRenderer::referenceShapeCount() const {
    return m_showReferenceShapes ? m_shapesDrawn : 0;
}

} // namespace devsurf::views
