#include "poly_data_builders.h"

#include <vtkCellArray.h>

namespace devsurf::views {

using model::Vec3;

vtkSmartPointer<vtkPoints> makePoints(const std::vector<Vec3>& points) {
    auto result = vtkSmartPointer<vtkPoints>::New();
    result->SetDataTypeToDouble();
    result->SetNumberOfPoints(static_cast<vtkIdType>(points.size()));
    for (std::size_t i = 0; i < points.size(); ++i) {
        result->SetPoint(static_cast<vtkIdType>(i), points[i].x, points[i].y, points[i].z);
    }
    return result;
}

vtkSmartPointer<vtkPolyData> polylineData(const std::vector<std::vector<Vec3>>& lines) {
    std::vector<Vec3> points;
    auto cells = vtkSmartPointer<vtkCellArray>::New();
    for (const auto& line : lines) {
        if (line.size() < 2) {
            continue;
        }
        cells->InsertNextCell(static_cast<vtkIdType>(line.size()));
        for (const Vec3& p : line) {
            cells->InsertCellPoint(static_cast<vtkIdType>(points.size()));
            points.push_back(p);
        }
    }
    auto data = vtkSmartPointer<vtkPolyData>::New();
    data->SetPoints(makePoints(points));
    data->SetLines(cells);
    return data;
}

vtkSmartPointer<vtkPolyData> segmentData(const std::vector<std::pair<Vec3, Vec3>>& segments) {
    std::vector<std::vector<Vec3>> lines;
    lines.reserve(segments.size());
    for (const auto& [a, b] : segments) {
        lines.push_back({a, b});
    }
    return polylineData(lines);
}

vtkSmartPointer<vtkPolyData> pointData(const std::vector<Vec3>& points) {
    auto cells = vtkSmartPointer<vtkCellArray>::New();
    for (std::size_t i = 0; i < points.size(); ++i) {
        const vtkIdType id = static_cast<vtkIdType>(i);
        cells->InsertNextCell(1, &id);
    }
    auto data = vtkSmartPointer<vtkPolyData>::New();
    data->SetPoints(makePoints(points));
    data->SetVerts(cells);
    return data;
}

} // namespace devsurf::views
