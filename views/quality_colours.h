#pragma once

// Internal to views/: the 3D view's colouring by a quality measure, with its legend.

#include "colour_by.h"
#include "scene_geometry.h"

#include <vtkSmartPointer.h>

#include <QColor>
#include <QString>

#include <array>
#include <vector>

class vtkLookupTable;
class vtkUnsignedCharArray;

namespace devsurf::views {

// Developability and flatness give one value per polygon, the angle defect one per point, in the
// order of the scene's polygons or points: the scene's measures (solver/quality, as the Solver
// panel reports them), with 0 where a measure does not apply (triangles, the boundary).
std::vector<double> qualityValues(const SurfaceScene& scene, ColourBy by);
bool isPerPoint(ColourBy by);

// The colours of a scale whose mark (the tolerance, a fraction 0..1 of the scale) parts what is
// good enough from what is not: `count` colours from bottom to top, green up to the mark, then
// yellow through orange to red. Shared by the quality colouring and the distance colour map.
std::vector<QColor> toleranceScale(double mark, int count);

// The lookup table (logarithmic, fixed from kScaleLow to kScaleHigh: green below the tolerance,
// yellow to red above it). The view's overlay draws its legend at the right of the viewport
// (ViewOverlay::setQualityLegend).
class QualityColouring {
public:
    QualityColouring();
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
    // The solve's tolerance (solver::Options::reportTolerance), marked on the legend: values
    // below it are green, "developable".
    double tolerance() const { return m_tolerance; }
    // The legend's words at the tolerance mark.
    static QString toleranceLabel();
    QString title() const;
    // Where the legend is drawn in a viewport of width × height device pixels (display
    // coordinates, origin at the bottom left).
    struct Box {
        double left = 0.0;
        double bottom = 0.0;
        double right = 0.0;
        double top = 0.0;
    };
    static Box legendBox(int width, int height);
    // The table's colours from kScaleLow to kScaleHigh, evenly on the logarithmic scale.
    const std::vector<QColor>& colours() const { return m_colours; }

    // The fixed scale of every design: the colours mean the same value whatever is shown.
    static constexpr double kScaleLow = 1e-12;
    static constexpr double kScaleHigh = 1e-2;
    // The legend's box: its left edge, bottom and top as fractions of the viewport (from the
    // bottom), its right edge this many pixels from the viewport's.
    static constexpr double kLegendLeft = 0.78;
    static constexpr double kLegendBottom = 0.1;
    static constexpr double kLegendTop = 0.86;
    static constexpr double kLegendRightMargin = 8.0;
    static constexpr int kColours = 256;

private:
    ColourBy m_mode = ColourBy::Patch;
    std::vector<double> m_values;
    double m_low = kScaleLow;
    double m_high = kScaleHigh;
    double m_tolerance = 1e-8;
    vtkSmartPointer<vtkLookupTable> m_table;
    std::vector<QColor> m_colours;
};

} // namespace devsurf::views
