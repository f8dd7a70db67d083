#pragma once

// Internal to views/: VTK poly data from plain point lists.

#include "model/vec3.h"

#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <utility>
#include <vector>

namespace devsurf::views {

vtkSmartPointer<vtkPoints> makePoints(const std::vector<model::Vec3>& points);
// One polyline cell per line of at least two points.
vtkSmartPointer<vtkPolyData> polylineData(const std::vector<std::vector<model::Vec3>>& lines);
vtkSmartPointer<vtkPolyData>
segmentData(const std::vector<std::pair<model::Vec3, model::Vec3>>& segments);
// One vertex cell per point.
vtkSmartPointer<vtkPolyData> pointData(const std::vector<model::Vec3>& points);

} // namespace devsurf::views
