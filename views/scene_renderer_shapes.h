#pragma once

// The reference shapes the 3D view draws (SceneRenderer::setReferenceShapes), shared by the
// renderer and scene_renderer_shapes.cpp, which builds them.

#include "scene_renderer.h"

#include <vtkActor.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkSmartPointer.h>

#include <array>
#include <cstddef>

namespace devsurf::views {

// A reference shape as drawn: its poly data, built once, and the storage it was built from.
struct SceneRenderer::ShapeActor {
    vtkSmartPointer<vtkPolyDataMapper> mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
    vtkSmartPointer<vtkActor> actor = vtkSmartPointer<vtkActor>::New();
    vtkSmartPointer<vtkPolyData> data;
    const model::Vec3* points = nullptr;
    std::size_t pointCount = 0;
    const std::array<int, 3>* triangles = nullptr;
    std::size_t triangleCount = 0;
    model::Vec3 low, high; // bounding box
    bool isCloud = false;
    bool coloured = false; // by distance (setReferenceColours)

    bool builtFrom(const model::ReferenceShape& shape) const {
        return data != nullptr && points == shape.points.data() &&
               pointCount == shape.points.size() && triangles == shape.triangles.data() &&
               triangleCount == shape.triangles.size();
    }
};

} // namespace devsurf::views
