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

// Developability and flatness give one value per polygon, the angle defect one per point, in the
// order of the scene's polygons or points: the scene's measures (solver/quality, as the Solver
// panel reports them), with 0 where a measure does not apply (triangles, the boundary).
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
    // The largest value given to one patch of the scenes last measured (its polygons, or its
    // polygons' points for the angle defect); NaN when colouring by patch or if it has none.
    double valueOfPatch(const std::vector<SurfaceScene>& scenes, int surface,
                        model::FaceId face) const;
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
