#pragma once

// Internal to views/: the 3D view's colouring by a quality measure, with its legend.

#include "colour_by.h"
#include "scene_geometry.h"

#include <vtkSmartPointer.h>

#include <QString>

#include <array>
#include <vector>

class vtkLookupTable;
class vtkRenderer;
class vtkScalarBarActor;
class vtkUnsignedCharArray;

namespace devsurf::views {

// Developability and flatness give one value per polygon, the angle defect one per point
// (0 on the boundary), in the order of the scene's polygons or points.
std::vector<double> qualityValues(const SurfaceScene& scene, ColourBy by);
bool isPerPoint(ColourBy by);

// The lookup table (logarithmic) and the scalar bar of a renderer.
class QualityColouring {
public:
    explicit QualityColouring(vtkRenderer* renderer);
    ~QualityColouring();

    void setMode(ColourBy by);
    ColourBy mode() const { return m_mode; }
    // Measures the scenes and fits the legend's range. Values are concatenated in scene order.
    void update(const std::vector<SurfaceScene>& scenes);
    const std::vector<double>& values() const { return m_values; }
    // RGB in 0..1 of a value on the current scale.
    std::array<double, 3> colour(double value) const;
    // Per-point colours (angle defect) for a polydata with the scenes' points in order.
    vtkSmartPointer<vtkUnsignedCharArray> pointColours() const;

    double low() const { return m_low; }
    double high() const { return m_high; }
    QString title() const;

private:
    ColourBy m_mode = ColourBy::Patch;
    std::vector<double> m_values;
    double m_low = 1e-12;
    double m_high = 1.0;
    vtkSmartPointer<vtkLookupTable> m_table;
    vtkSmartPointer<vtkScalarBarActor> m_bar;
};

} // namespace devsurf::views
